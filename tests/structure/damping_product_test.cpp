// The viscous damping product (isolab/structure/damping_product.h): dense kernels compiled for 1
// to kDenseDampingDofs dofs and the sparse product above, against Eigen's sparse product on
// random matrices, entry by entry to round-off (entries and velocities within +-1; the sums
// need not be taken in the same order).
#include "isolab/structure/damping_product.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace isolab::structure {
namespace {

TEST(DampingProduct, EqualsTheSparseProductAtEverySize) {
  std::mt19937 generator(5);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int n = 1; n <= kDenseDampingDofs + 3; ++n) {
    std::vector<Eigen::Triplet<double>> entries;
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        if (std::abs(i - j) <= 1 || i == 0 || j == 0)
          entries.emplace_back(i, j, uniform(generator));
      }
    }
    Eigen::SparseMatrix<double> damping(n, n);
    damping.setFromTriplets(entries.begin(), entries.end());
    damping.makeCompressed();
    const DampingProduct product(damping);
    Eigen::VectorXd v(n);
    for (double& vi : v) vi = uniform(generator);
    Eigen::VectorXd out;  // sized by Apply
    product.Apply(damping, v, &out);
    const Eigen::VectorXd expected = damping * v;
    ASSERT_EQ(out.size(), n);
    for (int i = 0; i < n; ++i) EXPECT_NEAR(out[i], expected[i], 1e-14 * n) << n << ", " << i;
  }
}

TEST(DampingProduct, AnEmptyMatrixGivesZeroForces) {
  Eigen::SparseMatrix<double> none(4, 4);
  none.makeCompressed();
  const DampingProduct product(none);
  Eigen::VectorXd out;
  product.Apply(none, Eigen::VectorXd::Ones(4), &out);
  EXPECT_EQ(out, Eigen::VectorXd::Zero(4));
}

// Stored zeros (a damping of zero coefficients, its pattern kept, -0.0 among them) give the
// product's forces at finite velocities, +0.0 to the bit, at the dense sizes and the sparse ones.
TEST(DampingProduct, StoredZerosGiveTheProductsZeros) {
  for (const int n : {1, 6, kDenseDampingDofs + 2}) {
    std::vector<Eigen::Triplet<double>> entries;
    for (int i = 0; i < n; ++i) entries.emplace_back(i, i, 0.0);
    for (int i = 1; i < n; ++i) entries.emplace_back(i, i - 1, -0.0);
    Eigen::SparseMatrix<double> zeros(n, n);
    zeros.setFromTriplets(entries.begin(), entries.end());
    zeros.makeCompressed();
    ASSERT_EQ(zeros.nonZeros(), 2 * n - 1);
    const DampingProduct product(zeros);
    const Eigen::VectorXd v = -Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
    Eigen::VectorXd out = Eigen::VectorXd::Constant(n + 1, 7.0);  // resized by Apply
    product.Apply(zeros, v, &out);
    const Eigen::VectorXd expected = zeros * v;
    ASSERT_EQ(out.size(), n);
    for (int i = 0; i < n; ++i) {
      EXPECT_EQ(out[i], expected[i]) << n << ", " << i;
      EXPECT_EQ(std::signbit(out[i]), std::signbit(expected[i])) << n << ", " << i;
    }
  }
}

}  // namespace
}  // namespace isolab::structure
