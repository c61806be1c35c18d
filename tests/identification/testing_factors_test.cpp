// Testing factors from a bearing's own cycles against loops built by hand: a rigid-plastic-
// hardening loop whose strength changes from cycle to cycle gives back each cycle's strength and
// the spread of the three about their mean; a bilinear loop of one strength gives its closed-form
// loop, the first cycle's from rest included.
#include "isolab/identification/testing_factors.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "isolab/hysteresis/cyclic_test.h"
#include "isolab/hysteresis/parallel_assembly.h"

namespace isolab::identification {
namespace {

constexpr double kAmplitude = 200.0;  // mm
constexpr double kKd = 0.8;           // kN/mm
constexpr int kSteps = 800;           // per cycle

// u = D sin(2 pi t), F = Kd u + Q_c sign(du/dt) in cycle c (from one upward zero crossing to the
// next): a rigid-plastic slider of strength Q_c beside a spring.
CyclicTestData RigidPlastic(const std::vector<double>& strengths) {
  CyclicTestData test;
  test.name = "rigid_plastic";
  const int samples = kSteps * static_cast<int>(strengths.size());
  for (int k = 0; k <= samples; ++k) {
    const double phase = 2.0 * std::numbers::pi * k / kSteps;
    const std::size_t c = std::min<std::size_t>(k / kSteps, strengths.size() - 1);
    const double u = kAmplitude * std::sin(phase);
    // The force of the motion that arrived at the sample (a slider's force jumps at a reversal).
    const double sign =
        k == 0 || u >= kAmplitude * std::sin(2.0 * std::numbers::pi * (k - 1) / kSteps) ? 1.0
                                                                                        : -1.0;
    test.time.push_back(k * 1.0 / kSteps);
    test.displacement.push_back(u);
    test.force.push_back(kKd * u + strengths[c] * sign);
  }
  Segment(&test);
  return test;
}

TEST(TestingFactors, AreTheCyclesSpreadAboutTheirMean) {
  const std::vector<CyclicTestData> tests = {RigidPlastic({60.0, 50.0, 46.0, 45.0})};
  const TestingFactors f = TestingFactorsOf(tests);
  ASSERT_EQ(f.tests.size(), 1u);
  const TestProperties& t = f.tests[0];
  ASSERT_EQ(t.cycles.size(), 3u);  // the fourth is not one of the code's three
  const double q[] = {60.0, 50.0, 46.0};
  for (int c = 0; c < 3; ++c) {
    // E = 4 Q D (the spring's work cancels over a closed cycle), to the sampling's 1e-3.
    EXPECT_NEAR(t.cycles[c].qd, q[c], 1e-3 * q[c]) << c;
    EXPECT_NEAR(t.cycles[c].kd, kKd, 1e-3 * kKd) << c;
    EXPECT_NEAR(t.cycles[c].amplitude, kAmplitude, 1e-9);
  }
  const double mean = (60.0 + 50.0 + 46.0) / 3.0;  // 52
  EXPECT_NEAR(f.qd.nominal, mean, 1e-3 * mean);
  EXPECT_NEAR(f.qd.max, 60.0 / mean, 1e-3);  // 1.1538
  EXPECT_NEAR(f.qd.min, 46.0 / mean, 1e-3);  // 0.8846
  EXPECT_NEAR(f.kd.max, 1.0, 2e-3);
  EXPECT_NEAR(f.kd.min, 1.0, 2e-3);
}

TEST(TestingFactors, OfABilinearLoopAreItsClosedFormFromRest) {
  // A lead-rubber bearing without heating: Qd 50 kN, Kd 0.8, Ku 8 kN/mm, Dy = 50 / 7.2 mm.
  const std::vector<double> values = {50.0, 0.8, 8.0, NAN, NAN, NAN, NAN, NAN, NAN, NAN};
  const hysteresis::ParallelAssembly bearing(
      {{"lrb", hysteresis::LawParameters::Make(hysteresis::LawType::kLeadRubber,
                                               hysteresis::ParameterForm::kMechanical, values)}});
  hysteresis::CyclicProtocol protocol;
  protocol.amplitude = kAmplitude;
  protocol.cycles = 3;
  protocol.steps_per_cycle = kSteps;
  const hysteresis::CyclicResult run = hysteresis::RunCyclicTest(bearing, protocol);
  CyclicTestData test;
  test.name = "lrb";
  test.time = run.loop.time;
  test.displacement = run.loop.displacement;
  test.force = run.loop.force;
  Segment(&test);
  const std::vector<CyclicTestData> tests = {test, RigidPlastic({50.0, 50.0})};
  const TestingFactors f = TestingFactorsOf(tests);
  ASSERT_EQ(f.tests.size(), 1u);
  ASSERT_EQ(f.skipped.size(), 1u);  // two cycles are not the code's three
  const double dy = 50.0 / 7.2;
  // The steady loop: E = 4 Qd (D - Dy). The first cycle starts from rest on the virgin branch,
  // whose z rises from 0, not from 1, over its first Dy: Qd Dy / 2 less.
  const double steady = 4.0 * 50.0 * (kAmplitude - dy);
  const double energy[] = {steady - 50.0 * dy / 2.0, steady, steady};
  for (int c = 0; c < 3; ++c) {
    const CycleProperties& p = f.tests[0].cycles[c];
    EXPECT_NEAR(p.dissipated, energy[c], 1e-4 * steady) << c;
    EXPECT_NEAR(p.qd, energy[c] / (4.0 * kAmplitude), 1e-4 * 50.0) << c;
    EXPECT_NEAR(p.effective_stiffness, 0.8 + 50.0 / kAmplitude, 1e-9) << c;
  }
  const double mean = (energy[0] + 2 * steady) / 3.0;
  EXPECT_NEAR(f.qd.min, energy[0] / mean, 1e-4);
  EXPECT_NEAR(f.qd.max, steady / mean, 1e-4);
}

}  // namespace
}  // namespace isolab::identification
