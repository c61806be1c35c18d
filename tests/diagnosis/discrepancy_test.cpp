// The discrepancy's own numbers against independent ones:
//  * the half-cycles of a steady loop are alike, and a linear spring's dissipate nothing, with
//    its stiffness as their secant;
//  * the noise of white Gaussian noise of known deviation, from the band above the response and
//    from samples at rest;
//  * the noise floor of one data set at 1024 Hz and decimated to 128 Hz (the friction damper of
//    friction_damper_case.h, its noise through a load cell's 50 Hz filter): read where the
//    signal has no content, it is the same at both rates and the e^2 the truth leaves, where
//    second differences differ by orders of magnitude between the rates;
//  * the effective sample count of an AR(1) residual, n (1 - rho) / (1 + rho).
#include "isolab/diagnosis/discrepancy.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "diagnosis/friction_damper_case.h"
#include "doc_table_row.h"
#include "isolab/identification/fit.h"
#include "isolab/identification/synthetic_tests.h"

namespace isolab::diagnosis {
namespace {

using hysteresis::LawType;

// A steady bilinear loop's half-cycles span the amplitude and half the period, and carry the
// same energy and secant each (the detectors compare them with the model's through the same
// averaging near the reversals, so the measures need only be the same for the same loop; the
// unaveraged half-cycle energy is checked against the loop's closed-form area in
// cyclic_data_test). A linear spring's half-cycles dissipate nothing, and their secant is the
// spring's stiffness however the reversals are averaged.
TEST(Discrepancy, HalfCyclesOfSteadyLoopsAreAlikeAndALinearSpringDissipatesNothing) {
  const auto bhm2 = hysteresis::SingleLaw(LawType::kBhm2, {1.5, 0.25, 8});
  const auto data = AllCycles(identification::SyntheticTests(bhm2, {{100}, {2.0}, 3, 4000}));
  const Discrepancy d = Discrepancy::Of(bhm2, data);
  ASSERT_EQ(d.cycles.size(), 5u);
  for (std::size_t c = 1; c < d.cycles.size(); ++c) {  // the first follows the virgin loading
    EXPECT_NEAR(d.cycles[c].amplitude, 100.0, 1e-9);
    EXPECT_NEAR(d.cycles[c].period, 2.0, 1e-9);
    EXPECT_NEAR(d.cycles[c].measured.energy, d.cycles[1].measured.energy, 1e-9 * 1000);
    EXPECT_NEAR(d.cycles[c].measured.secant, d.cycles[1].measured.secant, 1e-12);
    EXPECT_EQ(d.cycles[c].measured.energy, d.cycles[c].modelled.energy);  // the truth itself
  }
  const auto spring = hysteresis::SingleLaw(LawType::kLinearSpring, {0.7});
  const auto linear = AllCycles(identification::SyntheticTests(spring, {{50}, {1.0}, 2, 400}));
  for (const CycleRecord& c : Discrepancy::Of(spring, linear).cycles) {
    EXPECT_NEAR(c.measured.energy, 0.0, 1e-9);
    EXPECT_NEAR(c.measured.secant, 0.7, 1e-12);
  }
}

TEST(NoiseEstimate, WhiteNoiseOfKnownDeviationFromTheBandAboveTheResponseAndFromRest) {
  const auto bhm2 = hysteresis::SingleLaw(LawType::kBhm2, {1.5, 0.25, 8});
  auto tests = identification::SyntheticTests(bhm2, {{100}, {2.0}, 5, 1000});
  std::mt19937_64 random(4);
  std::normal_distribution<double> gaussian(0.0, 0.3);
  for (double& f : tests[0].force) f += gaussian(random);
  const NoiseEstimate band = EstimateForceNoise(tests[0]);
  EXPECT_EQ(band.source, NoiseEstimate::Source::kBand);
  EXPECT_NEAR(band.sigma, 0.3, 0.03);
  // 2 s at rest before the motion: the force's spread there is the noise, whatever its spectrum.
  identification::CyclicTestData rest;
  for (int k = 0; k < 400; ++k) {
    rest.time.push_back(0.005 * k);
    rest.displacement.push_back(0.0);
    rest.force.push_back(gaussian(random));
  }
  for (std::size_t k = 0; k < tests[0].time.size(); ++k) {
    rest.time.push_back(2.0 + tests[0].time[k]);
    rest.displacement.push_back(tests[0].displacement[k]);
    rest.force.push_back(tests[0].force[k]);
  }
  const NoiseEstimate at_rest = EstimateForceNoise(rest);
  EXPECT_EQ(at_rest.source, NoiseEstimate::Source::kRest);
  EXPECT_GE(at_rest.rest_samples, 400);
  EXPECT_NEAR(at_rest.sigma, 0.3, 0.03);
}

enum class Read { kForce, kResidual, kSecondDifferences };

// The floor read from each test's force, from the truth's residual (the final model of a
// diagnosis that found the truth), or from second differences.
double Floor(const identification::FitData& data, Read read) {
  const auto truth = testing::FrictionDamperTruth();
  const auto forces = identification::SimulateForces(truth, data.tests, false);
  std::vector<double> sigma;
  for (std::size_t i = 0; i < data.tests.size(); ++i) {
    const auto& test = data.tests[i];
    std::vector<double> residual(test.force.size());
    for (std::size_t k = 0; k < residual.size(); ++k) residual[k] = test.force[k] - forces[i][k];
    sigma.push_back(read == Read::kSecondDifferences ? SecondDifferenceNoise(test)
                    : read == Read::kForce           ? EstimateForceNoise(test).sigma
                                                     : EstimateNoise(test, residual).sigma);
  }
  return NoiseFloor(data, sigma);
}

TEST(NoiseFloor, TheSameDataAt1024And128HzHaveTheSameFloor) {
  const auto high = testing::FrictionDamperTests(1024.0);
  const auto truth = testing::FrictionDamperTruth();
  const auto at_1024 = AllCycles(high);
  const auto at_128 = AllCycles(testing::Decimate(high, 8));
  // The e^2 the truth leaves is the noise's: the floor any rate should read.
  const double noise_1024 = identification::ComputeFitError(truth, at_1024).total;
  const double noise_128 = identification::ComputeFitError(truth, at_128).total;
  const double residual_1024 = Floor(at_1024, Read::kResidual);
  const double residual_128 = Floor(at_128, Read::kResidual);
  const double force_1024 = Floor(at_1024, Read::kForce), force_128 = Floor(at_128, Read::kForce);
  const double second_1024 = Floor(at_1024, Read::kSecondDifferences);
  const double second_128 = Floor(at_128, Read::kSecondDifferences);
  // docs/diagnosis.md quotes this table (scripts/doc_tables/test_printout.py).
  const auto percent = [](double e2, int digits) {
    return isolab::testing::Significant(100 * e2, digits) + " %";
  };
  isolab::testing::PrintTableHeader({"", "1024 Hz", "128 Hz"});
  isolab::testing::PrintTableRow(
      {"e^2 the truth leaves (the noise's)", percent(noise_1024, 4), percent(noise_128, 4)});
  isolab::testing::PrintTableRow({"floor read above the response, from the truth's residual",
                                  percent(residual_1024, 4), percent(residual_128, 4)});
  isolab::testing::PrintTableRow({"the same from the force (harmonic lines in the band)",
                                  percent(force_1024, 4), percent(force_128, 4)});
  isolab::testing::PrintTableRow({"from the force's second differences (the estimator before)",
                                  percent(second_1024, 3), percent(second_128, 2)});
  // The same at both rates, and the noise's, read from the residual a diagnosis ends with.
  EXPECT_LT(std::max(residual_1024, residual_128) / std::min(residual_1024, residual_128), 1.2);
  EXPECT_NEAR(residual_1024 / noise_1024, 1.0, 0.15);
  EXPECT_NEAR(residual_128 / noise_128, 1.0, 0.15);
  // From the force, with the friction's harmonic lines in the band: higher, but the same at both
  // rates within a factor 2, and never below the noise (lines only add).
  EXPECT_LT(std::max(force_1024, force_128) / std::min(force_1024, force_128), 2.0);
  EXPECT_GT(force_1024, 0.9 * noise_1024);
  EXPECT_LT(force_1024, 2.0 * noise_1024);
  // Filtered noise is smooth from sample to sample at 1024 Hz: second differences miss it.
  EXPECT_GT(second_128 / second_1024, 100.0);
}

// A device that chatters while it slides, a quarter of a second at rest before each test: at
// 1024 Hz 256 samples at rest (enough to read there), at 128 Hz 32 (too few). The rest read sees
// the load cell's noise alone, the band read the chatter too, so read one way at one rate and the
// other way at the other the floors would be far apart (584 times on a real damper). Both reads
// are taken where they can be, and the larger where they disagree: the floors at the two rates
// agree, the 1024 Hz tests are marked uncertain, and the floor is the e^2 the truth leaves
// (noise and chatter: what no model of the hysteresis can take out).
TEST(NoiseFloor, AChatteringDeviceHasTheSameFloorAt1024And128Hz) {
  testing::DamperNoise noise;
  noise.rest_seconds = 0.25;
  noise.chatter = 0.1;  // kip, five times the load cell's noise
  const auto high = testing::FrictionDamperTests(1024.0, noise);
  const auto at_1024 = AllCycles(high);
  const auto at_128 = AllCycles(testing::Decimate(high, 8));
  const auto truth = testing::FrictionDamperTruth();
  const double truth_1024 = identification::ComputeFitError(truth, at_1024).total;
  const double truth_128 = identification::ComputeFitError(truth, at_128).total;
  const double residual_1024 = Floor(at_1024, Read::kResidual);
  const double residual_128 = Floor(at_128, Read::kResidual);
  const double force_1024 = Floor(at_1024, Read::kForce), force_128 = Floor(at_128, Read::kForce);
  std::printf(
      "chatter, noise floor %%, at 1024 and 128 Hz: the truth leaves %.4g and %.4g; from the "
      "truth's residual %.4g and %.4g; from the force %.4g and %.4g\n",
      100 * truth_1024, 100 * truth_128, 100 * residual_1024, 100 * residual_128, 100 * force_1024,
      100 * force_128);
  for (const auto& test : at_1024.tests) {
    const NoiseEstimate n = EstimateForceNoise(test);
    std::printf("  %s at 1024 Hz: %s\n", test.name.c_str(), n.Describe().c_str());
    EXPECT_TRUE(n.uncertain) << test.name;
    EXPECT_EQ(n.source, NoiseEstimate::Source::kBand) << test.name;
    // The load cell alone; 257 samples of 50 Hz noise are some 25 independent ones, so 40 %.
    EXPECT_NEAR(n.rest_sigma, 0.02, 0.008) << test.name;
  }
  for (const auto& test : at_128.tests) {
    const NoiseEstimate n = EstimateForceNoise(test);
    EXPECT_FALSE(n.uncertain) << test.name;
    EXPECT_EQ(n.rest_samples, 0) << test.name;
  }
  EXPECT_LT(std::max(force_1024, force_128) / std::min(force_1024, force_128), 2.0);
  EXPECT_LT(std::max(residual_1024, residual_128) / std::min(residual_1024, residual_128), 1.5);
  EXPECT_NEAR(residual_1024 / truth_1024, 1.0, 0.3);
  EXPECT_NEAR(residual_128 / truth_128, 1.0, 0.3);
}

// The same damper without chatter, at rest for a quarter of a second: the two reads agree within
// the factor of two (the friction's sharp reversals put harmonic lines above the response, which
// the band read's low quantile passes over), so no test is uncertain and the floor is the rest
// read's. A load cell quantised far above its noise reads one value at rest: no rest read.
TEST(NoiseEstimate, AQuietDeviceIsNotUncertainAndAConstantRestIsNoRead) {
  testing::DamperNoise noise;
  noise.rest_seconds = 0.25;
  for (const auto& test : testing::FrictionDamperTests(1024.0, noise)) {
    const NoiseEstimate n = EstimateForceNoise(test);
    std::printf("  %s quiet: rest read %.4g, band read %.4g\n", test.name.c_str(), n.rest_sigma,
                n.band_sigma);
    EXPECT_FALSE(n.uncertain) << test.name << ": " << n.Describe();
    EXPECT_EQ(n.source, NoiseEstimate::Source::kRest) << test.name;
  }
  noise.quantum = 0.5;  // kip: 25 times the noise
  for (const auto& test : testing::FrictionDamperTests(1024.0, noise)) {
    const NoiseEstimate n = EstimateForceNoise(test);
    EXPECT_EQ(n.rest_samples, 0) << test.name;
    EXPECT_FALSE(n.uncertain) << test.name;
    EXPECT_EQ(n.source, NoiseEstimate::Source::kBand) << test.name;
  }
}

TEST(EffectiveSamples, AnAr1ResidualCountsAsNTimesOneLessRhoOverOnePlusRho) {
  const auto spring = hysteresis::SingleLaw(LawType::kLinearSpring, {0.5});
  auto tests = identification::SyntheticTests(spring, {{50, 100}, {2.0}, 10, 2000});
  const double rho = 0.8;
  std::mt19937_64 random(9);
  std::normal_distribution<double> gaussian(0.0, 1.0);
  long samples = 0;
  for (auto& test : tests) {
    double e = 0.0;
    for (double& f : test.force) {
      e = rho * e + gaussian(random);
      f += e;
    }
    samples += static_cast<long>(test.force.size());
  }
  const auto data = AllCycles(std::move(tests));
  const Discrepancy d = Discrepancy::Of(spring, data);
  EXPECT_NEAR(EffectiveSamples(d) / (samples * (1 - rho) / (1 + rho)), 1.0, 0.15);
  for (const double tau : CorrelationTimes(d)) EXPECT_NEAR(tau, (1 + rho) / (1 - rho), 1.5);
}

}  // namespace
}  // namespace isolab::diagnosis
