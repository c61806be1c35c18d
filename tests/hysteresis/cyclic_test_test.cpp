// Cyclic tests against the paper: Table 7's W_d and u_ha, and the closed-form energy per cycle of
// the identified Table 9 (THM1) and Table 10 (THM2) systems.
#include "isolab/hysteresis/cyclic_test.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "isolab/core/errors.h"
#include "isolab/model/model_file.h"
#include "paper_tables.h"

namespace isolab::hysteresis {
namespace {

model::ModelFile LoadPaperModel(const std::string& name) {
  return model::LoadModelFile(std::string(ISOLAB_SOURCE_DIR) + "/models/paper/" + name);
}

struct Table7Row {
  std::string file;
  double u_ha;  // mm
  double w_d;   // kN mm, over the complete second cycle
};

class Table7 : public ::testing::TestWithParam<Table7Row> {};

TEST_P(Table7, SecondCycleMatchesThePaper) {
  const Table7Row& row = GetParam();
  const model::ModelFile model = LoadPaperModel(row.file);
  CyclicProtocol protocol;
  protocol.amplitude = 200.0;
  protocol.cycles = 2;
  const CyclicResult result = RunCyclicTest(model.isolation, protocol);
  ASSERT_EQ(result.cycles.size(), 2u);
  const CycleSummary& second = result.cycles[1];
  EXPECT_NEAR(second.dissipated, row.w_d, 1e-3 * row.w_d);
  EXPECT_NEAR(second.components[0].slider_at_peak, row.u_ha, 1e-3 * row.u_ha);
}

INSTANTIATE_TEST_SUITE_P(Paper, Table7,
                         ::testing::Values(Table7Row{"table7_thm1_hard.yaml", 124.0, 9920.0},
                                           Table7Row{"table7_thm1_soft.yaml", 156.0, 12480.0},
                                           Table7Row{"table7_thm2_hard.yaml", 180.0, 11520.0},
                                           Table7Row{"table7_thm2_soft.yaml", 180.0, 11520.0}),
                         [](const auto& info) { return info.param.file.substr(7, 9); });

CycleSummary ThirdCycle(const ParallelAssembly& assembly, double amplitude) {
  CyclicProtocol protocol;
  protocol.amplitude = amplitude;
  protocol.period = 2.0;  // 0.5 Hz
  protocol.cycles = 3;
  return RunCyclicTest(assembly, protocol).cycles[2];
}

TEST(Table10, EnergyPerCycleIsTheSumOfFourFsTimesAmplitudeMinusYield) {
  const model::ModelFile model = LoadPaperModel("table10_thm2_system.yaml");
  for (const double ua : testing::kTestAmplitudes) {
    double closed_form = 0.0;
    for (const auto& component : testing::kTable10)
      closed_form += testing::Thm2CycleEnergy(component, ua);
    EXPECT_NEAR(ThirdCycle(model.isolation, ua).dissipated, closed_form, 1e-9 * closed_form)
        << "u_a = " << ua;
  }
}

TEST(Table9, EachComponentDissipatesItsClosedForm) {
  const model::ModelFile model = LoadPaperModel("table9_thm1_system.yaml");
  ASSERT_EQ(model.isolation.size(), 9u);
  for (const double ua : testing::kTestAmplitudes) {
    const CycleSummary cycle = ThirdCycle(model.isolation, ua);
    double total = 0.0;
    for (int c = 0; c < 9; ++c) {
      const double expected = testing::Thm1CycleEnergy(testing::kTable9[c], ua);
      total += expected;
      EXPECT_NEAR(cycle.components[c].dissipated, expected, 1e-9 * (expected + 1.0))
          << "component " << c + 1 << ", u_a = " << ua;
    }
    EXPECT_NEAR(cycle.dissipated, total, 1e-9 * total) << "u_a = " << ua;
  }
}

TEST(CyclicTest, PeakForceOfThm1HardIsKeTimesElasticDeformation) {
  const model::ModelFile model = LoadPaperModel("table7_thm1_hard.yaml");
  CyclicProtocol protocol;
  protocol.amplitude = 200.0;
  const CyclicResult result = RunCyclicTest(model.isolation, protocol);
  // f = ke (u_a - u_ha) = 1 * (200 - 124), reached at u = +-u_a.
  EXPECT_NEAR(result.cycles[1].peak_force, 76.0, 1e-9);
  EXPECT_EQ(result.loop.time.size(), 2u * 400u + 1u);
}

TEST(CyclicProtocol, RejectsStepsThatMissThePeaks) {
  CyclicProtocol protocol;
  protocol.amplitude = 1.0;
  protocol.steps_per_cycle = 30;
  EXPECT_THROW(protocol.Validate(), isolab::InvalidParameter);
  protocol.steps_per_cycle = 40;
  protocol.amplitude = 0.0;
  EXPECT_THROW(protocol.Validate(), isolab::InvalidParameter);
}

// The README's "which law is my bearing": a lead-rubber bearing given by its characteristic
// strength Qd, post-yield stiffness Kd and elastic stiffness Ku is BHM2 with ke = Ku, kh = Kd,
// fs = Qd (k0 = Ku, k1 = Kd, uy = Qd / (Ku - Kd)). The bilinear loop's textbook properties hold:
// force -Qd at u = 0 coming down from +D, Qd + Kd D at D, energy 4 Qd (D - Dy) a cycle.
TEST(BearingMapping, LeadRubberQdKdKuIsBhm2) {
  const double qd = 50.0, kd = 1.0, ku = 10.0, d = 100.0;  // kN, kN/mm, mm
  const ParallelAssembly lrb(
      {{"lrb", LawParameters::Make(LawType::kBhm2, ParameterForm::kMechanical,
                                   std::vector<double>{ku, kd, qd})}});
  const auto mathematical = lrb.components()[0].parameters.Values(ParameterForm::kMathematical);
  EXPECT_DOUBLE_EQ(mathematical[0], ku);
  EXPECT_DOUBLE_EQ(mathematical[1], kd);
  EXPECT_DOUBLE_EQ(mathematical[2], qd / (ku - kd));
  CyclicProtocol protocol;
  protocol.amplitude = d;
  protocol.cycles = 2;
  const CyclicResult result = RunCyclicTest(lrb, protocol);
  EXPECT_NEAR(result.cycles[1].peak_force, qd + kd * d, 1e-9);
  EXPECT_NEAR(result.cycles[1].dissipated, 4 * qd * (d - qd / (ku - kd)), 1e-6);
  // Second cycle, u = 0 on the way down (sample 600 of 800: a quarter period after the peak).
  const std::size_t zero = protocol.steps_per_cycle * 3 / 2;
  EXPECT_NEAR(result.loop.displacement[zero], 0.0, 1e-9);
  EXPECT_NEAR(result.loop.force[zero], -qd, 1e-9);
}

// A friction pendulum of radius R and friction coefficient mu under a weight W: Kd = W / R,
// Qd = mu W, sliding after a small elastic displacement Dy: BHM2 with ke = Kd + Qd / Dy, kh = Kd,
// fs = Qd; at D its force is mu W + W D / R.
TEST(BearingMapping, FrictionPendulumIsBhm2) {
  const double weight = 1000.0, radius = 2235.0, mu = 0.06, dy = 0.5, d = 200.0;  // kN, mm
  const double kd = weight / radius, qd = mu * weight;
  const ParallelAssembly fps(
      {{"fps", LawParameters::Make(LawType::kBhm2, ParameterForm::kMechanical,
                                   std::vector<double>{kd + qd / dy, kd, qd})}});
  EXPECT_DOUBLE_EQ(fps.components()[0].parameters.Values(ParameterForm::kMathematical)[2], dy);
  CyclicProtocol protocol;
  protocol.amplitude = d;
  protocol.cycles = 2;
  const CyclicResult result = RunCyclicTest(fps, protocol);
  EXPECT_NEAR(result.cycles[1].peak_force, mu * weight + weight * d / radius, 1e-9);
  EXPECT_NEAR(result.cycles[1].dissipated, 4 * qd * (d - dy), 1e-6);
}

}  // namespace
}  // namespace isolab::hysteresis
