// Identification from cyclic tests: cycle splitting, the paper's error, parameter recovery of a
// known three-component model, and the paper's finding on the HDRB tests (Table 9 THM1 system
// against a six-component THM2 fit).
#include "isolab/identification/fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "identification/table9_assembly.h"
#include "isolab/identification/synthetic_tests.h"

namespace isolab::identification {
namespace {

using hysteresis::Component;
using hysteresis::LawParameters;
using hysteresis::LawType;
using hysteresis::ParameterForm;

Component Law(std::string name, LawType type, std::vector<double> math) {
  return {std::move(name), LawParameters::Make(type, ParameterForm::kMathematical, math)};
}

const std::vector<double> kHdrbAmplitudes(std::begin(testing::kTestAmplitudes),
                                           std::end(testing::kTestAmplitudes));

hysteresis::ParallelAssembly Table9() { return testing::Table9ExactAssembly(); }

std::vector<ComponentSpec> Specs(std::vector<std::pair<LawType, int>> counts) {
  std::vector<ComponentSpec> specs;
  for (const auto& [type, count] : counts) {
    for (int i = 0; i < count; ++i) {
      specs.push_back({"c" + std::to_string(specs.size() + 1), type, {}, {}, {}});
    }
  }
  return specs;
}

TEST(CyclicData, SplitsASineHistoryIntoItsCycles) {
  std::vector<double> u;
  for (int k = 0; k <= 600; ++k) u.push_back(50 * std::sin(2 * std::numbers::pi * k / 200.0));
  const auto cycles = SplitCycles(u);
  ASSERT_EQ(cycles.size(), 3u);
  EXPECT_EQ(cycles[0].begin, 0u);
  EXPECT_NEAR(static_cast<double>(cycles[1].begin), 200.0, 1.0);
  EXPECT_NEAR(static_cast<double>(cycles[2].begin), 400.0, 1.0);
  // A half cycle at the end is not a cycle.
  for (int k = 1; k <= 100; ++k) u.push_back(50 * std::sin(2 * std::numbers::pi * k / 200.0));
  EXPECT_EQ(SplitCycles(u).size(), 3u);
}

TEST(FitError, IsZeroForTheTruthAndTheSquaredScaleErrorOtherwise) {
  const auto truth = Table9();
  FitData data = SelectCycles(SyntheticTests(truth, {{50, 200}, {2.0}, 3, 200, 0.0, 1}), {3});
  EXPECT_LT(ComputeFitError(truth, data).total, 1e-20);
  // Every force scaled by 1.1: each test's term is 0.1^2 / 1.1^2 of the measured norm... with
  // the model at 1/1.1 of the data: (1 - 1/1.1)^2 per test.
  for (auto& test : data.tests) {
    for (double& f : test.force) f *= 1.1;
  }
  const FitError error = ComputeFitError(truth, data);
  ASSERT_EQ(error.per_test.size(), 2u);
  EXPECT_NEAR(error.per_test[0], std::pow(1 - 1 / 1.1, 2), 1e-12);
  EXPECT_NEAR(error.total, 2 * std::pow(1 - 1 / 1.1, 2), 1e-12);
}

// Identifiable by construction: two elastoplastic elements (distinct yield displacements) and a
// trilinear spring share no linear branch. (Components that each carry a linear branch, e.g. a
// THM1 and a trilinear spring below their hardening, can trade stiffness between them: such
// models fit data exactly with other parameters, so no fit can recover them.)
TEST(Fit, RecoversTheParametersOfAKnownThreeComponentModel) {
  std::mt19937 random(2016);
  const auto uniform = [&](double low, double high) {
    return std::uniform_real_distribution<double>(low, high)(random);
  };
  const std::vector<std::vector<double>> truth = {
      {uniform(2, 5), uniform(0.5, 2)},
      {uniform(0.2, 0.8), uniform(15, 40)},
      {uniform(0.1, 0.3), uniform(0.4, 0.9), uniform(100, 150)},
  };
  const hysteresis::ParallelAssembly model({Law("a", LawType::kElastoplastic, truth[0]),
                                            Law("b", LawType::kElastoplastic, truth[1]),
                                            Law("c", LawType::kTrilinearElastic, truth[2])});
  const FitData data = SelectCycles(SyntheticTests(model, {kHdrbAmplitudes, {2.0}, 3, 200, 0.0, 1}),
                                    {3});
  const ModelParametrisation parametrisation(
      {{"a", LawType::kElastoplastic, {}, {}, {}},
       {"b", LawType::kElastoplastic, {}, {}, {}},
       {"c", LawType::kTrilinearElastic, {}, {}, {}}},
      ScalesOf(data));
  FitOptions options;
  options.seed = 7;
  options.budget = 20000;
  FitResult result = Fit(parametrisation, data, options);
  std::printf("three-component recovery: e^2 = %.3e after %ld evaluations, %d restarts, %.1f s\n",
              result.error.total, result.evaluations, result.restarts, result.seconds);
  // The two elastoplastic elements are interchangeable: match them by yield displacement.
  if (result.mathematical[0][1] > result.mathematical[1][1]) {
    std::swap(result.mathematical[0], result.mathematical[1]);
  }
  for (std::size_t c = 0; c < truth.size(); ++c) {
    for (std::size_t p = 0; p < truth[c].size(); ++p) {
      EXPECT_NEAR(result.mathematical[c][p] / truth[c][p], 1.0, 0.02)
          << "component " << c << " parameter " << p << ": " << result.mathematical[c][p]
          << " vs " << truth[c][p];
    }
  }
}

// Energy of the fitted (third) cycle of each test, measured and modelled.
std::vector<std::pair<double, double>> EnergyPerTest(const hysteresis::ParallelAssembly& model,
                                                     const FitData& data) {
  std::vector<std::pair<double, double>> energies;
  for (std::size_t i = 0; i < data.tests.size(); ++i) {
    const auto& test = data.tests[i];
    const auto force = SimulateForce(model, test);
    energies.emplace_back(LoopEnergy(test.displacement, test.force, data.fitted[i][0]),
                          LoopEnergy(test.displacement, force, data.fitted[i][0]));
  }
  return energies;
}

FitResult FitHdrb(const FitData& data, std::vector<ComponentSpec> specs, long budget) {
  const ModelParametrisation parametrisation(std::move(specs), ScalesOf(data));
  FitOptions options;
  options.seed = 1;
  options.budget = budget;
  return Fit(parametrisation, data, options);
}

TEST(Fit, NineComponentThm1FitsTheHdrbTestsAndSixThm2DoNot) {
  // Synthetic HDRB data: the Table 9 system at the paper's ten amplitudes, three cycles at
  // 0.5 Hz, the third fitted; noise-free.
  const FitData data =
      SelectCycles(SyntheticTests(Table9(), {kHdrbAmplitudes, {2.0}, 3, 200, 0.0, 1}), {3});
  const auto thm1_specs = Specs({{LawType::kTrilinearElastic, 3}, {LawType::kThm1, 4},
                                 {LawType::kElastoplastic, 2}});
  const auto thm2_specs = Specs({{LawType::kThm2, 6}});
  const FitResult thm1 = FitHdrb(data, thm1_specs, 60000);
  const FitResult thm2 = FitHdrb(data, thm2_specs, 60000);
  const auto thm1_model = ModelParametrisation(thm1_specs, ScalesOf(data)).Assembly(thm1.point, thm1.amplitudes);
  const auto thm2_model = ModelParametrisation(thm2_specs, ScalesOf(data)).Assembly(thm2.point, thm2.amplitudes);
  std::printf("HDRB fits: 33-parameter THM1 e^2 = %.3f %% (%ld evaluations, %.1f s); "
              "30-parameter THM2 e^2 = %.3f %% (%.1f s)\n",
              100 * thm1.error.total, thm1.evaluations, thm1.seconds, 100 * thm2.error.total,
              thm2.seconds);
  EXPECT_LE(thm1.error.total, 0.01);
  EXPECT_GE(thm2.error.total, 2 * thm1.error.total);

  const auto thm1_energy = EnergyPerTest(thm1_model, data);
  const auto thm2_energy = EnergyPerTest(thm2_model, data);
  for (std::size_t i = 0; i < kHdrbAmplitudes.size(); ++i) {
    const auto [measured, fitted] = thm1_energy[i];
    std::printf("  u = %5.0f mm: W_d measured %9.1f, THM1 fit %9.1f (%+.1f %%), THM2 fit %9.1f "
                "(%+.1f %%)\n",
                kHdrbAmplitudes[i], measured, fitted, 100 * (fitted / measured - 1),
                thm2_energy[i].second, 100 * (thm2_energy[i].second / measured - 1));
    EXPECT_NEAR(fitted / measured, 1.0, 0.05) << "u = " << kHdrbAmplitudes[i];
  }
  // The paper's finding: THM2's energy per cycle, 4 sum fs_i (u_a - uy_i) past yield, is
  // piecewise linear in the amplitude and cannot follow the HDRB's convex growth: from 100 to
  // 160 mm it grows less than measured, and it misses by more than 5 % somewhere.
  const auto growth = [](const std::vector<std::pair<double, double>>& e, bool model) {
    const auto at = [&](std::size_t i) { return model ? e[i].second : e[i].first; };
    return at(7) / at(4);  // 160 mm against 100 mm
  };
  EXPECT_LT(growth(thm2_energy, true), growth(thm2_energy, false));
  double worst = 0.0;
  for (const auto& [measured, fitted] : thm2_energy) {
    worst = std::max(worst, std::abs(fitted / measured - 1));
  }
  EXPECT_GT(worst, 0.05);
}

}  // namespace
}  // namespace isolab::identification
