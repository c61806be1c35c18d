#include "isolab/structure/damping_product.h"

#include <array>
#include <utility>

namespace isolab::structure {
namespace {

// The sum in a local array, so that the compiler keeps it in registers (out may alias v as far
// as it knows).
template <int kN>
void DenseProduct(const double* dense, const double* v, double* out) {
  std::array<double, kN> sum{};
#pragma GCC unroll 16
  for (int j = 0; j < kN; ++j) {
    const double vj = v[j];
    const double* column = dense + j * kN;
#pragma GCC unroll 16
    for (int i = 0; i < kN; ++i) sum[i] += column[i] * vj;
  }
#pragma GCC unroll 16
  for (int i = 0; i < kN; ++i) out[i] = sum[i];
}

template <int... kSizes>
constexpr std::array<DampingProduct::Kernel, sizeof...(kSizes)> DenseKernels(
    std::integer_sequence<int, kSizes...>) {
  return {&DenseProduct<kSizes>...};
}
constexpr auto kDenseKernels =
    DenseKernels(std::make_integer_sequence<int, kDenseDampingDofs + 1>());

bool AllZero(const Eigen::SparseMatrix<double>& matrix) {
  for (int j = 0; j < matrix.outerSize(); ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(matrix, j); it; ++it) {
      if (it.value() != 0.0) return false;
    }
  }
  return true;
}

}  // namespace

DampingProduct::DampingProduct(const Eigen::SparseMatrix<double>& damping) {
  zero_ = AllZero(damping);
  const int n = static_cast<int>(damping.rows());
  if (zero_ || n < 1 || n > kDenseDampingDofs || damping.cols() != n) return;
  dense_.assign(static_cast<std::size_t>(n) * n, 0.0);
  for (int j = 0; j < n; ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(damping, j); it; ++it) {
      dense_[static_cast<std::size_t>(it.row() + j * n)] = it.value();
    }
  }
  kernel_ = kDenseKernels[n];
}

}  // namespace isolab::structure
