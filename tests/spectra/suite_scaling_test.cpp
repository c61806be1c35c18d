// Suite scaling to a target (suite_scaling.h, ASCE 7-16 Sec. 17.3.3) against factors worked by
// hand for power-law spectra on a three-period grid, the properties that define the factors on a
// fine grid, and the bundled records: two pairs' RotD100 spectra scaled, then the records
// themselves scaled by the factors and their spectra computed again, independently of the
// factors' arithmetic, to show the scaled suite's mean on the target.
#include "isolab/spectra/suite_scaling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "isolab/core/errors.h"
#include "isolab/io/record.h"
#include "isolab/spectra/rotd_spectrum.h"
#include "refused_key.h"

namespace isolab::spectra {
namespace {

constexpr double kTight = 1e-12;

using testing::RefusedKey;

// Sa = a T^b at each period.
std::vector<double> PowerLaw(const std::vector<double>& periods, double a, double b) {
  std::vector<double> sa;
  for (const double t : periods) sa.push_back(a * std::pow(t, b));
  return sa;
}

std::vector<double> Targets(const TargetSpectrum& target, const std::vector<double>& periods) {
  std::vector<double> sa;
  for (const double t : periods) sa.push_back(SpectralAcceleration(target, t));
  return sa;
}

// Grid T = 1, 2, 4 s; target 1/T = 1, 0.5, 0.25 g.
const std::vector<double> kPeriods = {1.0, 2.0, 4.0};
const std::vector<double> kTarget = {1.0, 0.5, 0.25};

TEST(SuiteScaling, TwoPowerLawsByHand) {
  // Pair 1: 0.5 / T = 0.5, 0.25, 0.125: target / it = 2 throughout, s1 = 2.
  // Pair 2: 1 / T^2 = 1, 0.25, 0.0625: ln(target / it) = ln T, mean (0 + ln 2 + ln 4) / 3 = ln 2,
  //   s2 = 2; shaped 2, 0.5, 0.125.
  // Shaped mean (1 + 2, 0.5 + 0.5, 0.25 + 0.125) / 2 = 1.5, 0.5, 0.1875; target over it 2/3, 1,
  //   4/3: c = 4/3 at 4 s. Factors 8/3 each; scaled mean 4/3 x shaped = 2, 2/3, 0.25.
  const SuiteScaling s =
      ScaleSuite(kPeriods, kTarget, {PowerLaw(kPeriods, 0.5, -1), PowerLaw(kPeriods, 1.0, -2)});
  ASSERT_EQ(s.pair_shape_factors.size(), 2u);
  EXPECT_NEAR(s.pair_shape_factors[0], 2.0, kTight);
  EXPECT_NEAR(s.pair_shape_factors[1], 2.0, kTight);
  EXPECT_NEAR(s.common_factor, 4.0 / 3.0, kTight);
  EXPECT_NEAR(s.factors[0], 8.0 / 3.0, kTight);
  EXPECT_NEAR(s.factors[1], 8.0 / 3.0, kTight);
  EXPECT_EQ(s.governing, 2u);
  EXPECT_NEAR(s.scaled_mean[0], 2.0, kTight);
  EXPECT_NEAR(s.scaled_mean[1], 2.0 / 3.0, kTight);
  EXPECT_NEAR(s.scaled_mean[2], 0.25, kTight);
  EXPECT_EQ(s.periods, kPeriods);
  EXPECT_EQ(s.target, kTarget);
}

TEST(SuiteScaling, ThreePowerLawsByHandShapesDiffer) {
  // As above, plus pair 3: 3 g flat: ln(target / 3) = -ln 3 - ln T, mean -ln 3 - ln 2, s3 = 1/6;
  //   shaped 0.5, 0.5, 0.5.
  // Shaped mean (1 + 2 + 0.5, 0.5 + 0.5 + 0.5, 0.25 + 0.125 + 0.5) / 3 = 7/6, 0.5, 0.875/3;
  //   target over it 6/7, 1, 6/7: c = 1 at 2 s. Factors 2, 2, 1/6.
  const SuiteScaling s = ScaleSuite(
      kPeriods, kTarget,
      {PowerLaw(kPeriods, 0.5, -1), PowerLaw(kPeriods, 1.0, -2), PowerLaw(kPeriods, 3.0, 0)});
  EXPECT_NEAR(s.pair_shape_factors[2], 1.0 / 6.0, kTight);
  EXPECT_NEAR(s.common_factor, 1.0, kTight);
  EXPECT_NEAR(s.factors[0], 2.0, kTight);
  EXPECT_NEAR(s.factors[1], 2.0, kTight);
  EXPECT_NEAR(s.factors[2], 1.0 / 6.0, kTight);
  EXPECT_EQ(s.governing, 1u);
  EXPECT_NEAR(s.scaled_mean[0], 7.0 / 6.0, kTight);
  EXPECT_NEAR(s.scaled_mean[1], 0.5, kTight);
  EXPECT_NEAR(s.scaled_mean[2], 0.875 / 3.0, kTight);
}

TEST(SuiteScaling, OnePairAtHalfTheTargetGetsTwoAndTouchesEverywhere) {
  const TargetSpectrum target = Asce7Spectrum{1.5, 0.9, 3.0};
  const std::vector<double> periods = ScalingPeriods(target, 1.5, 4.0);
  const std::vector<double> sa = Targets(target, periods);
  std::vector<double> half;
  for (const double a : sa) half.push_back(0.5 * a);
  const SuiteScaling s = ScaleSuite(periods, sa, {half});
  EXPECT_NEAR(s.pair_shape_factors[0], 2.0, kTight);
  EXPECT_NEAR(s.common_factor, 1.0, kTight);
  EXPECT_NEAR(s.factors[0], 2.0, kTight);
  for (std::size_t p = 0; p < periods.size(); ++p) {
    EXPECT_NEAR(s.scaled_mean[p], sa[p], kTight * sa[p]) << periods[p];
  }
}

TEST(SuiteScaling, MeanOnTheTargetAtTheGoverningPeriodAndAboveElsewhere) {
  const TargetSpectrum target = Eurocode8Spectrum{0.3, GroundType::kC, 1, 1.2, 0.05};
  const std::vector<double> periods = ScalingPeriods(target, 0.3, 3.5, 60);
  const std::vector<double> sa = Targets(target, periods);
  const std::vector<std::vector<double>> rotd100 = {
      PowerLaw(periods, 0.2, -1.3), PowerLaw(periods, 0.05, -0.4), PowerLaw(periods, 0.4, -2.0),
      PowerLaw(periods, 0.1, 0.3)};
  const SuiteScaling s = ScaleSuite(periods, sa, rotd100);
  for (std::size_t i = 0; i < rotd100.size(); ++i) {
    // Step 1 as its definition: the geometric mean of target / RotD100 over the grid.
    double product = 1.0;
    for (std::size_t p = 0; p < periods.size(); ++p) product *= sa[p] / rotd100[i][p];
    EXPECT_NEAR(s.pair_shape_factors[i], std::pow(product, 1.0 / periods.size()),
                1e-12 * s.pair_shape_factors[i]);
    EXPECT_NEAR(s.factors[i], s.common_factor * s.pair_shape_factors[i], kTight * s.factors[i]);
  }
  for (std::size_t p = 0; p < periods.size(); ++p) {
    double mean = 0.0;
    for (std::size_t i = 0; i < rotd100.size(); ++i) mean += s.factors[i] * rotd100[i][p];
    mean /= rotd100.size();
    EXPECT_NEAR(s.scaled_mean[p], mean, kTight * mean);
    EXPECT_GE(s.scaled_mean[p], sa[p] * (1 - kTight)) << periods[p];
    EXPECT_GE(s.scaled_mean[p] / sa[p], s.scaled_mean[s.governing] / sa[s.governing]);
  }
  EXPECT_NEAR(s.scaled_mean[s.governing], sa[s.governing], kTight * sa[s.governing]);
  // A pair's spectrum k times larger gets a shape factor k times smaller and the same scaled
  // spectrum: the factors do not depend on how the records came scaled.
  std::vector<std::vector<double>> tripled = rotd100;
  for (double& a : tripled[1]) a *= 3.0;
  const SuiteScaling t = ScaleSuite(periods, sa, tripled);
  EXPECT_NEAR(t.pair_shape_factors[1], s.pair_shape_factors[1] / 3.0,
              1e-12 * s.pair_shape_factors[1]);
  EXPECT_NEAR(t.common_factor, s.common_factor, 1e-12 * s.common_factor);
  EXPECT_EQ(t.governing, s.governing);
}

TEST(SuiteScaling, AMeanAboveTheTargetIsScaledDown) {
  // Two pairs at 4 and 2 x the 1/T target, 4/T and 2/T: s = 1/4 and 1/2 bring each onto the
  // target, so their mean is on it everywhere and c = 1: both come down.
  const SuiteScaling s =
      ScaleSuite(kPeriods, kTarget, {PowerLaw(kPeriods, 4.0, -1), PowerLaw(kPeriods, 2.0, -1)});
  EXPECT_NEAR(s.factors[0], 0.25, kTight);
  EXPECT_NEAR(s.factors[1], 0.5, kTight);
  EXPECT_NEAR(s.common_factor, 1.0, kTight);
}

TEST(SuiteScaling, RefusesWhatCannotBeScaled) {
  const std::vector<double> good = PowerLaw(kPeriods, 1.0, -1);
  EXPECT_EQ(RefusedKey([&] { ScaleSuite(kPeriods, kTarget, {}); }), "rotd100");
  EXPECT_EQ(RefusedKey([&] { ScaleSuite({}, {}, {{}}); }), "periods");
  EXPECT_EQ(RefusedKey([&] {
              ScaleSuite(kPeriods, std::vector<double>{1.0, 0.5}, {good});
            }),
            "target_sa");
  EXPECT_EQ(RefusedKey([&] { ScaleSuite(kPeriods, kTarget, {good, {1.0, 0.5}}); }), "rotd100[1]");
  EXPECT_EQ(RefusedKey([&] {
              ScaleSuite(kPeriods, kTarget, {good, {1.0, 0.0, 0.2}});
            }),
            "rotd100[1][1]");
  EXPECT_EQ(RefusedKey([&] {
              ScaleSuite(kPeriods, kTarget, {{1.0, 0.5, -0.2}});
            }),
            "rotd100[0][2]");
  EXPECT_EQ(RefusedKey([&] {
              ScaleSuite(kPeriods, std::vector<double>{1.0, NAN, 0.2}, {good});
            }),
            "target_sa[1]");
  EXPECT_EQ(RefusedKey([&] {
              ScaleSuite(std::vector<double>{1.0, 0.0, 4.0}, kTarget, {good});
            }),
            "periods[1]");
}

TEST(SuiteScaling, PeriodsLogSpacedWithTheTargetsCornersInside) {
  // T_L = 3 s is inside [1.5, 4]; T_0 = 0.12 s and T_s = 0.6 s are not.
  const TargetSpectrum target = Asce7Spectrum{1.5, 0.9, 3.0};
  const std::vector<double> periods = ScalingPeriods(target, 1.5, 4.0, 100);
  ASSERT_EQ(periods.size(), 101u);
  EXPECT_EQ(periods.front(), 1.5);
  EXPECT_EQ(periods.back(), 4.0);
  int corners = 0;
  const double step = std::pow(4.0 / 1.5, 1.0 / 99.0);
  for (std::size_t k = 1; k < periods.size(); ++k) {
    ASSERT_GT(periods[k], periods[k - 1]);
    if (periods[k] == 3.0) {
      ++corners;
      // The corner splits one log step in two.
      EXPECT_NEAR(periods[k + 1] / periods[k - 1], step, 1e-12);
    } else if (periods[k - 1] != 3.0) {
      EXPECT_NEAR(periods[k] / periods[k - 1], step, 1e-12) << k;
    }
  }
  EXPECT_EQ(corners, 1);
  // Two points: the ends and the corners between them (Eurocode 8 type 1, ground B: T_B 0.15,
  // T_C 0.5, T_D 2).
  EXPECT_EQ(ScalingPeriods(Eurocode8Spectrum{0.3, GroundType::kB, 1, 1.0, 0.05}, 0.1, 3.0, 2),
            (std::vector<double>{0.1, 0.15, 0.5, 2.0, 3.0}));
  // A corner on an end is not repeated.
  EXPECT_EQ(ScalingPeriods(Eurocode8Spectrum{0.3, GroundType::kB, 1, 1.0, 0.05}, 0.5, 2.0, 2),
            (std::vector<double>{0.5, 2.0}));

  const Eurocode8Spectrum ec8{0.3, GroundType::kB, 1, 1.0, 0.05};
  EXPECT_EQ(RefusedKey([&] { ScalingPeriods(ec8, 2.0, 4.5); }), "hi");
  EXPECT_EQ(RefusedKey([&] { ScalingPeriods(ec8, 0.0, 3.0); }), "lo");
  EXPECT_EQ(RefusedKey([&] { ScalingPeriods(ec8, 3.0, 3.0); }), "hi");
  EXPECT_EQ(RefusedKey([&] { ScalingPeriods(ec8, 1.0, 3.0, 1); }), "count");
  const TabulatedSpectrum table{{0.5, 1.0, 2.0}, {1.0, 0.8, 0.4}, "t.csv"};
  EXPECT_EQ(RefusedKey([&] { ScalingPeriods(table, 0.4, 2.0); }), "lo");
  EXPECT_EQ(RefusedKey([&] { ScalingPeriods(table, 0.5, 2.5); }), "hi");
  EXPECT_EQ(ScalingPeriods(table, 0.5, 2.0, 2), (std::vector<double>{0.5, 1.0, 2.0}));
  EXPECT_EQ(RefusedKey([&] { ScalingPeriods(Asce7Spectrum{}, 1.0, 2.0); }), "sms");
}

// A bundled record in g: the spectra come out in g too (the oscillator is linear).
integrators::SampledHistory Bundled(const std::string& name, double factor = 1.0) {
  const io::Record record =
      io::ReadRecord(std::string(ISOLAB_SOURCE_DIR) + "/ground_motions/" + name);
  EXPECT_EQ(record.units, "g");
  integrators::SampledHistory ground{record.dt, {}};
  for (const double a : record.values) ground.values.push_back(factor * a);
  return ground;
}

std::vector<double> RotD100(const integrators::SampledHistory& h1,
                            const integrators::SampledHistory& h2,
                            const std::vector<double>& periods) {
  const PairSpectrum pair = ComputePairSpectrum(h1, h2, periods, std::vector<double>{0.05});
  std::vector<double> sa;
  for (std::size_t p = 0; p < periods.size(); ++p) {
    sa.push_back(pair.rotd100.at(0, p).pseudo_acceleration);
  }
  return sa;
}

TEST(SuiteScaling, BundledPairsScaledOntoAnAsce7Spectrum) {
  // Isolated, T_M about 2.4 s (upper bound 2 s, lower bound 3.2 s): 0.75 x 2 to 1.25 x 3.2 s.
  const TargetSpectrum target = Asce7Spectrum{1.5, 0.9, 8.0};
  const std::vector<double> periods = ScalingPeriods(target, 1.5, 4.0, 40);
  const std::vector<double> sa = Targets(target, periods);
  const std::vector<std::pair<std::string, std::string>> pairs = {
      {"fwn_firm_seed1.at2", "h2_fwn_firm_seed3.at2"},
      {"fwn_soft_seed2.at2", "v_fwn_firm_seed4.at2"}};
  std::vector<std::vector<double>> rotd100;
  for (const auto& [h1, h2] : pairs) rotd100.push_back(RotD100(Bundled(h1), Bundled(h2), periods));
  const SuiteScaling s = ScaleSuite(periods, sa, rotd100);
  // The records are far below an MCE_R spectrum of S_M1 0.9 g at these periods.
  EXPECT_GT(s.factors[0], 1.0);
  EXPECT_GT(s.factors[1], 1.0);

  // The records themselves times their factors, their RotD100 computed again.
  std::vector<double> mean(periods.size(), 0.0);
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const std::vector<double> scaled = RotD100(Bundled(pairs[i].first, s.factors[i]),
                                               Bundled(pairs[i].second, s.factors[i]), periods);
    for (std::size_t p = 0; p < periods.size(); ++p) mean[p] += scaled[p] / pairs.size();
  }
  for (std::size_t p = 0; p < periods.size(); ++p) {
    EXPECT_GE(mean[p], sa[p] * (1 - 1e-9)) << periods[p];
    EXPECT_NEAR(mean[p], s.scaled_mean[p], 1e-9 * mean[p]);
  }
  EXPECT_NEAR(mean[s.governing], sa[s.governing], 1e-9 * sa[s.governing]);
}

}  // namespace
}  // namespace isolab::spectra
