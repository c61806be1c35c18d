// The verdict on a residual (residual.h) on residuals of known make, the model being the truth
// itself: white noise is noise; a force offset by direction of motion (a friction the model
// lacks, +-3 x the noise) is structured and located by direction; a hum at 7.3 Hz that the
// motion does not drive, as large, is a residual the state does not explain.
#include "isolab/diagnosis/residual.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "diagnosis/hidden_effect_cases.h"

namespace isolab::diagnosis {
namespace {

const hysteresis::ParallelAssembly kTruth =
    hysteresis::SingleLaw(hysteresis::LawType::kBhm2, {1.5, 0.25, 8});

ResidualVerdict Judge(const identification::FitData& data) {
  const Discrepancy d = Discrepancy::Of(kTruth, data);
  return JudgeResidual(d, identification::ComputeFitError(kTruth, data).total,
                       NoiseFloor(data, d.force_noise));
}

identification::FitData NoisyData() {
  return AllCycles(identification::SyntheticTests(kTruth, DiagnosisProtocol(41)));
}

// Each test's noise deviation: 1 % of its RMS force.
double Noise(const identification::CyclicTestData& test) {
  double square = 0.0;
  for (const double f : test.force) square += f * f;
  return 0.01 * std::sqrt(square / test.force.size());
}

TEST(ResidualVerdict, WhiteNoiseIsNoise) {
  const ResidualVerdict v = Judge(NoisyData());
  EXPECT_EQ(v.kind, ResidualVerdict::Kind::kNoise) << v.headline;
  EXPECT_NEAR(v.ratio, 1.0, 0.2);
  EXPECT_NEAR(v.whiteness, 1.0, 0.1);
  EXPECT_LT(v.state_share, 0.02);
  EXPECT_TRUE(v.where.empty());
}

TEST(ResidualVerdict, AnOffsetByDirectionIsStructuredAndLocatedByDirection) {
  auto data = NoisyData();
  for (auto& test : data.tests) {
    const double c = 3 * Noise(test);
    for (std::size_t k = 1; k < test.force.size(); ++k) {
      test.force[k] += test.displacement[k] > test.displacement[k - 1] ? c : -c;
    }
  }
  const ResidualVerdict v = Judge(data);
  EXPECT_EQ(v.kind, ResidualVerdict::Kind::kStructured) << v.headline;
  // Nine parts of ten of the residual are the offset: (3^2) / (3^2 + 1).
  EXPECT_NEAR(v.state_share, 0.9, 0.05);
  ASSERT_FALSE(v.where.empty());
  EXPECT_NE(v.where[0].find("moving"), std::string::npos) << v.where[0];
  EXPECT_NE(v.where[0].find("mean residual"), std::string::npos) << v.where[0];
  // The direction table's cells carry the sign: +3 moving up, -3 moving down, in noise units.
  const ResidualTable& table = v.tables[0];
  EXPECT_NEAR(table.mean[0][1], 3.0, 0.3);
  EXPECT_NEAR(table.mean[1][1], -3.0, 0.3);
}

TEST(ResidualVerdict, AHumTheMotionDoesNotDriveIsNotReadAsState) {
  auto data = NoisyData();
  for (auto& test : data.tests) {
    const double a = 3 * std::sqrt(2.0) * Noise(test);  // RMS 3 x the noise
    for (std::size_t k = 0; k < test.force.size(); ++k) {
      test.force[k] += a * std::sin(2 * std::numbers::pi * 7.3 * test.time[k] + 0.4);
    }
  }
  const ResidualVerdict v = Judge(data);
  EXPECT_EQ(v.kind, ResidualVerdict::Kind::kUnexplained) << v.headline;
  EXPECT_GT(v.ratio, 5.0);
  EXPECT_LT(v.state_share, 0.1);
}

}  // namespace
}  // namespace isolab::diagnosis
