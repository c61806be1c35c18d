// Identification from cyclic tests: cycle splitting, the paper's error, parameter recovery of a
// known three-component model, and the paper's finding on the HDRB tests (Table 9 THM1 system
// against a six-component THM2 fit); the options' checks, the same fit on 1 and 4 threads, more
// budget never worse and never overrun, the convergence stop, and components fitted to zero.
#include "isolab/identification/fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <thread>

#include "identification/table9_assembly.h"
#include "isolab/core/errors.h"
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
  const FitData data =
      SelectCycles(SyntheticTests(model, {kHdrbAmplitudes, {2.0}, 3, 200, 0.0, 1}), {3});
  const ModelParametrisation parametrisation({{"a", LawType::kElastoplastic, {}, {}, {}},
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
          << "component " << c << " parameter " << p << ": " << result.mathematical[c][p] << " vs "
          << truth[c][p];
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
  const auto thm1_specs =
      Specs({{LawType::kTrilinearElastic, 3}, {LawType::kThm1, 4}, {LawType::kElastoplastic, 2}});
  const auto thm2_specs = Specs({{LawType::kThm2, 6}});
  const FitResult thm1 = FitHdrb(data, thm1_specs, 60000);
  const FitResult thm2 = FitHdrb(data, thm2_specs, 60000);
  const auto thm1_model =
      ModelParametrisation(thm1_specs, ScalesOf(data)).Assembly(thm1.point, thm1.amplitudes);
  const auto thm2_model =
      ModelParametrisation(thm2_specs, ScalesOf(data)).Assembly(thm2.point, thm2.amplitudes);
  std::printf(
      "HDRB fits: 33-parameter THM1 e^2 = %.3f %% (%ld evaluations, %.1f s); "
      "30-parameter THM2 e^2 = %.3f %% (%.1f s)\n",
      100 * thm1.error.total, thm1.evaluations, thm1.seconds, 100 * thm2.error.total, thm2.seconds);
  // The truth is inside the nine-component class and the data are noise-free: the default budget
  // reaches 0.023 % (on any machine: the island count is fixed), far below THM2's 2.8 %. The
  // search cannot reach zero within the budget (21 shape coordinates, a multimodal landscape),
  // but a regression of the search shows here: three times what it reaches.
  EXPECT_LE(thm1.error.total, 7e-4);
  EXPECT_GE(thm2.error.total, 50 * thm1.error.total);

  const auto thm1_energy = EnergyPerTest(thm1_model, data);
  const auto thm2_energy = EnergyPerTest(thm2_model, data);
  for (std::size_t i = 0; i < kHdrbAmplitudes.size(); ++i) {
    const auto [measured, fitted] = thm1_energy[i];
    std::printf(
        "  u = %5.0f mm: W_d measured %9.1f, THM1 fit %9.1f (%+.1f %%), THM2 fit %9.1f "
        "(%+.1f %%)\n",
        kHdrbAmplitudes[i], measured, fitted, 100 * (fitted / measured - 1), thm2_energy[i].second,
        100 * (thm2_energy[i].second / measured - 1));
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

TEST(FitOptions, ValidateNamesTheFieldAtFault) {
  const auto key_of = [](FitOptions options) {
    try {
      options.Validate();
    } catch (const InvalidParameter& error) {
      return error.violation().key;
    }
    return std::string("none");
  };
  EXPECT_EQ(key_of({}), "none");
  FitOptions o;
  o.budget = 99;
  EXPECT_EQ(key_of(o), "budget");
  o = {};
  o.islands = 0;
  EXPECT_EQ(key_of(o), "islands");
  o = {};
  o.threads = -1;
  EXPECT_EQ(key_of(o), "threads");
  o = {};
  o.polish_share = 1.0;
  EXPECT_EQ(key_of(o), "polish_share");
  o = {};
  o.stop_window = -1;
  EXPECT_EQ(key_of(o), "stop_window");
  o = {};
  o.stop_window_share = 1.5;
  EXPECT_EQ(key_of(o), "stop_window_share");
  o = {};
  o.stop_e2 = 1.0;
  EXPECT_EQ(key_of(o), "stop_e2");
  o = {};
  o.stop_step = -0.1;
  EXPECT_EQ(key_of(o), "stop_step");
}

// Noisy BHM2 tests and a two-component model to fit to them: the test models below.
FitData NoisyBhm2Data(int per_cycle, std::vector<double> amplitudes = {25, 100, 200}) {
  const auto truth = hysteresis::SingleLaw(LawType::kBhm2, {1.5, 0.25, 8});
  return SelectCycles(SyntheticTests(truth, {amplitudes, {2.0}, 3, per_cycle, 0.01, 5}), {});
}

const std::vector<ComponentSpec> kBhm2AndElastoplastic = {
    {"bilinear", LawType::kBhm2, {}, {}, {}}, {"extra", LawType::kElastoplastic, {}, {}, {}}};

// The islands share nothing and each evaluation's laws write their own columns, summed in one
// order: so the thread count, which differs from machine to machine, cannot change the result.
// Large enough data (2 laws x 120,000 samples) that each evaluation is shared too.
TEST(Fit, TheSameSeedGivesTheSameFitToTheLastDigitOnOneAndFourThreads) {
  const FitData data = NoisyBhm2Data(20000, {50, 200});
  const ModelParametrisation model(kBhm2AndElastoplastic, ScalesOf(data));
  const auto fit = [&](int threads) {
    FitOptions options;
    options.seed = 3;
    options.budget = 600;
    options.threads = threads;
    return Fit(model, data, options);
  };
  const FitResult one = fit(1), four = fit(4);
  EXPECT_EQ(one.error.total, four.error.total);
  EXPECT_EQ(one.evaluations, four.evaluations);
  EXPECT_EQ(one.point, four.point);
  EXPECT_EQ(one.mathematical, four.mathematical);
}

// The CMA-ES stage runs whole chunks while the budget allows, the same chunks for a larger
// budget, and the polish starts from the best point and keeps its best: a larger budget can only
// find a lower e^2. Every evaluation counts, the polish's included.
TEST(Fit, MoreBudgetNeverGivesAWorseFitAndNeverOverrunsIt) {
  const FitData data = NoisyBhm2Data(200);
  const ModelParametrisation model(kBhm2AndElastoplastic, ScalesOf(data));
  for (const long window : {0L, 3000L}) {
    double previous = INFINITY;
    for (const long budget : {100L, 400L, 1500L, 6000L}) {
      FitOptions options;
      options.seed = 2;
      options.budget = budget;
      options.stop_window = window;
      const FitResult result = Fit(model, data, options);
      EXPECT_LE(result.evaluations, budget) << "window " << window;
      EXPECT_LE(result.error.total, previous * (1 + 1e-12))
          << "budget " << budget << ", window " << window;
      previous = result.error.total;
    }
  }
}

// Noise-free data from a law inside the model class: the search finds the truth long before the
// default budget, and the convergence stop ends it there, saying so.
TEST(Fit, TheConvergenceStopEndsASettledSearchAndSaysWhy) {
  const auto truth = hysteresis::SingleLaw(LawType::kBhm2, {1.5, 0.25, 8});
  const FitData data = SelectCycles(SyntheticTests(truth, {{25, 100, 200}, {2.0}, 3, 200}), {});
  const ModelParametrisation model({{"bilinear", LawType::kBhm2, {}, {}, {}}}, ScalesOf(data));
  FitOptions options;
  options.budget = 60000;
  const FitResult result = Fit(model, data, options);
  EXPECT_EQ(result.stop, FitStop::kConverged);
  EXPECT_LT(result.evaluations, 15000);
  EXPECT_NE(result.stop_reason.find("converged after"), std::string::npos) << result.stop_reason;
  // Settled: below 1e-12, an RMS force error of 1e-6, which fixes uy to about 1e-5 of itself.
  EXPECT_LT(result.error.total, 1e-12);
  EXPECT_NEAR(result.mathematical[0][2], 8.0, 1e-4);
  options.stop_window = 0;
  options.budget = 2000;
  const FitResult full = Fit(model, data, options);
  EXPECT_EQ(full.stop, FitStop::kBudget);
  EXPECT_NE(full.stop_reason.find("budget of 2000"), std::string::npos) << full.stop_reason;
}

// A fit whose sign-constrained solve set every stiffness of two components to zero (the
// amplitudes at a shape point, as Fit returns them): those two are the zero components, and
// dropping them leaves the forces, so e^2, exactly as they were.
TEST(Fit, ComponentsFittedToZeroAreDroppedWithoutChangingTheForces) {
  const auto spring = hysteresis::SingleLaw(LawType::kLinearSpring, {0.5});
  const FitData data = SelectCycles(SyntheticTests(spring, {{20, 60}, {2.0}, 2, 200}), {});
  const std::vector<ComponentSpec> specs = {{"a", LawType::kElastoplastic, {}, {}, {}},
                                            {"b", LawType::kBhm2, {}, {}, {}},
                                            {"c", LawType::kTrilinearElastic, {}, {}, {}},
                                            {"d", LawType::kElastoplastic, {}, {}, {}}};
  const ModelParametrisation model(specs, ScalesOf(data));
  FitResult result;
  result.point = model.StartPoint();
  result.amplitudes = Eigen::VectorXd::Zero(model.amplitude_count());
  result.amplitudes[model.first_amplitude(1) + 1] = 0.3;  // b's k1 alone: a BHM2 without slider
  result.amplitudes[model.first_amplitude(2)] = 0.2;      // c's k1
  result.amplitudes[model.first_amplitude(3)] = 0.4;      // d's k0
  result.mathematical = model.Mathematical(result.point, result.amplitudes);
  const double e2 = ComputeFitError(model.Assembly(result.point, result.amplitudes), data).total;
  const auto zero = ZeroComponents(model, result.amplitudes);
  EXPECT_EQ(zero, std::vector<std::size_t>{0});  // b has a stiffness left: not zero
  const auto kept = DropComponents(model, zero, &result);
  ASSERT_EQ(kept.size(), 3u);
  EXPECT_EQ(kept[0].name, "b");
  const ModelParametrisation smaller(kept, ScalesOf(data));
  ASSERT_EQ(static_cast<int>(result.point.size()), smaller.dimension());
  // Equal but for the hair (1e-12 of the largest stiffness) that Assembly keeps a zero stiffness
  // above zero, so the dropped laws are valid.
  EXPECT_NEAR(ComputeFitError(smaller.Assembly(result.point, result.amplitudes), data).total, e2,
              1e-9 * e2);
  EXPECT_EQ(result.mathematical[0][1], 0.3);  // b's k1
}

TEST(Fit, ALawLeftWithoutItsSliderIsWrittenAsTheLawThatRemains) {
  std::vector<LawType> types = {LawType::kBhm2, LawType::kThm2, LawType::kBhm2};
  std::vector<std::vector<double>> values = {{0.3, 0.3, 5}, {0.7, 0.7, 0.9, 4, 50}, {1.5, 0.25, 8}};
  const auto notes = SimplifyComponents({"a", "b", "c"}, &types, &values);
  ASSERT_EQ(notes.size(), 2u);
  EXPECT_EQ(types, (std::vector<LawType>{LawType::kLinearSpring, LawType::kTrilinearElastic,
                                         LawType::kBhm2}));
  EXPECT_EQ(values[0], std::vector<double>{0.3});
  EXPECT_EQ(values[1], (std::vector<double>{0.7, 0.9, 50}));
  EXPECT_NE(notes[0].find("linear_spring"), std::string::npos) << notes[0];
}

// Each thread keeps the bases of its last evaluation (fit.cpp): an evaluation after one of another
// model of as many stiffnesses on the same tests (so into the same matrices) gives, to the last
// digit, what it gives on a fresh thread, and that e^2 is the one a simulation of its assembly
// gives.
TEST(SolveAmplitudes, BasesKeptFromAnotherModelGiveWhatFreshOnesGive) {
  const FitData hdrb =
      SelectCycles(SyntheticTests(Table9(), {kHdrbAmplitudes, {2.0}, 3, 200, 0.0, 1}), {3});
  const ModelParametrisation thm2(Specs({{LawType::kThm2, 2}}), ScalesOf(hdrb));
  const ModelParametrisation other(
      Specs({{LawType::kThm2, 1}, {LawType::kBhm2, 1}, {LawType::kElastoplastic, 1}}),
      ScalesOf(hdrb));
  ASSERT_EQ(other.amplitude_count(), thm2.amplitude_count());
  const std::vector<double> x(thm2.dimension(), 0.4);
  AmplitudeSolution fresh;
  std::thread([&] { fresh = SolveAmplitudes(thm2, x, hdrb); }).join();

  SolveAmplitudes(other, other.StartPoint(), hdrb);
  const AmplitudeSolution kept = SolveAmplitudes(thm2, x, hdrb);
  EXPECT_EQ(kept.error, fresh.error);
  EXPECT_EQ(kept.amplitudes, fresh.amplitudes);
  const double simulated = ComputeFitError(thm2.Assembly(x, kept.amplitudes), hdrb).total;
  EXPECT_NEAR(kept.error, simulated, 1e-9 * simulated);
}

}  // namespace
}  // namespace isolab::identification
