// RotD50/RotD100 of a pair (rotd_spectrum.h) against independent values: closed forms where H2
// is a multiple of H1 (RotD100 = sqrt(1 + c^2) D1, RotD50 = D1 times the median of
// |cos a + c sin a| over 0..179 degrees) or zero; and, for the bundled pair of independent
// records, a brute force that rotates the records themselves and runs the single-record
// oscillator at every angle.
#include "isolab/spectra/rotd_spectrum.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "isolab/core/errors.h"
#include "isolab/io/record.h"
#include "isolab/spectra/exact_linear_sdof.h"

namespace isolab::spectra {
namespace {

integrators::SampledHistory Bundled(const std::string& name) {
  const io::Record record =
      io::ReadRecord(std::string(ISOLAB_SOURCE_DIR) + "/ground_motions/" + name);
  integrators::SampledHistory ground{record.dt, {}};
  for (const double a : record.values) ground.values.push_back(a * 9.80665);
  return ground;
}

integrators::SampledHistory Scaled(const integrators::SampledHistory& ground, double c) {
  integrators::SampledHistory scaled{ground.dt, {}};
  for (const double a : ground.values) scaled.values.push_back(c * a);
  return scaled;
}

// a_H1 cos theta + a_H2 sin theta: the pair's component along theta.
integrators::SampledHistory Rotated(const integrators::SampledHistory& h1,
                                    const integrators::SampledHistory& h2, double degrees) {
  const double theta = degrees * std::numbers::pi / 180.0;
  integrators::SampledHistory rotated{h1.dt, {}};
  for (std::size_t k = 0; k < h1.values.size(); ++k) {
    rotated.values.push_back(std::cos(theta) * h1.values[k] + std::sin(theta) * h2.values[k]);
  }
  return rotated;
}

// The median of 180 values: the mean of the 90th and 91st.
double Median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return 0.5 * (values[89] + values[90]);
}

const std::vector<double> kPeriods = {0.1, 0.5, 1.0, 3.0};
const std::vector<double> kDamping = {0.0, 0.05};

TEST(RotDSpectrum, SecondComponentAMultipleOfTheFirstHasClosedForms) {
  const auto h1 = Bundled("fwn_firm_seed1.at2");
  for (const double c : {0.7, -1.3}) {
    const PairSpectrum pair = ComputePairSpectrum(h1, Scaled(h1, c), kPeriods, kDamping);
    std::vector<double> projections;
    for (int a = 0; a < 180; ++a) {
      const double theta = a * std::numbers::pi / 180.0;
      projections.push_back(std::abs(std::cos(theta) + c * std::sin(theta)));
    }
    const double median = Median(projections);
    for (std::size_t k = 0; k < pair.h1.ordinates.size(); ++k) {
      const double d1 = pair.h1.ordinates[k].deformation;
      ASSERT_GT(d1, 0.0);
      EXPECT_NEAR(pair.h2.ordinates[k].deformation, std::abs(c) * d1, 1e-12 * d1);
      EXPECT_NEAR(pair.rotd100.ordinates[k].deformation, std::sqrt(1.0 + c * c) * d1, 1e-12 * d1)
          << c << " " << k;
      EXPECT_NEAR(pair.rotd50.ordinates[k].deformation, median * d1, 1e-12 * d1) << c << " " << k;
      EXPECT_NEAR(pair.geometric_mean.ordinates[k].deformation, std::sqrt(std::abs(c)) * d1,
                  1e-12 * d1);
      // The maximum direction is (1, c): atan(c), in [0, 180).
      double angle = std::atan(c) * 180.0 / std::numbers::pi;
      if (angle < 0.0) angle += 180.0;
      EXPECT_NEAR(pair.rotd100_angle[k], angle, 1e-9);
      // A = w^2 D.
      const double omega = 2.0 * std::numbers::pi / pair.rotd100.periods[k % kPeriods.size()];
      EXPECT_DOUBLE_EQ(pair.rotd100.ordinates[k].pseudo_acceleration,
                       omega * omega * pair.rotd100.ordinates[k].deformation);
    }
  }
}

TEST(RotDSpectrum, ZeroSecondComponentGivesTheFirstsSpectrum) {
  const auto h1 = Bundled("fwn_firm_seed1.at2");
  const PairSpectrum pair = ComputePairSpectrum(h1, Scaled(h1, 0.0), kPeriods, kDamping);
  const ElasticSpectrum alone = ComputeElasticSpectrum(h1, kPeriods, kDamping);
  std::vector<double> cosines;
  for (int a = 0; a < 180; ++a) cosines.push_back(std::abs(std::cos(a * std::numbers::pi / 180)));
  const double median = Median(cosines);
  for (std::size_t k = 0; k < alone.ordinates.size(); ++k) {
    const double d = alone.ordinates[k].deformation;
    // The lockstep walk does each component's arithmetic as the single walk does.
    EXPECT_EQ(pair.h1.ordinates[k].deformation, d);
    EXPECT_EQ(pair.h1.ordinates[k].time_of_peak, alone.ordinates[k].time_of_peak);
    EXPECT_EQ(pair.rotd100.ordinates[k].deformation, d);
    EXPECT_NEAR(pair.rotd50.ordinates[k].deformation, median * d, 1e-12 * d);
    EXPECT_EQ(pair.h2.ordinates[k].deformation, 0.0);
    EXPECT_EQ(pair.geometric_mean.ordinates[k].deformation, 0.0);
  }
}

TEST(RotDSpectrum, IndependentRecordsMatchRotatingTheRecordsThemselves) {
  const auto h1 = Bundled("fwn_firm_seed1.at2");
  const auto h2 = Bundled("h2_fwn_firm_seed3.at2");
  const std::vector<double> periods = {0.3, 1.0, 2.5};
  const double zeta = 0.05;
  const std::vector<double> damping = {zeta};
  const PairSpectrum pair = ComputePairSpectrum(h1, h2, periods, damping);
  const ElasticSpectrum alone1 = ComputeElasticSpectrum(h1, periods, damping);
  const ElasticSpectrum alone2 = ComputeElasticSpectrum(h2, periods, damping);
  for (std::size_t p = 0; p < periods.size(); ++p) {
    std::vector<double> brute;
    for (int a = 0; a < 180; ++a) {
      brute.push_back(ExactPeakDeformation(Rotated(h1, h2, a), periods[p], zeta).value);
    }
    const double rotd50 = pair.rotd50.ordinates[p].deformation;
    const double rotd100 = pair.rotd100.ordinates[p].deformation;
    EXPECT_NEAR(rotd50, Median(brute), 1e-10 * rotd50) << periods[p];
    const double brute_max = *std::max_element(brute.begin(), brute.end());
    EXPECT_GE(rotd100 * (1.0 + 1e-12), brute_max);
    EXPECT_LE(rotd100 * std::cos(0.5 * std::numbers::pi / 180.0), brute_max * (1.0 + 1e-12));
    // The record turned to RotD100's direction peaks at RotD100.
    EXPECT_NEAR(
        ExactPeakDeformation(Rotated(h1, h2, pair.rotd100_angle[p]), periods[p], zeta).value,
        rotd100, 1e-10 * rotd100);
    const double d1 = alone1.ordinates[p].deformation, d2 = alone2.ordinates[p].deformation;
    EXPECT_EQ(pair.h1.ordinates[p].deformation, d1);
    EXPECT_EQ(pair.h2.ordinates[p].deformation, d2);
    EXPECT_GE(rotd100, std::max(d1, d2));
    EXPECT_GT(rotd50, 0.5 * std::min(d1, d2));  // independent noise: a real median
    EXPECT_DOUBLE_EQ(pair.geometric_mean.ordinates[p].deformation, std::sqrt(d1 * d2));
  }
}

TEST(RotDSpectrum, PairsOfDifferentStepsOrLengthsAreRefused) {
  const auto h1 = Bundled("fwn_firm_seed1.at2");
  auto shorter = h1;
  shorter.values.pop_back();
  auto coarser = h1;
  coarser.dt *= 2.0;
  try {
    ComputePairSpectrum(h1, shorter, kPeriods, kDamping);
    FAIL() << "a shorter h2 was accepted";
  } catch (const InvalidParameter& error) {
    EXPECT_EQ(error.violation().key, "h2 samples");
  }
  try {
    ComputePairSpectrum(h1, coarser, kPeriods, kDamping);
    FAIL() << "a coarser h2 was accepted";
  } catch (const InvalidParameter& error) {
    EXPECT_EQ(error.violation().key, "h2 dt");
  }
  auto bad = h1;
  bad.values[7] = std::nan("");
  try {
    ComputePairSpectrum(h1, bad, kPeriods, kDamping);
    FAIL() << "a NaN sample was accepted";
  } catch (const InvalidParameter& error) {
    EXPECT_EQ(error.violation().key, "h2 record sample 7");
  }
}

}  // namespace
}  // namespace isolab::spectra
