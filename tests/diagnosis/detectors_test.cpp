// Each detector on residuals of known make (detectors.h): the data are a truth's forces, the
// model read against them is the truth without the effect (or the truth itself: the null), so no
// fit stands between the effect and its statistic.
//  * a residual that is exactly c v (a dashpot the model lacks, no noise) is all viscous: the
//    partial R^2 is 1, and -c v (a negative dashpot) counts for nothing;
//  * a residual that is exactly a constant is all offset: R^2 = 1; with noise of deviation s,
//    c^2 / (c^2 + s^2);
//  * each catalogue effect the model lacks reaches its detector's threshold, and no detector
//    fires on the truth's own residual (1 % noise) beyond half its threshold;
//  * backlash does not fire on a hardening spring's residual, which also stiffens again, but
//    past the loop's centre, nor asymmetric strength on a symmetric effect's.
#include "isolab/diagnosis/detectors.h"

#include <gtest/gtest.h>

#include <random>

#include "diagnosis/hidden_effect_cases.h"

namespace isolab::diagnosis {
namespace {

using hysteresis::LawType;

const hysteresis::ParallelAssembly kBase = hysteresis::SingleLaw(LawType::kBhm2, {1.5, 0.25, 8});

// The protocol of the hidden-effect cases, noise as asked, through `truth`.
identification::FitData Data(const hysteresis::ParallelAssembly& truth, double noise,
                             unsigned seed = 5) {
  identification::SyntheticTestOptions protocol = DiagnosisProtocol(seed);
  protocol.noise = noise;
  return AllCycles(identification::SyntheticTests(truth, protocol));
}

hysteresis::ParallelAssembly Truth(const std::string& file) {
  return HiddenEffectTruth({file, 1}).isolation;
}

TEST(Detectors, AResidualThatIsAViscousForceIsAllViscous) {
  const auto with_dashpot = hysteresis::ParallelAssembly(
      {{"base",
        hysteresis::LawParameters::Make(LawType::kBhm2, hysteresis::ParameterForm::kMathematical,
                                        std::vector{1.5, 0.25, 8.0})},
       {"c",
        hysteresis::LawParameters::Make(LawType::kDashpot, hysteresis::ParameterForm::kMathematical,
                                        std::vector{0.002})}});
  const auto data = Data(with_dashpot, 0.0);
  const Evidence e = Detect(Effect::kRateDependence, Discrepancy::Of(kBase, data));
  EXPECT_EQ(e.effect, Effect::kRateDependence);
  EXPECT_NEAR(e.value, 1.0, 1e-9);
  EXPECT_NEAR(e.supporting[0].value, 0.002, 1e-5);  // c from the residual
  // The model has a dashpot the device lacks: the residual is -c v, and c must be positive.
  const auto reversed = Data(kBase, 0.0);
  EXPECT_EQ(Detect(Effect::kRateDependence, Discrepancy::Of(with_dashpot, reversed)).value, 0.0);
}

TEST(Detectors, AResidualThatIsAConstantIsAllOffset) {
  auto data = Data(kBase, 0.0);
  for (auto& test : data.tests) {
    for (double& f : test.force) f += 2.0;
  }
  EXPECT_NEAR(Detect(Effect::kAsymmetricStrength, Discrepancy::Of(kBase, data)).value, 1.0, 1e-12);
  // With white noise of deviation s = c: the constant explains c^2 / (c^2 + s^2) = 1/2.
  std::mt19937_64 random(3);
  std::normal_distribution<double> gaussian(0.0, 2.0);
  for (auto& test : data.tests) {
    for (double& f : test.force) f += gaussian(random);
  }
  EXPECT_NEAR(Detect(Effect::kAsymmetricStrength, Discrepancy::Of(kBase, data)).value, 0.5, 0.03);
}

// The hidden-effect truths' added components, taken away again: the residual is the effect.
struct Case {
  const char* file;
  Effect effect;
};
const Case kCases[] = {
    {"rate_dependence.yaml", Effect::kRateDependence},
    {"amplitude_dependent_dissipation.yaml", Effect::kAmplitudeDependentDissipation},
    {"large_amplitude_hardening.yaml", Effect::kLargeAmplitudeHardening},
    {"cyclic_degradation.yaml", Effect::kCyclicDegradation},
    {"asymmetric_strength.yaml", Effect::kAsymmetricStrength},
    {"backlash.yaml", Effect::kBacklash},
};

TEST(Detectors, EachEffectTheModelLacksReachesItsThreshold) {
  for (const Case& c : kCases) {
    const auto data = Data(Truth(c.file), 0.01);
    const Evidence e = Detect(c.effect, Discrepancy::Of(kBase, data));
    EXPECT_TRUE(e.Supported()) << c.file << ": " << e.value << " < " << e.threshold;
    EXPECT_FALSE(e.finding.empty());
  }
}

TEST(Detectors, NoneFiresOnTheTruthsOwnResidual) {
  for (const Case& c : kCases) {
    const auto truth = Truth(c.file);
    const auto data = Data(truth, 0.01);  // outlives the discrepancy, which points to it
    const Discrepancy d = Discrepancy::Of(truth, data);
    for (const Effect effect : AllEffects()) {
      const Evidence e = Detect(effect, d);
      EXPECT_LT(e.Strength(), 0.5) << c.file << ", " << EffectName(effect) << ": " << e.value;
    }
  }
}

TEST(Detectors, TheRealDevicesEffectsAreNotReadIntoOtherEffects) {
  for (const Case& c : kCases) {
    const auto data = Data(Truth(c.file), 0.01);
    const Discrepancy d = Discrepancy::Of(kBase, data);
    if (c.effect != Effect::kBacklash) {
      EXPECT_LT(Detect(Effect::kBacklash, d).Strength(), 0.5) << c.file;
    }
    if (c.effect != Effect::kAsymmetricStrength) {
      EXPECT_LT(Detect(Effect::kAsymmetricStrength, d).Strength(), 0.5) << c.file;
    }
  }
}

}  // namespace
}  // namespace isolab::diagnosis
