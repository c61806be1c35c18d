// The viscous damping product (isolab/structure/damping_product.h): dense kernels compiled for 1
// to kDenseDampingDofs dofs and the sparse product above, against Eigen's sparse product on
// random matrices, entry by entry to round-off (entries and velocities within +-1; the sums
// need not be taken in the same order).
#include "isolab/structure/damping_product.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace isolab::structure
