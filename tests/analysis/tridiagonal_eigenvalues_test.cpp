// The rational QL eigenvalues against a closed form (a uniform chain) and against Eigen's
// implicit QR on random symmetric tridiagonal matrices.
#include "tridiagonal_eigenvalues.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace isolab::analysis {
namespace {

// A uniform fixed-free chain of n masses m and springs k (a shear building of equal stories):
// lambda_j = 4 k / m sin^2((2 j - 1) pi / (2 (2 n + 1))), j = 1..n.
TEST(TridiagonalEigenvalues, UniformChainMatchesTheClosedForm) {
  for (const std::size_t n : {1u, 2u, 5u, 100u, 1000u}) {
    const double k = 76.0, m = 0.025;
    std::vector<double> diagonal(n, 2.0 * k / m), off(n - 1, -k / m);
    diagonal.back() = k / m;  // the roof: one spring
    const std::vector<double> lambda = TridiagonalEigenvalues(diagonal, off);
    ASSERT_EQ(lambda.size(), n);
    for (std::size_t j = 1; j <= n; ++j) {
      const double s = std::sin((2.0 * double(j) - 1.0) * std::numbers::pi / (2.0 * (2.0 * n + 1)));
      const double exact = 4.0 * k / m * s * s;
      // Absolute accuracy of a few ulps of the largest eigenvalue, as any QL/QR method has.
      EXPECT_NEAR(lambda[j - 1], exact, 64 * 1e-16 * 4.0 * k / m) << "n " << n << ", j " << j;
    }
  }
}

TEST(TridiagonalEigenvalues, RandomMatricesMatchEigen) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> value(-3.0, 3.0);
  for (const int n : {2, 3, 10, 57, 300}) {
    for (int trial = 0; trial < 5; ++trial) {
      std::vector<double> diagonal(n), off(n - 1);
      for (double& v : diagonal) v = value(random);
      for (double& v : off) v = value(random);
      if (trial == 1) off[n / 2] = 0.0;  // a split matrix
      if (trial == 2) {
        for (double& v : diagonal) v = 1.0;  // repeated diagonal
      }
      Eigen::VectorXd d = Eigen::Map<Eigen::VectorXd>(diagonal.data(), n);
      Eigen::VectorXd e = Eigen::Map<Eigen::VectorXd>(off.data(), n - 1);
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen;
      eigen.computeFromTridiagonal(d, e, Eigen::EigenvaluesOnly);
      const std::vector<double> mine = TridiagonalEigenvalues(diagonal, off);
      const double scale = eigen.eigenvalues().cwiseAbs().maxCoeff();
      for (int i = 0; i < n; ++i) {
        EXPECT_NEAR(mine[i], eigen.eigenvalues()[i], 1e-13 * scale)
            << n << " " << trial << " " << i;
      }
    }
  }
}

}  // namespace
}  // namespace isolab::analysis
