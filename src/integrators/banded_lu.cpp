#include "banded_lu.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "row_scaling.h"

namespace isolab::integrators {

Bandwidths BandwidthsOf(const structure::SparseMatrix& pattern) {
  Bandwidths widths;
  for (int j = 0; j < pattern.outerSize(); ++j) {
    for (int k = pattern.outerIndexPtr()[j]; k < pattern.outerIndexPtr()[j + 1]; ++k) {
      const int i = pattern.innerIndexPtr()[k];
      widths.lower = std::max(widths.lower, i - j);
      widths.upper = std::max(widths.upper, j - i);
    }
  }
  return widths;
}

BandedLu::BandedLu(const structure::SparseMatrix& pattern) : n_(static_cast<int>(pattern.rows())) {
  const Bandwidths widths = BandwidthsOf(pattern);
  kl_ = widths.lower;
  ku_ = widths.upper;
  kv_ = kl_ + ku_;
  stride_ = 2 * kl_ + ku_;
  band_.assign(static_cast<std::size_t>(n_) * (stride_ + 1), 0.0);
  pivots_.assign(n_, 0);
  row_scales_.assign(n_, 0.0);
  positions_.resize(pattern.nonZeros());
  for (int j = 0; j < n_; ++j) {
    for (int k = pattern.outerIndexPtr()[j]; k < pattern.outerIndexPtr()[j + 1]; ++k) {
      positions_[k] = kv_ + pattern.innerIndexPtr()[k] + j * stride_;
    }
  }
}

bool BandedLu::Factorize(const structure::SparseMatrix& matrix) {
  if (!InverseRowScales(matrix, &row_scales_)) return false;
  std::fill(band_.begin(), band_.end(), 0.0);
  const int* rows = matrix.innerIndexPtr();
  const double* values = matrix.valuePtr();
  for (std::size_t k = 0; k < positions_.size(); ++k) {
    band_[positions_[k]] = values[k] * row_scales_[rows[k]];
  }
  PivotRatio ratio;
  int last = 0;  // the last column that row exchanges have brought into U so far
  for (int j = 0; j < n_; ++j) {
    const int below = std::min(kl_, n_ - 1 - j);
    int p = j;
    for (int i = j + 1; i <= j + below; ++i) {
      if (std::abs(At(i, j)) > std::abs(At(p, j))) p = i;
    }
    pivots_[j] = p;
    ratio.Add(At(p, j));
    if (At(p, j) == 0.0) return false;
    last = std::max(last, std::min(p + ku_, n_ - 1));
    if (p != j) {
      for (int c = j; c <= last; ++c) std::swap(At(p, c), At(j, c));
    }
    if (below == 0) continue;
    const double inverse = 1.0 / At(j, j);
    double* column = &At(j, j);
    for (int i = 1; i <= below; ++i) column[i] *= inverse;
    for (int c = j + 1; c <= last; ++c) {
      const double factor = At(j, c);
      if (factor == 0.0) continue;
      double* target = &At(j, c);
      for (int i = 1; i <= below; ++i) target[i] -= column[i] * factor;
    }
  }
  return ratio.Acceptable();
}

void BandedLu::Solve(Eigen::VectorXd* rhs) const {
  double* b = rhs->data();
  for (int i = 0; i < n_; ++i) b[i] *= row_scales_[i];
  for (int j = 0; j < n_; ++j) {
    if (pivots_[j] != j) std::swap(b[j], b[pivots_[j]]);
    const int below = std::min(kl_, n_ - 1 - j);
    const double bj = b[j];
    for (int i = 1; i <= below; ++i) b[j + i] -= At(j + i, j) * bj;
  }
  for (int j = n_ - 1; j >= 0; --j) {
    b[j] /= At(j, j);
    const double bj = b[j];
    for (int i = std::max(0, j - kv_); i < j; ++i) b[i] -= At(i, j) * bj;
  }
}

}  // namespace isolab::integrators
