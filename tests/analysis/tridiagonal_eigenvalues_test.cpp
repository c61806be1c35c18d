// The rational QL eigenvalues against a closed form (a uniform chain) and against Eigen's
// implicit QR on random symmetric tridiagonal matrices; matrices solved together (two at a time,
// interleaved in a vector's lanes) against each solved alone.
#include "tridiagonal_eigenvalues.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
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

// Pairs that interleave (solved two at a time, in order): unequal sizes, so that one pair's
// sweeps and iterations differ, the first of a pair finishing first and then the second; a split
// matrix; a matrix with a zero diagonal, whose first sweep meets a zero pivot, beside one whose
// zero-pivot replacement differs; a 1 x 1 and an empty one; an odd count (the last solved alone).
TEST(TridiagonalEigenvalues, MatricesSolvedTogetherHaveTheirOwnEigenvaluesBitForBit) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> value(-3.0, 3.0);
  std::vector<SymmetricTridiagonal> matrices;
  for (const std::size_t n : {41u, 300u, 97u, 120u, 9u, 60u, 1u, 0u, 7u}) {
    SymmetricTridiagonal t{std::vector<double>(n), std::vector<double>(n > 0 ? n - 1 : 0)};
    for (double& v : t.diagonal) v = value(random);
    for (double& v : t.off_diagonal) v = value(random);
    if (n == 97) t.off_diagonal[30] = 0.0;
    if (n == 9) {
      std::fill(t.diagonal.begin(), t.diagonal.end(), 0.0);
      std::fill(t.off_diagonal.begin(), t.off_diagonal.end(), 1.0);
    }
    matrices.push_back(std::move(t));
  }
  const std::vector<std::vector<double>> together = TridiagonalEigenvalues(matrices);
  ASSERT_EQ(together.size(), matrices.size());
  for (std::size_t k = 0; k < matrices.size(); ++k) {
    const std::vector<double> alone =
        TridiagonalEigenvalues(matrices[k].diagonal, matrices[k].off_diagonal);
    ASSERT_EQ(together[k].size(), matrices[k].diagonal.size());
    for (std::size_t i = 0; i < alone.size(); ++i) {
      EXPECT_EQ(together[k][i], alone[i]) << "matrix " << k << ", eigenvalue " << i;
    }
    // Both right, not merely equal: against Eigen's implicit QR.
    if (alone.empty()) continue;
    const Eigen::Index n = static_cast<Eigen::Index>(alone.size());
    Eigen::VectorXd d = Eigen::Map<const Eigen::VectorXd>(matrices[k].diagonal.data(), n);
    Eigen::VectorXd e = Eigen::Map<const Eigen::VectorXd>(matrices[k].off_diagonal.data(), n - 1);
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen;
    eigen.computeFromTridiagonal(d, e, Eigen::EigenvaluesOnly);
    const double scale = eigen.eigenvalues().cwiseAbs().maxCoeff();
    for (Eigen::Index i = 0; i < n; ++i) {
      EXPECT_NEAR(together[k][i], eigen.eigenvalues()[i], 1e-13 * scale) << k << " " << i;
    }
  }
}

// The uniform chains of the closed-form test, all solved together.
TEST(TridiagonalEigenvalues, UniformChainsSolvedTogetherMatchTheClosedForm) {
  const double k = 76.0, m = 0.025;
  const std::vector<std::size_t> sizes = {1000, 999, 5, 100, 2};
  std::vector<SymmetricTridiagonal> chains;
  for (const std::size_t n : sizes) {
    SymmetricTridiagonal t{std::vector<double>(n, 2.0 * k / m), std::vector<double>(n - 1, -k / m)};
    t.diagonal.back() = k / m;
    chains.push_back(std::move(t));
  }
  const std::vector<std::vector<double>> lambda = TridiagonalEigenvalues(std::move(chains));
  for (std::size_t c = 0; c < sizes.size(); ++c) {
    const std::size_t n = sizes[c];
    ASSERT_EQ(lambda[c].size(), n);
    for (std::size_t j = 1; j <= n; ++j) {
      const double s = std::sin((2.0 * double(j) - 1.0) * std::numbers::pi / (2.0 * (2.0 * n + 1)));
      EXPECT_NEAR(lambda[c][j - 1], 4.0 * k / m * s * s, 64 * 1e-16 * 4.0 * k / m)
          << "n " << n << ", j " << j;
    }
  }
}

}  // namespace
}  // namespace isolab::analysis
