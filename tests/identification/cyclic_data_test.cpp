// Any displacement history as test data: half-cycles between reversals (the band rule of
// cyclic_data.h) against a sine's known reversals, with ripples that raw sign changes would
// count; the half-cycle energy against BHM2's closed-form loop area; and one specimen: a history
// cut into tests that start mid-history, simulated with the state carried, gives the forces of
// the uncut history exactly, while fresh specimens do not.
#include "isolab/identification/cyclic_data.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "isolab/identification/fit.h"
#include "isolab/identification/synthetic_tests.h"

namespace isolab::identification {
namespace {

using hysteresis::LawParameters;
using hysteresis::LawType;
using hysteresis::ParameterForm;

std::vector<double> Sine(double amplitude, int cycles, int per_cycle) {
  std::vector<double> u;
  for (int k = 0; k <= cycles * per_cycle; ++k) {
    u.push_back(amplitude * std::sin(2 * std::numbers::pi * k / per_cycle));
  }
  return u;
}

TEST(HalfCycles, ASineHasItsReversalsAtThePeaks) {
  const auto u = Sine(50, 3, 200);
  const auto halves = SplitHalfCycles(u);
  // Reversals at 50, 150, ..., 550: five half-cycles between six reversals.
  ASSERT_EQ(halves.size(), 5u);
  for (std::size_t h = 0; h < halves.size(); ++h) {
    EXPECT_EQ(halves[h].begin, 50 + 100 * h);
    EXPECT_EQ(halves[h].end, 50 + 100 * (h + 1) + 1);
    EXPECT_DOUBLE_EQ(HalfRange(u, halves[h]), 50.0);
  }
}

TEST(HalfCycles, RipplesInsideTheBandDoNotSplitAHalfCycle) {
  auto u = Sine(50, 3, 200);
  // Sample-to-sample jitter of +-0.9 (1.8 % of the range, inside the 2 % band): the differences
  // change sign at most samples, far more often than at the five true reversals.
  for (std::size_t k = 0; k < u.size(); ++k) u[k] += k % 2 == 0 ? 0.9 : -0.9;
  int sign_changes = 0;
  for (std::size_t k = 2; k < u.size(); ++k) {
    if ((u[k] - u[k - 1]) * (u[k - 1] - u[k - 2]) < 0) ++sign_changes;
  }
  EXPECT_GT(sign_changes, 300);
  const auto halves = SplitHalfCycles(u);
  ASSERT_EQ(halves.size(), 5u);
  for (const CycleSpan& h : halves) EXPECT_NEAR(HalfRange(u, h), 50.9, 0.1);
}

TEST(HalfCycles, AnIrregularHistoryStartingAwayFromZeroHasHalfCyclesOfItsOwnRanges) {
  // 10 -> 40 -> -20 -> 5 -> -60: reversals at 40, -20, 5 (the first and last stretches are not
  // half-cycles); amplitudes 30 and 12.5.
  std::vector<double> u;
  const double points[] = {10, 40, -20, 5, -60};
  for (int p = 0; p + 1 < 5; ++p) {
    for (int k = 0; k < 50; ++k) u.push_back(points[p] + (points[p + 1] - points[p]) * k / 50.0);
  }
  u.push_back(-60);
  const auto halves = SplitHalfCycles(u);
  ASSERT_EQ(halves.size(), 2u);
  EXPECT_DOUBLE_EQ(HalfRange(u, halves[0]), 30.0);
  EXPECT_DOUBLE_EQ(HalfRange(u, halves[1]), 12.5);
}

TEST(HalfCycles, EnergyIsHalfTheClosedFormLoopAreaOfBhm2) {
  // BHM2 k0 = 1.5, k1 = 0.25, uy = 8: the steady loop at amplitude u_a has area
  // 4 (k0 - k1) uy (u_a - uy); each half-cycle dissipates half of it, whatever the elastic part.
  const auto law = hysteresis::SingleLaw(LawType::kBhm2, {1.5, 0.25, 8.0});
  CyclicTestData test;
  test.displacement = Sine(100, 3, 400);
  for (std::size_t k = 0; k < test.displacement.size(); ++k) test.time.push_back(0.01 * k);
  test.force = SimulateForce(law, test);
  Segment(&test);
  ASSERT_EQ(test.half_cycles.size(), 5u);
  const double loop = 4 * 1.25 * 8 * (100 - 8);
  for (const CycleSpan& h : test.half_cycles) {
    EXPECT_NEAR(HalfCycleEnergy(test.displacement, test.force, h) / (0.5 * loop), 1.0, 1e-3);
  }
  // A linear spring stores and returns: no energy.
  const auto spring = SimulateForce(hysteresis::SingleLaw(LawType::kLinearSpring, {2.0}), test);
  EXPECT_NEAR(HalfCycleEnergy(test.displacement, spring, test.half_cycles[1]), 0.0, 1e-9);
}

hysteresis::ParallelAssembly DegradingBearing() {
  return hysteresis::ParallelAssembly(
      {{"base", LawParameters::Make(LawType::kBhm2, ParameterForm::kMathematical,
                                    std::vector<double>{1.5, 0.25, 8.0})},
       {"degrading", LawParameters::Make(LawType::kDegradingBhm2, ParameterForm::kMathematical,
                                         std::vector<double>{0.5, 0.0, 30.0, 0.6, 150.0})}});
}

TEST(OneSpecimen, AHistoryCutIntoTestsGivesTheForcesOfTheWholeHistory) {
  // A decaying, drifting history at 100 Hz, cut at samples where u is far from zero.
  CyclicTestData whole;
  whole.name = "whole";
  for (int k = 0; k < 3000; ++k) {
    const double t = 0.01 * k;
    whole.time.push_back(t);
    whole.displacement.push_back(80 * std::exp(-t / 20) * std::sin(2.1 * t) +
                                 15 * std::sin(0.3 * t));
  }
  const auto bearing = DegradingBearing();
  whole.force = SimulateForce(bearing, whole);
  std::vector<CyclicTestData> pieces;
  const std::size_t cuts[] = {0, 737, 1911, 3000};
  for (int p = 0; p < 3; ++p) {
    CyclicTestData piece;
    piece.name = "piece" + std::to_string(p);
    for (std::size_t k = cuts[p]; k < cuts[p + 1]; ++k) {
      piece.time.push_back(whole.time[k] - whole.time[cuts[p]]);  // each test's clock from 0
      piece.displacement.push_back(whole.displacement[k]);
      piece.force.push_back(whole.force[k]);
    }
    pieces.push_back(piece);
  }
  ASSERT_GT(std::abs(pieces[1].displacement[0]), 10.0);  // starts mid-history
  const auto carried = SimulateForces(bearing, pieces, true);
  const auto fresh = SimulateForces(bearing, pieces, false);
  for (int p = 0; p < 3; ++p) {
    for (std::size_t k = 0; k < pieces[p].force.size(); ++k) {
      ASSERT_NEAR(carried[p][k], pieces[p].force[k], 1e-9) << "piece " << p << " sample " << k;
    }
  }
  // The fresh specimen starts from rest: the later pieces come out wrong, by much.
  const auto data = [&](bool one) {
    FitData d = SelectCycles(pieces, {}, one);
    return d;
  };
  const FitError one = ComputeFitError(bearing, data(true));
  const FitError independent = ComputeFitError(bearing, data(false));
  EXPECT_LT(one.total, 1e-20);
  EXPECT_LT(independent.per_test[0], 1e-20);
  EXPECT_GT(independent.per_test[1], 1e-3);
  EXPECT_GT(independent.per_test[2], 1e-3);
}

// Parameter recovery on a campaign: three tests on one degrading specimen (25, 50, 100 mm, every
// cycle fitted), fitted as one specimen, give the truth back; fitted as fresh specimens they
// cannot.
TEST(OneSpecimen, AFitWithCarriedStateRecoversADegradingCampaign) {
  SyntheticTestOptions protocol{{25, 50, 100}, {2.0}, 3, 200, 0.0, 1};
  protocol.one_specimen = true;
  const auto tests = SyntheticTests(DegradingBearing(), protocol);
  std::vector<ComponentSpec> specs = {{"base", LawType::kBhm2, {}, {}, {}},
                                      {"degrading", LawType::kDegradingBhm2, {}, {}, {}}};
  FitOptions options;
  options.seed = 3;
  options.budget = 6000;
  const auto fit = [&](bool one) {
    const FitData data = SelectCycles(tests, {1, 2, 3}, one);
    return Fit(ModelParametrisation(specs, ScalesOf(data)), data, options);
  };
  const FitResult carried = fit(true);
  const FitResult fresh = fit(false);
  std::printf("degrading campaign: e^2 %.3g (one specimen) vs %.3g (fresh specimens)\n",
              carried.error.total, fresh.error.total);
  EXPECT_LT(carried.error.total, 1e-6);
  EXPECT_GT(fresh.error.total, 100 * carried.error.total);
  const std::vector<double> truth = {0.5, 0.0, 30.0, 0.6, 150.0};
  for (std::size_t p : {2u, 3u, 4u}) {
    EXPECT_NEAR(carried.mathematical[1][p] / truth[p], 1.0, 0.02) << "parameter " << p;
  }
}

}  // namespace
}  // namespace isolab::identification
