// The least-squares refinement against problems whose minimum is known in closed form: a
// separable exponential decay (the minimum is the generating parameters, residual zero), a linear
// problem whose unconstrained minimum lies outside the cube (the bound-constrained minimum is the
// projection along the held coordinate, solved by hand), Rosenbrock's valley as residuals; and
// the same answer on 1 and 4 threads.
#include "isolab/identification/least_squares.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "isolab/core/errors.h"

namespace isolab::identification {
namespace {

// y(t) = a exp(-b t) sampled at 50 points, with a = 0.5 + x0 and b = 0.2 + 2 x1 on the cube: the
// residual is zero at x = (0.3, 0.4), inside it.
Eigen::VectorXd Decay(std::span<const double> x) {
  Eigen::VectorXd r(50);
  for (int i = 0; i < 50; ++i) {
    const double t = 0.1 * i;
    const double model = (0.5 + x[0]) * std::exp(-(0.2 + 2.0 * x[1]) * t);
    const double data = 0.8 * std::exp(-1.0 * t);
    r[i] = model - data;
  }
  return r;
}

TEST(LeastSquares, FindsTheGeneratingParametersOfAnExponentialDecay) {
  RefinementOptions options;
  options.threads = 1;
  const RefinementOutcome out = RefineLeastSquares(Decay, {0.9, 0.9}, options);
  EXPECT_EQ(out.stop, RefinementStop::kConverged) << RefinementSummary(out, options, "S", 1.0);
  EXPECT_NEAR(out.point[0], 0.3, 1e-6);
  EXPECT_NEAR(out.point[1], 0.4, 1e-6);
  EXPECT_LT(out.value, 1e-12);
  EXPECT_LE(out.evaluations, options.budget);
  EXPECT_LT(out.iterations, 30);  // Gauss-Newton's quadratic convergence on a zero residual
}

// r = (x0 - 1.5, x1 - 0.25, 0.5 (x0 + x1) - 0.5): unconstrained minimum beyond x0 = 1. With x0
// held at 1, S(x1) = (x1 - 0.25)^2 + (0.5 x1)^2 + const is least at x1 = 0.25 / 1.25 = 0.2.
Eigen::VectorXd BeyondTheCube(std::span<const double> x) {
  Eigen::VectorXd r(3);
  r << x[0] - 1.5, x[1] - 0.25, 0.5 * (x[0] + x[1]) - 0.5;
  return r;
}

TEST(LeastSquares, HoldsACoordinateAtTheFaceTheMinimumLiesBeyond) {
  RefinementOptions options;
  options.threads = 1;
  const RefinementOutcome out = RefineLeastSquares(BeyondTheCube, {0.2, 0.8}, options);
  EXPECT_EQ(out.stop, RefinementStop::kConverged) << RefinementSummary(out, options, "S", 1.0);
  EXPECT_DOUBLE_EQ(out.point[0], 1.0);
  // The residual is linear, so the Gauss-Newton step lands on the minimum: what the convergence
  // criteria promise is the distance to it (step) and the reduction left (decrement).
  EXPECT_NEAR(out.point[1], 0.2, out.step + 1e-15);
  EXPECT_LE(out.step, options.step_tolerance);
  const double least = 0.25 + 0.0025 + 0.01;  // r = (-0.5, -0.05, 0.1)
  EXPECT_NEAR(out.value, least, options.decrement_tolerance * least);
}

// Rosenbrock as residuals, (10 (v - u^2), 1 - u), with u = 2 x0 - 0.5 and v = 2 x1 - 0.5: the
// minimum u = v = 1 at x = (0.75, 0.75), at the end of a curved valley.
Eigen::VectorXd Rosenbrock(std::span<const double> x) {
  const double u = 2.0 * x[0] - 0.5, v = 2.0 * x[1] - 0.5;
  Eigen::VectorXd r(2);
  r << 10.0 * (v - u * u), 1.0 - u;
  return r;
}

TEST(LeastSquares, FollowsRosenbrocksValleyToItsEnd) {
  RefinementOptions options;
  options.threads = 1;
  const RefinementOutcome out = RefineLeastSquares(Rosenbrock, {0.1, 0.9}, options);
  EXPECT_EQ(out.stop, RefinementStop::kConverged) << RefinementSummary(out, options, "S", 1.0);
  EXPECT_NEAR(out.point[0], 0.75, 1e-5);
  EXPECT_NEAR(out.point[1], 0.75, 1e-5);
}

TEST(LeastSquares, ThreadsChangeNothing) {
  RefinementOptions one, four;
  one.threads = 1;
  four.threads = 4;
  const RefinementOutcome a = RefineLeastSquares(Decay, {0.9, 0.1}, one);
  const RefinementOutcome b = RefineLeastSquares(Decay, {0.9, 0.1}, four);
  EXPECT_EQ(a.point, b.point);
  EXPECT_EQ(a.value, b.value);
  EXPECT_EQ(a.evaluations, b.evaluations);
}

TEST(LeastSquares, ABudgetTooSmallIsStatedAndAStartThatDoesNotRunRefused) {
  RefinementOptions options;
  options.budget = 12;  // a Jacobian (4) and a few steps
  const RefinementOutcome out = RefineLeastSquares(Rosenbrock, {0.1, 0.9}, options);
  EXPECT_EQ(out.stop, RefinementStop::kBudget);
  EXPECT_LE(out.evaluations, 12);
  EXPECT_NE(RefinementSummary(out, options, "S", 1.0).find("NOT converged"), std::string::npos);
  options.budget = 5;
  EXPECT_THROW(RefineLeastSquares(Rosenbrock, {0.1, 0.9}, options), InvalidParameter);
  const Residual broken = [](std::span<const double>) -> Eigen::VectorXd {
    throw std::runtime_error("the model does not run");
  };
  EXPECT_THROW(RefineLeastSquares(broken, {0.5}, RefinementOptions{}), std::invalid_argument);
}

}  // namespace
}  // namespace isolab::identification
