// The equivalent lateral force procedure (ASCE 7-16 17.5) against its closed form for bilinear
// lead-rubber bearings: k_eff = N (Kd + Qd / D), E = 4 N Qd (D - Dy) with Dy = Qd / (Ku - Kd),
// and the fixed point D = g S_M1 T / (4 pi^2 B) solved here by bisection on those formulas
// alone, with B from Table 17.5-1 as the code prints it.
#include "isolab/design/equivalent_lateral_force.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "isolab/model/model_file.h"
#include "isolab/spectra/design_spectrum.h"

namespace isolab::design {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(DampingCoefficient, IsTable17_5_1LinearBetweenItsRows) {
  EXPECT_DOUBLE_EQ(DampingCoefficient(0.0), 0.8);
  EXPECT_DOUBLE_EQ(DampingCoefficient(0.02), 0.8);
  EXPECT_DOUBLE_EQ(DampingCoefficient(0.05), 1.0);
  EXPECT_DOUBLE_EQ(DampingCoefficient(0.15), 1.35);  // halfway from 1.2 (10 %) to 1.5 (20 %)
  EXPECT_DOUBLE_EQ(DampingCoefficient(0.35), 1.8);
  EXPECT_DOUBLE_EQ(DampingCoefficient(0.5), 2.0);
  EXPECT_DOUBLE_EQ(DampingCoefficient(0.8), 2.0);
}

// A rigid slab of 1600 t on 16 lead-rubber bearings (no heating: bilinear).
const std::string kModel = R"(units: {force: kN, length: mm, time: s}
structure: {type: shear_building, base_mass: 1600 t}
isolation:
  count: 16
  name: lrb
  components: [{name: lrb, type: lead_rubber, qd: 60 kN, kd: 0.8 kN/mm, ku: 8 kN/mm}]
)";

TEST(EquivalentLateralForce, EffectivePropertiesAreTheBilinearLoopsClosedForm) {
  const IsolationSystem system(model::LoadModelText(kModel, "lrb.yaml"));
  const double n = 16, qd = 60, kd = 0.8, dy = 60 / (8 - 0.8);
  EXPECT_NEAR(system.weight(), 1600 * 9.80665, 1e-9 * system.weight());
  for (const double d : {50.0, 200.0, 400.0}) {
    const EffectiveProperties p = system.At(d, 2.0);
    const double k = n * (kd + qd / d);
    const double e = 4 * n * qd * (d - dy);
    EXPECT_NEAR(p.stiffness, k, 1e-9 * k) << d;
    EXPECT_NEAR(p.dissipated, e, 1e-9 * e) << d;
    EXPECT_NEAR(p.damping, e / (2 * kPi * k * d * d), 1e-9) << d;
  }
}

// ASCE 7-16 Table 17.5-1, written here rather than taken from the code under test: B_M against
// the effective damping ratio, linear between its rows, constant beyond its ends.
double TableB(double beta) {
  const double rows[][2] = {{0.02, 0.8}, {0.05, 1.0}, {0.10, 1.2}, {0.20, 1.5},
                            {0.30, 1.7}, {0.40, 1.9}, {0.50, 2.0}};
  if (beta <= rows[0][0]) return rows[0][1];
  for (int i = 1; i < 7; ++i) {
    if (beta <= rows[i][0]) {
      const double f = (beta - rows[i - 1][0]) / (rows[i][0] - rows[i - 1][0]);
      return rows[i - 1][1] + f * (rows[i][1] - rows[i - 1][1]);
    }
  }
  return rows[6][1];
}

TEST(EquivalentLateralForce, DesignDisplacementIsTheFixedPointOfEq17_5_1) {
  const IsolationSystem system(model::LoadModelText(kModel, "lrb.yaml"));
  const double g = 9806.65, sm1 = 0.9;  // mm/s^2, g
  const DisplacementDemand demand = [&](double period, double beta) {
    return g * sm1 * period / (4 * kPi * kPi * TableB(beta));
  };
  const ElfResult elf = SolveElf(system, demand, 1000.0);

  // The same fixed point from the closed forms alone.
  const double n = 16, qd = 60, kd = 0.8, dy = 60 / (8 - 0.8), mass = 1.6;  // kN s^2/mm (1000 t)
  const auto excess = [&](double d) {
    const double k = n * (kd + qd / d);
    const double beta = 4 * n * qd * (d - dy) / (2 * kPi * k * d * d);
    const double period = 2 * kPi * std::sqrt(mass / k);
    return demand(period, beta) - d;
  };
  double low = 100, high = 2000;  // excess > 0 at 100 mm, < 0 at 2 m
  ASSERT_GT(excess(low), 0.0);
  ASSERT_LT(excess(high), 0.0);
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (low + high);
    (excess(mid) > 0 ? low : high) = mid;
  }
  EXPECT_NEAR(elf.displacement, low, 1e-6 * low);
  const double k = n * (kd + qd / low);
  EXPECT_NEAR(elf.period, 2 * kPi * std::sqrt(mass / k), 1e-6);
  EXPECT_NEAR(elf.base_shear, k * low, 1e-6 * k * low);
  // The demand balances: D = g S_M1 T / (4 pi^2 B) at the result's own T and beta.
  EXPECT_NEAR(demand(elf.period, elf.at_design.damping), elf.displacement, 1e-9 * elf.displacement);
}

// A pendulum's loop at D (sliding throughout) has F(+-D) = +-(W D / R + mu W), so k_eff =
// W / R + mu W / D. Four pendulums given w = 500 kN under a 400 t slab carry 2000 kN at their own
// w, and the slab's 3922.66 kN under axial_load, as the runs load them: the ELF step uses the
// same weight.
TEST(EquivalentLateralForce, PendulumsCarryTheWeightTheRunsGiveThem) {
  const std::string text = R"(units: {force: kN, length: mm, time: s}
structure: {type: shear_building, base_mass: 400 t}
isolation:
  count: 4
  components: [{name: fp, type: friction_pendulum, w: 500, r: 2000, mu: 0.05, uy: 0.01}]
)";
  const double r = 2000, mu = 0.05, d = 300;
  const auto k_eff = [&](double w) { return w / r + mu * w / d; };
  const IsolationSystem own(model::LoadModelText(text, "fp.yaml"));
  EXPECT_NEAR(own.At(d, 3.0).stiffness, k_eff(2000.0), 1e-9 * k_eff(2000.0));
  const IsolationSystem loaded(model::LoadModelText(text + "axial_load: {}\n", "fp.yaml"));
  const double weight = 400 * 9.80665;
  EXPECT_NEAR(loaded.At(d, 3.0).stiffness, k_eff(weight), 1e-9 * k_eff(weight));
  ASSERT_EQ(loaded.bearing_weights().size(), 4u);
  EXPECT_EQ(loaded.bearing_weights()[0].law, 500.0);
  EXPECT_NEAR(loaded.bearing_weights()[0].carried, weight / 4, 1e-9 * weight);
}

// Eq. 17.5-3 by hand for models/design/five_story_lrb_plan.yaml: 16 equal bearings on a 4 x 4
// grid of a 30 m x 20 m plan (x at 0, 10, 20, 30 m; y at 0, 6.667, 13.333, 20 m), the centre of
// rigidity at (15, 10) m, the centre of mass at (15.6, 10) m. Mean squared distance of the
// bearings from the centre of mass (Eq. 17.5-4): (15.6^2 + 5.6^2 + 4.4^2 + 14.4^2) / 4 +
// (10^2 + 3.333^2 + 3.333^2 + 10^2) / 4 = 125.36 + 55.56 = 180.92 m^2; the plan's
// (30^2 + 20^2) / 12 = 108.33 m^2, so P_T^2 = 1.6700. Along x: y = 10 m, e = 0 + 0.05 x 20 = 1 m,
// 1 + 10 / 1.67 x 12 x 1 / 1300 = 1.0553; along y: y = 15 m, e = 0.6 + 0.05 x 30 = 2.1 m,
// 1 + 15 / 1.67 x 12 x 2.1 / 1300 = 1.1741, which governs (above 1.15).
TEST(EquivalentLateralForce, TotalDisplacementIsEq17_5_3OfThePlan) {
  const model::ModelFile model = model::LoadModelFile(std::string(ISOLAB_SOURCE_DIR) +
                                                      "/models/design/five_story_lrb_plan.yaml");
  const IsolationSystem system(model);
  ElfResult elf;
  elf.displacement = 500.0;
  elf.period = 3.0;
  const double dx2 = (15.6 * 15.6 + 5.6 * 5.6 + 4.4 * 4.4 + 14.4 * 14.4) / 4.0;
  const double p_t2 = (dx2 + (100.0 + 2 * 100.0 / 9.0 + 100.0) / 4.0) / (1300.0 / 12.0);
  const double expected = 1.0 + 15.0 / p_t2 * 12.0 * 2.1 / 1300.0;
  EXPECT_NEAR(expected, 1.1741, 1e-4);
  // The grid stands at 6667 and 13333 mm, not thirds: 1e-5 of the value.
  EXPECT_NEAR(TotalDisplacement(model, system, elf), 500.0 * expected, 1e-5 * 500.0 * expected);
  // A one-direction model has no plan to twist in: the code's floor, 1.15 D_M.
  const IsolationSystem layer(model::LoadModelText(kModel, "lrb.yaml"));
  EXPECT_DOUBLE_EQ(TotalDisplacement(model::LoadModelText(kModel, "lrb.yaml"), layer, elf),
                   1.15 * 500.0);
}

}  // namespace
}  // namespace isolab::design
