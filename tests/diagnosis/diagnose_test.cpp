// The diagnosis workflow on data with hidden effects (models/diagnosis/, 1 % noise): given only
// the data and a one-BHM2 base it must name the effect the truth has over the base, nothing in
// the null case, and both effects, larger first, in the two-effect case; the e^2 after the
// addition must be at most a quarter of the base's or within 1.5 x the noise floor.
#include "isolab/diagnosis/diagnose.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "diagnosis/hidden_effect_cases.h"

namespace isolab::diagnosis {
namespace {

std::vector<identification::ComponentSpec> OneBhm2() {
  return {{"base", hysteresis::LawType::kBhm2, {}, {}, {}}};
}

Diagnosis DiagnoseCase(const HiddenEffectCase& c, long budget = 12000) {
  const identification::FitData data = HiddenEffectData(c);
  DiagnoseOptions options;
  options.seed = 7;
  options.budget = budget;
  if (c.one_specimen) std::printf("(one specimen, tests in order)\n");
  const Diagnosis d = Diagnose(OneBhm2(), data, options);
  std::printf("%s: base e^2 = %.4g %%, noise floor %.4g %%, %zu steps, %.1f s; %s\n",
              c.file.c_str(), 100 * d.base.fit.error.total, 100 * d.noise_floor, d.steps.size(),
              d.seconds, d.stop_reason.c_str());
  const auto print = [](const std::vector<Candidate>& candidates) {
    for (const Candidate& k : candidates) {
      std::printf("    %-32s %8.4f (threshold %.3f)%s e^2 %.4g %% BIC %.1f\n",
                  std::string(EffectName(k.evidence.effect)).c_str(), k.evidence.value,
                  k.evidence.threshold, k.refitted ? " refit" : "      ", 100 * k.e2, k.bic);
    }
  };
  for (const DiagnosisStep& step : d.steps) {
    std::printf("  step: %s, e^2 %.4g %% -> %.4g %%, BIC %.1f -> %.1f\n",
                std::string(EffectName(step.effect)).c_str(), 100 * step.e2_before,
                100 * step.e2_after, step.bic_before, step.bic_after);
    print(step.candidates);
  }
  std::printf("  last round:\n");
  print(d.last_candidates);
  return d;
}

void ExpectNamesOnly(const Diagnosis& d, const std::vector<Effect>& effects) {
  ASSERT_EQ(d.steps.size(), effects.size()) << d.stop_reason;
  for (std::size_t k = 0; k < effects.size(); ++k) {
    EXPECT_EQ(EffectName(d.steps[k].effect), EffectName(effects[k])) << "step " << k + 1;
  }
}

void ExpectGapClosed(const Diagnosis& d) {
  const double final_e2 = d.final_model.fit.error.total;
  EXPECT_TRUE(final_e2 <= 0.25 * d.base.fit.error.total || final_e2 <= 1.5 * d.noise_floor)
      << "base e^2 " << d.base.fit.error.total << ", final " << final_e2 << ", noise floor "
      << d.noise_floor;
}

TEST(Diagnose, NullCaseNamesNothing) {
  const Diagnosis d = DiagnoseCase({"null.yaml", 11});
  ExpectNamesOnly(d, {});
  // The noise gate is not the only guard: no detector finds evidence on this residual either.
  for (const Candidate& c : d.last_candidates) {
    EXPECT_LT(c.evidence.value, 0.5 * c.evidence.threshold) << EffectName(c.evidence.effect);
  }
  // The base fits to the noise: its e^2 is the noise floor, which the estimate must see.
  EXPECT_NEAR(d.base.fit.error.total / d.noise_floor, 1.0, 0.15);
}

// Band-limited noise (3 %, a 25-sample moving average, as a load cell's anti-alias filter leaves
// it) hides from the second-difference noise estimate, so the noise gate does not fire; counting
// the residual's correlated samples as independent would then let a component that fits a little
// of it through. The effective sample count keeps every seed at "none".
TEST(Diagnose, NullCaseWithFilteredNoiseNamesNothing) {
  identification::SyntheticTestOptions protocol = DiagnosisProtocol(0);
  protocol.noise = 0.0;
  const model::ModelFile truth =
      model::LoadModelFile(std::string(ISOLAB_SOURCE_DIR) + "/models/diagnosis/null.yaml");
  for (unsigned seed = 1; seed <= 3; ++seed) {
    auto tests = identification::SyntheticTests(truth.isolation, protocol);
    std::mt19937_64 random(seed);
    std::normal_distribution<double> gaussian(0.0, 1.0);
    constexpr int kWidth = 25;
    for (auto& test : tests) {
      double square = 0.0;
      for (const double f : test.force) square += f * f;
      const double rms = std::sqrt(square / test.force.size());
      std::vector<double> white(test.force.size() + kWidth);
      for (double& w : white) w = gaussian(random);
      for (std::size_t k = 0; k < test.force.size(); ++k) {
        double sum = 0.0;
        for (int j = 0; j < kWidth; ++j) sum += white[k + j];
        test.force[k] += 0.03 * rms * sum / std::sqrt(double(kWidth));  // 3 % standard deviation
      }
    }
    const identification::FitData data = AllCycles(std::move(tests));
    DiagnoseOptions options;
    options.seed = seed;
    const Diagnosis d = Diagnose(OneBhm2(), data, options);
    EXPECT_TRUE(d.steps.empty()) << "seed " << seed << ": named "
                                 << (d.steps.empty() ? "" : EffectName(d.steps[0].effect));
    // The estimate misses most of this noise: the gate alone would not have stopped it.
    EXPECT_GT(d.base.fit.error.total, 5 * d.noise_floor);
  }
}

TEST(Diagnose, FindsRateDependence) {
  const Diagnosis d = DiagnoseCase({"rate_dependence.yaml", 12});
  ExpectNamesOnly(d, {Effect::kRateDependence});
  ExpectGapClosed(d);
}

TEST(Diagnose, FindsAmplitudeDependentDissipation) {
  const Diagnosis d = DiagnoseCase({"amplitude_dependent_dissipation.yaml", 13});
  ExpectNamesOnly(d, {Effect::kAmplitudeDependentDissipation});
  ExpectGapClosed(d);
}

TEST(Diagnose, FindsLargeAmplitudeHardening) {
  const Diagnosis d = DiagnoseCase({"large_amplitude_hardening.yaml", 14});
  ExpectNamesOnly(d, {Effect::kLargeAmplitudeHardening});
  ExpectGapClosed(d);
}

TEST(Diagnose, FindsCyclicDegradation) {
  const Diagnosis d = DiagnoseCase({"cyclic_degradation.yaml", 15});
  ExpectNamesOnly(d, {Effect::kCyclicDegradation});
  ExpectGapClosed(d);
}

// Campaigns on one specimen: the tests ran one after another, the degradation accumulating over
// the campaign and the rate case's slider carrying its offset from test to test. Modelled as one
// specimen, the diagnosis names only the right effect and ends within 1.5 x the noise floor.
// Where the carried state matters: the truth itself, simulated from rest test by test, misses
// every test after the first by far more than noise.
void ExpectCarriedStateMatters(const HiddenEffectCase& c) {
  identification::FitData data = HiddenEffectData(c);
  const auto truth = HiddenEffectTruth(c).isolation;
  const auto carried = identification::ComputeFitError(truth, data);
  data.one_specimen = false;
  const auto from_rest = identification::ComputeFitError(truth, data);
  std::printf("%s campaign, truth e^2 per test (carried / from rest), %%:", c.file.c_str());
  for (std::size_t i = 0; i < data.tests.size(); ++i) {
    std::printf(" %s %.3g/%.3g", data.tests[i].name.c_str(), 100 * carried.per_test[i],
                100 * from_rest.per_test[i]);
  }
  std::printf("; total %.4g / %.4g\n", 100 * carried.total, 100 * from_rest.total);
  EXPECT_NEAR(from_rest.per_test[0], carried.per_test[0], 1e-12);  // the first test is fresh
  EXPECT_GT(from_rest.total, 2 * carried.total);
}

void ExpectCampaignDiagnosed(const HiddenEffectCase& c, Effect effect) {
  ExpectCarriedStateMatters(c);
  const Diagnosis d = DiagnoseCase(c, 5000);  // a third of the default: seconds, not minutes
  ExpectNamesOnly(d, {effect});
  EXPECT_LE(d.final_model.fit.error.total, 1.5 * d.noise_floor);
}

TEST(Diagnose, OneSpecimenCampaignWithAccumulatingDegradation) {
  ExpectCampaignDiagnosed({"cyclic_degradation.yaml", 21, true}, Effect::kCyclicDegradation);
}

TEST(Diagnose, OneSpecimenCampaignWithRateDependence) {
  ExpectCampaignDiagnosed({"rate_dependence.yaml", 22, true}, Effect::kRateDependence);
}

TEST(Diagnose, FindsTwoEffectsLargerFirst) {
  const Diagnosis d = DiagnoseCase({"two_effects.yaml", 16});
  ExpectNamesOnly(d, {Effect::kLargeAmplitudeHardening, Effect::kRateDependence});
  ExpectGapClosed(d);
  ASSERT_EQ(d.steps.size(), 2u);
  // Larger first: the first step closes more of the gap than the second.
  EXPECT_GT(d.steps[0].e2_before - d.steps[0].e2_after, d.steps[1].e2_before - d.steps[1].e2_after);
}

}  // namespace
}  // namespace isolab::diagnosis
