// Sturm-sequence bisection against the closed form of the uniform fixed-base shear building
// (n equal masses m and stories k), w_j = 2 sqrt(k/m) sin((2j - 1) pi / (2 (2n + 1))), the
// eigenvalues of its tridiagonal K = k tridiag(-1, 2, -1) with a free top (for n = 5 they are
// Chopra's Case E periods 2.000, 0.685, 0.435, 0.338, 0.297 s), and against Eigen's dense
// generalized eigensolver on an irregular building.
#include "tridiagonal_pencil.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

namespace isolab::structure {
namespace {

// Stories of stiffness k[i] between floor i and the floor below (the ground for i = 0).
TridiagonalPencil ShearBuilding(const Eigen::VectorXd& k, const Eigen::VectorXd& m) {
  const Eigen::Index n = k.size();
  TridiagonalPencil pencil{k, -k.tail(n - 1), m};
  pencil.diagonal.head(n - 1) += k.tail(n - 1);
  return pencil;
}

TEST(TridiagonalPencil, UniformShearBuildingMatchesTheClosedForm) {
  for (const int n : {1, 5, 1000}) {
    const double k = 76.0, m = 0.025;
    const TridiagonalPencil pencil =
        ShearBuilding(Eigen::VectorXd::Constant(n, k), Eigen::VectorXd::Constant(n, m));
    // Bisection is accurate to a few eps times the largest eigenvalue (below 4 k / m), not
    // relative to each one: the first mode of 1000 stories is 1.6e6 times smaller.
    const double tolerance = 16.0 * std::numeric_limits<double>::epsilon() * 4.0 * k / m;
    for (const int j : {1, 2, 3, n / 2 + 1, n}) {
      if (j > n) continue;
      const double w =
          2.0 * std::sqrt(k / m) * std::sin((2 * j - 1) * std::numbers::pi / (2.0 * (2 * n + 1)));
      EXPECT_NEAR(pencil.Eigenvalue(j), w * w, tolerance) << n << " stories, mode " << j;
      EXPECT_NEAR(std::sqrt(pencil.Eigenvalue(j)) / w, 1.0, 1e-9) << n << " stories, mode " << j;
    }
  }
}

TEST(TridiagonalPencil, IrregularBuildingMatchesTheDenseEigensolution) {
  const int n = 60;
  std::mt19937 random(17);
  std::uniform_real_distribution<double> stiffness(20.0, 200.0), mass(0.01, 0.05);
  Eigen::VectorXd k(n), m(n);
  for (int i = 0; i < n; ++i) {
    k[i] = stiffness(random);
    m[i] = mass(random);
  }
  const TridiagonalPencil pencil = ShearBuilding(k, m);
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
  dense.diagonal() = pencil.diagonal;
  for (int i = 0; i + 1 < n; ++i) dense(i, i + 1) = dense(i + 1, i) = pencil.off_diagonal[i];
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(
      dense, Eigen::MatrixXd(m.asDiagonal()));
  for (int j = 1; j <= n; ++j) {
    const double expected = solver.eigenvalues()[j - 1];
    EXPECT_NEAR(pencil.Eigenvalue(j), expected, 1e-10 * expected) << "mode " << j;
    EXPECT_EQ(pencil.CountBelow(expected * (1 - 1e-8)), j - 1) << "mode " << j;
  }
  EXPECT_THROW(pencil.Eigenvalue(0), std::out_of_range);
  EXPECT_THROW(pencil.Eigenvalue(n + 1), std::out_of_range);
}

}  // namespace
}  // namespace isolab::structure
