#include "dense_lu.h"

#include <array>
#include <cmath>
#include <utility>

#include "row_scaling.h"

namespace isolab::integrators {
namespace {

// kN > 0: the size known at compile time; 0: arrays.n.
template <int kN>
void Scatter(const DenseLu::Arrays& arrays, const double* values) {
  const int n = kN > 0 ? kN : arrays.n;
  double* a = arrays.lu;
#pragma GCC unroll 16
  for (int k = 0; k < n * n; ++k) a[k] = 0.0;
#pragma GCC unroll 16
  for (int k = 0; k < arrays.entries; ++k) a[arrays.positions[k]] = values[k];
}

// LDL^T of the scattered matrix when it is symmetric and its pivots are positive and well above
// round-off: the effective tangent of a structure whose laws have symmetric tangents and whose
// mass term dominates their softening, the usual case, at half an LU's work and with no
// pivoting (stable for such a matrix). False, with the matrix overwritten, otherwise. The
// pivots are judged scaled by their diagonal entries (d_j / a_jj, in (0, 1] for a positive
// definite matrix), like the LU's by its row scales, so that a rotation's units do not matter.
template <int kN>
bool FactorizeSymmetric(const DenseLu::Arrays& arrays) {
  const int n = kN > 0 ? kN : arrays.n;
  double* a = arrays.lu;
#pragma GCC unroll 16
  for (int j = 0; j < n; ++j) {
#pragma GCC unroll 16
    for (int i = j + 1; i < n; ++i) {
      if (a[i + j * n] != a[j + i * n]) return false;
    }
  }
  PivotRatio ratio;
  // Column by column: l_ij below the diagonal (unit diagonal implied), d_j on it; the upper
  // triangle is left as it was.
#pragma GCC unroll 16
  for (int j = 0; j < n; ++j) {
    double* column = a + j * n;
    const double diagonal = column[j];
#pragma GCC unroll 16
    for (int p = 0; p < j; ++p) {
      const double scaled = a[j + p * n] * a[p + p * n];  // l_jp d_p
#pragma GCC unroll 16
      for (int i = j; i < n; ++i) column[i] -= a[i + p * n] * scaled;
    }
    const double d = column[j];
    if (!(d > 0.0 && diagonal > 0.0)) return false;
    ratio.Add(d / diagonal);
    const double inverse = arrays.inverse_diagonal[j] = 1.0 / d;
#pragma GCC unroll 16
    for (int i = j + 1; i < n; ++i) column[i] *= inverse;
  }
  return ratio.Acceptable();
}

// Dense LU with partial pivoting and row scaling of the scattered matrix.
template <int kN>
bool FactorizeLu(const DenseLu::Arrays& arrays) {
  const int n = kN > 0 ? kN : arrays.n;
  double* a = arrays.lu;
  // Rows scaled by their largest magnitude (KLU's default scaling).
  double* scales = arrays.scales;
#pragma GCC unroll 16
  for (int i = 0; i < n; ++i) scales[i] = 0.0;
#pragma GCC unroll 16
  for (int j = 0; j < n; ++j) {
#pragma GCC unroll 16
    for (int i = 0; i < n; ++i) scales[i] = std::max(scales[i], std::abs(a[i + j * n]));
  }
#pragma GCC unroll 16
  for (int i = 0; i < n; ++i) {
    if (!(scales[i] > 0.0 && std::isfinite(scales[i]))) return false;
    scales[i] = 1.0 / scales[i];
  }
#pragma GCC unroll 16
  for (int j = 0; j < n; ++j) {
#pragma GCC unroll 16
    for (int i = 0; i < n; ++i) a[i + j * n] *= scales[i];
  }
  PivotRatio ratio;
#pragma GCC unroll 16
  for (int k = 0; k < n; ++k) {
    double* column = a + k * n;
    int p = k;
    double largest = std::abs(column[k]);
#pragma GCC unroll 16
    for (int i = k + 1; i < n; ++i) {
      if (std::abs(column[i]) > largest) {
        largest = std::abs(column[i]);
        p = i;
      }
    }
    arrays.pivots[k] = p;
    ratio.Add(largest);
    if (largest == 0.0) return false;
    // Only the columns still to eliminate are exchanged (the multipliers of earlier steps stay
    // where they were made), so Solve applies each exchange just before its step's column.
    if (p != k) {
#pragma GCC unroll 16
      for (int j = k; j < n; ++j) std::swap(a[k + j * n], a[p + j * n]);
    }
    const double inverse = arrays.inverse_diagonal[k] = 1.0 / column[k];
#pragma GCC unroll 16
    for (int i = k + 1; i < n; ++i) column[i] *= inverse;
#pragma GCC unroll 16
    for (int j = k + 1; j < n; ++j) {
      double* target = a + j * n;
      const double factor = target[k];
#pragma GCC unroll 16
      for (int i = k + 1; i < n; ++i) target[i] -= column[i] * factor;
    }
  }
  return ratio.Acceptable();
}

template <int kN>
bool FactorizeDense(const DenseLu::Arrays& arrays, const double* values) {
  Scatter<kN>(arrays, values);
  *arrays.symmetric = FactorizeSymmetric<kN>(arrays);
  if (*arrays.symmetric) return true;
  Scatter<kN>(arrays, values);
  return FactorizeLu<kN>(arrays);
}

// b overwritten by L^-1 P b: the unit lower triangle's forward substitution, with the row
// exchanges of partial pivoting (kPivoted) or without.
template <int kN, bool kPivoted>
void ForwardSubstitute(const DenseLu::Arrays& arrays, double* b) {
  const int n = kN > 0 ? kN : arrays.n;
  const double* a = arrays.lu;
#pragma GCC unroll 16
  for (int k = 0; k < n; ++k) {
    if constexpr (kPivoted) {
      const int p = arrays.pivots[k];
      if (p != k) std::swap(b[k], b[p]);
    }
    const double* column = a + k * n;
    const double bk = b[k];
#pragma GCC unroll 16
    for (int i = k + 1; i < n; ++i) b[i] -= column[i] * bk;
  }
}

template <int kN>
void SolveSymmetric(const DenseLu::Arrays& arrays, double* b) {
  const int n = kN > 0 ? kN : arrays.n;
  const double* a = arrays.lu;
  ForwardSubstitute<kN, false>(arrays, b);
#pragma GCC unroll 16
  for (int k = n - 1; k >= 0; --k) {  // D^-1, then L^T's back substitution
    const double* column = a + k * n;
    double bk = b[k] * arrays.inverse_diagonal[k];
#pragma GCC unroll 16
    for (int i = k + 1; i < n; ++i) bk -= column[i] * b[i];
    b[k] = bk;
  }
}

template <int kN>
void SolveLu(const DenseLu::Arrays& arrays, double* b) {
  const int n = kN > 0 ? kN : arrays.n;
  const double* a = arrays.lu;
#pragma GCC unroll 16
  for (int i = 0; i < n; ++i) b[i] *= arrays.scales[i];
  ForwardSubstitute<kN, true>(arrays, b);
#pragma GCC unroll 16
  for (int k = n - 1; k >= 0; --k) {
    const double* column = a + k * n;
    b[k] *= arrays.inverse_diagonal[k];  // a multiplication: back substitution is a chain
    const double bk = b[k];
#pragma GCC unroll 16
    for (int i = 0; i < k; ++i) b[i] -= column[i] * bk;
  }
}

template <int kN>
void SolveDense(const DenseLu::Arrays& arrays, double* b) {
  if (*arrays.symmetric) {
    SolveSymmetric<kN>(arrays, b);
  } else {
    SolveLu<kN>(arrays, b);
  }
}

// The kernels of sizes 0 (any) to kDenseFixedDofs.
template <int... kSizes>
constexpr std::array<std::pair<DenseLu::Factorizer, DenseLu::Solver>, sizeof...(kSizes)>
DenseKernels(std::integer_sequence<int, kSizes...>) {
  return {std::pair{&FactorizeDense<kSizes>, &SolveDense<kSizes>}...};
}
constexpr auto kDenseKernels = DenseKernels(std::make_integer_sequence<int, kDenseFixedDofs + 1>());

}  // namespace

DenseLu::DenseLu(const structure::SparseMatrix& pattern)
    : n_(static_cast<int>(pattern.rows())),
      positions_(pattern.nonZeros()),
      lu_(static_cast<std::size_t>(n_) * n_),
      inverse_diagonal_(n_),
      pivots_(n_),
      row_scales_(n_) {
  for (int j = 0; j < n_; ++j) {
    for (int k = pattern.outerIndexPtr()[j]; k < pattern.outerIndexPtr()[j + 1]; ++k) {
      positions_[k] = pattern.innerIndexPtr()[k] + j * n_;
    }
  }
  arrays_ = {n_,
             lu_.data(),
             inverse_diagonal_.data(),
             pivots_.data(),
             row_scales_.data(),
             &symmetric_,
             positions_.data(),
             static_cast<int>(positions_.size())};
  const auto& kernels = kDenseKernels[n_ <= kDenseFixedDofs ? n_ : 0];
  factorize_ = kernels.first;
  solve_ = kernels.second;
}


}  // namespace isolab::integrators
