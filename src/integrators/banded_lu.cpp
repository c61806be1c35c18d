#include "banded_lu.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "row_scaling.h"

namespace isolab::integrators {

BandStructure BandStructureOf(const structure::SparseMatrix& pattern) {
  const int n = static_cast<int>(pattern.rows());
  const int* columns = pattern.outerIndexPtr();
  const int* rows = pattern.innerIndexPtr();
  std::vector<int> entries(n, 0);
  for (int j = 0; j < n; ++j) {
    for (int k = columns[j]; k < columns[j + 1]; ++k) {
      ++entries[j];
      ++entries[rows[k]];
    }
  }
  BandStructure band;
  for (int i = 0; i < n; ++i) {
    if (entries[i] > kBorderEntries) band.border.push_back(i);
  }
  if (static_cast<int>(band.border.size()) > kMaxBorderDofs) band.border.clear();
  // Positions of the band's dofs among themselves.
  std::vector<int> position(n, -1);
  for (int i = 0, next = 0, b = 0; i < n; ++i) {
    if (b < static_cast<int>(band.border.size()) && band.border[b] == i) {
      ++b;
    } else {
      position[i] = next++;
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int k = columns[j]; k < columns[j + 1]; ++k) {
      const int pi = position[rows[k]], pj = position[j];
      if (pi < 0 || pj < 0) continue;
      band.lower = std::max(band.lower, pi - pj);
      band.upper = std::max(band.upper, pj - pi);
    }
  }
  return band;
}

BandedLu::BandedLu(const structure::SparseMatrix& pattern) : n_(static_cast<int>(pattern.rows())) {
  const BandStructure band = BandStructureOf(pattern);
  m_ = static_cast<int>(band.border.size());
  nb_ = n_ - m_;
  kl_ = band.lower;
  ku_ = band.upper;
  kv_ = kl_ + ku_;
  stride_ = 2 * kl_ + ku_;
  std::vector<int> position(n_, -1);
  for (int i = 0, b = 0; i < n_; ++i) {
    if (b < m_ && band.border[b] == i) {
      ++b;
    } else {
      position[i] = static_cast<int>(order_.size());
      order_.push_back(i);
    }
  }
  for (int b = 0; b < m_; ++b) {
    position[band.border[b]] = nb_ + b;
    order_.push_back(band.border[b]);
  }
  b_offset_ = nb_ * (stride_ + 1);
  c_offset_ = b_offset_ + nb_ * m_;
  d_offset_ = c_offset_ + m_ * nb_;
  values_.assign(d_offset_ + m_ * m_, 0.0);
  positions_.resize(pattern.nonZeros());
  for (int j = 0; j < n_; ++j) {
    for (int k = pattern.outerIndexPtr()[j]; k < pattern.outerIndexPtr()[j + 1]; ++k) {
      const int r = position[pattern.innerIndexPtr()[k]], c = position[j];
      if (r < nb_ && c < nb_) {
        positions_[k] = kv_ + r + c * stride_;
      } else if (r < nb_) {
        positions_[k] = b_offset_ + r + (c - nb_) * nb_;
      } else if (c < nb_) {
        positions_[k] = c_offset_ + (r - nb_) * nb_ + c;
      } else {
        positions_[k] = d_offset_ + (r - nb_) + (c - nb_) * m_;
      }
    }
  }
  pivots_.assign(nb_, 0);
  inverse_diagonal_.assign(nb_, 0.0);
  border_pivots_.assign(m_, 0);
  row_scales_.assign(n_, 0.0);
  work_.assign(n_, 0.0);
}

// A = P L U in place. kKl > 0: kl_ = ku_ = kKl, known at compile time, so that the loops along
// the band, two to six trips, are unrolled instead of vectorised for nothing. A row exchange
// brings entries at most kl + ku columns right of the diagonal, and the entries of U beyond those
// it brought are zero: the loops run over all kl + ku columns (exchanging and subtracting zeros)
// so that their trip counts stay constant.
template <int kKl>
bool BandedLu::FactorBand(PivotRatio* ratio) {
  const auto step = [&](int j, const int below, const int right) {
    int p = j;
    double largest = std::abs(At(j, j));
    for (int i = j + 1; i <= j + below; ++i) {
      if (std::abs(At(i, j)) > largest) {
        largest = std::abs(At(i, j));
        p = i;
      }
    }
    pivots_[j] = p;
    ratio->Add(largest);
    if (largest == 0.0) return false;
    if (p != j) {
      for (int c = j; c <= j + right; ++c) std::swap(At(p, c), At(j, c));
    }
    const double inverse = inverse_diagonal_[j] = 1.0 / At(j, j);
    double* column = &At(j, j);
    for (int i = 1; i <= below; ++i) column[i] *= inverse;
    for (int c = j + 1; c <= j + right; ++c) {
      const double factor = At(j, c);
      double* target = &At(j, c);
      for (int i = 1; i <= below; ++i) target[i] -= column[i] * factor;
    }
    return true;
  };
  const int kl = kKl > 0 ? kKl : kl_, kv = kKl > 0 ? 2 * kKl : kv_;
  int j = 0;
  for (; j < nb_ - kv; ++j) {
    if (!step(j, kl, kv)) return false;
  }
  for (; j < nb_; ++j) {
    if (!step(j, std::min(kl, nb_ - 1 - j), nb_ - 1 - j)) return false;
  }
  return true;
}

template <int kKl>
void BandedLu::SolveBand(double* x) const {
  const auto forward = [&](int j, const int below) {
    if (pivots_[j] != j) std::swap(x[j], x[pivots_[j]]);
    const double xj = x[j];
    for (int i = 1; i <= below; ++i) x[j + i] -= At(j + i, j) * xj;
  };
  const auto backward = [&](int j, const int above) {
    x[j] *= inverse_diagonal_[j];  // a multiplication: back substitution is a chain through x
    const double xj = x[j];
    for (int i = 1; i <= above; ++i) x[j - i] -= At(j - i, j) * xj;
  };
  const int kl = kKl > 0 ? kKl : kl_, kv = kKl > 0 ? 2 * kKl : kv_;
  int j = 0;
  for (; j < nb_ - kl; ++j) forward(j, kl);
  for (; j < nb_; ++j) forward(j, nb_ - 1 - j);
  for (j = nb_ - 1; j >= kv; --j) backward(j, kv);
  for (; j >= 0; --j) backward(j, j);
}

bool BandedLu::Factorize(const structure::SparseMatrix& matrix) {
  if (!InverseRowScales(matrix, &row_scales_)) return false;
  std::fill(values_.begin(), values_.end(), 0.0);
  const int* rows = matrix.innerIndexPtr();
  const double* values = matrix.valuePtr();
  for (std::size_t k = 0; k < positions_.size(); ++k) {
    values_[positions_[k]] = values[k] * row_scales_[rows[k]];
  }
  PivotRatio ratio;
  bool factored = false;
  switch (kl_ == ku_ ? kl_ : 0) {  // the common small bandwidths compiled as constants
    case 1:
      factored = FactorBand<1>(&ratio);
      break;
    case 2:
      factored = FactorBand<2>(&ratio);
      break;
    case 3:
      factored = FactorBand<3>(&ratio);
      break;
    default:
      factored = FactorBand<0>(&ratio);
  }
  if (!factored) return false;
  if (m_ == 0) return ratio.Acceptable();
  // W = A^-1 B over B; S = D - C W over D; S = P L U.
  double* w = values_.data() + b_offset_;
  const double* c = values_.data() + c_offset_;
  double* s = values_.data() + d_offset_;
  for (int b = 0; b < m_; ++b) BandSolve(w + b * nb_);
  for (int col = 0; col < m_; ++col) {
    for (int row = 0; row < m_; ++row) {
      double sum = 0.0;
      for (int k = 0; k < nb_; ++k) sum += c[row * nb_ + k] * w[col * nb_ + k];
      s[row + col * m_] -= sum;
    }
  }
  for (int k = 0; k < m_; ++k) {
    int p = k;
    double largest = std::abs(s[k + k * m_]);
    for (int i = k + 1; i < m_; ++i) {
      if (std::abs(s[i + k * m_]) > largest) {
        largest = std::abs(s[i + k * m_]);
        p = i;
      }
    }
    border_pivots_[k] = p;
    ratio.Add(largest);
    if (largest == 0.0) return false;
    if (p != k) {
      for (int j = k; j < m_; ++j) std::swap(s[k + j * m_], s[p + j * m_]);
    }
    const double inverse = 1.0 / s[k + k * m_];
    for (int i = k + 1; i < m_; ++i) s[i + k * m_] *= inverse;
    for (int j = k + 1; j < m_; ++j) {
      const double factor = s[k + j * m_];
      for (int i = k + 1; i < m_; ++i) s[i + j * m_] -= s[i + k * m_] * factor;
    }
  }
  return ratio.Acceptable();
}

void BandedLu::BandSolve(double* x) const {
  switch (kl_ == ku_ ? kl_ : 0) {
    case 1:
      return SolveBand<1>(x);
    case 2:
      return SolveBand<2>(x);
    case 3:
      return SolveBand<3>(x);
    default:
      return SolveBand<0>(x);
  }
}

void BandedLu::Solve(Eigen::VectorXd* rhs) {
  double* b = rhs->data();
  double* y = work_.data();
  for (int k = 0; k < n_; ++k) y[k] = b[order_[k]] * row_scales_[order_[k]];
  BandSolve(y);
  if (m_ > 0) {
    const double* w = values_.data() + b_offset_;
    const double* c = values_.data() + c_offset_;
    const double* s = values_.data() + d_offset_;
    double* y2 = y + nb_;
    for (int row = 0; row < m_; ++row) {
      double sum = 0.0;
      for (int k = 0; k < nb_; ++k) sum += c[row * nb_ + k] * y[k];
      y2[row] -= sum;
    }
    for (int k = 0; k < m_; ++k) {
      if (border_pivots_[k] != k) std::swap(y2[k], y2[border_pivots_[k]]);
      for (int i = k + 1; i < m_; ++i) y2[i] -= s[i + k * m_] * y2[k];
    }
    for (int k = m_ - 1; k >= 0; --k) {
      y2[k] /= s[k + k * m_];
      for (int i = 0; i < k; ++i) y2[i] -= s[i + k * m_] * y2[k];
    }
    for (int col = 0; col < m_; ++col) {
      for (int k = 0; k < nb_; ++k) y[k] -= w[col * nb_ + k] * y2[col];
    }
  }
  for (int k = 0; k < n_; ++k) b[order_[k]] = y[k];
}

}  // namespace isolab::integrators
