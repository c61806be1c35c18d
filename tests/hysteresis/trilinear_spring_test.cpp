#include "isolab/hysteresis/trilinear_spring.h"

#include <gtest/gtest.h>

namespace isolab::hysteresis {
namespace {

const TrilinearSpring kSpring{0.25, 0.8, 80.0};

TEST(TrilinearSpring, ForceFollowsTheThreeSegments) {
  EXPECT_DOUBLE_EQ(kSpring.Force(40.0), 10.0);
  EXPECT_DOUBLE_EQ(kSpring.Force(80.0), 20.0);
  EXPECT_DOUBLE_EQ(kSpring.Force(100.0), 20.0 + 0.8 * 20.0);
  EXPECT_DOUBLE_EQ(kSpring.Force(-100.0), -36.0);
  EXPECT_DOUBLE_EQ(kSpring.Stiffness(-100.0), 0.8);
  EXPECT_DOUBLE_EQ(kSpring.Stiffness(79.0), 0.25);
}

TEST(TrilinearSpring, EnergyIsTheIntegralOfForce) {
  // Midpoint rule is exact on each linear piece when no sample straddles the breakpoint.
  for (const double x : {-150.0, -80.0, 35.0, 80.0, 123.0}) {
    const int n = 100000;
    double integral = 0.0;
    for (int i = 0; i < n; ++i) integral += kSpring.Force((i + 0.5) * x / n) * x / n;
    EXPECT_NEAR(kSpring.Energy(x), integral, 1e-6 * std::abs(integral) + 1e-9) << x;
  }
}

TEST(TrilinearSpring, SolveInSeriesInvertsKeXPlusG) {
  const double ke = 1.0;
  for (const double x : {-200.0, -80.0, -3.0, 0.0, 50.0, 80.0, 80.5, 300.0}) {
    const double rhs = ke * x + kSpring.Force(x);
    double slope = 0.0;
    EXPECT_NEAR(kSpring.SolveInSeries(ke, rhs, &slope), x, 1e-12 * (1 + std::abs(x)));
    EXPECT_EQ(slope, kSpring.Stiffness(x));
  }
}

TEST(TrilinearSpring, InfiniteBreakpointIsALinearSpring) {
  const TrilinearSpring linear{0.3, 0.3, INFINITY};
  EXPECT_DOUBLE_EQ(linear.Force(1e3), 300.0);
  EXPECT_DOUBLE_EQ(linear.Energy(-10.0), 15.0);
  double slope = 0.0;
  EXPECT_DOUBLE_EQ(linear.SolveInSeries(1.0, 13.0, &slope), 10.0);
  EXPECT_EQ(slope, 0.3);
}

}  // namespace
}  // namespace isolab::hysteresis
