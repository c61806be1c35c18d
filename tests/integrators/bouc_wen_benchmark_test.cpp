// The Noel & Schoukens (2016) hysteretic benchmark: m y'' + c y' + k y + z = u(t) with a Bouc-Wen
// z, driven by the official sine-sweep test signal (shared/reference/boucwen). Integrated at
// 15 kHz as the benchmark's data were, force linear between the 750 Hz samples, from rest.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "isolab/hysteresis/law_parameters.h"
#include "isolab/integrators/newmark.h"
#include "isolab/structure/shear_building.h"
#include "reference_data.h"

namespace isolab::integrators {
namespace {

using hysteresis::LawParameters;
using hysteresis::LawType;
using hysteresis::ParameterForm;

TEST(BoucWenBenchmark, SineSweepWithinOnePointFivePercentRms) {
  const auto path = testing::SharedPath("reference/boucwen/val_sinesweep.csv");
  ISOLAB_REQUIRE_SHARED(path);
  const auto rows = testing::ReadNumericCsv(path);
  ASSERT_GT(rows.size(), 100000u);

  const hysteresis::ParallelAssembly restoring({
      {"k", LawParameters::Make(LawType::kLinearSpring, ParameterForm::kMathematical,
                                std::vector<double>{5e4})},
      {"z", LawParameters::Make(LawType::kBoucWen, ParameterForm::kMathematical,
                                std::vector<double>{5e4, 1e3, 0.8, -1.1, 1.0})},
  });
  const auto sdof = structure::BuildSdof(2.0, 10.0, restoring);
  const double record_dt = rows[1][0] - rows[0][0];
  Excitation excitation;
  AppliedForce force{0, {record_dt, {}}};
  for (const auto& row : rows) force.force.values.push_back(row[1]);
  excitation.forces.push_back(force);

  constexpr int kSubsteps = 20;  // 750 Hz -> 15 kHz
  const TimeGrid grid{record_dt / kSubsteps, static_cast<int>(rows.size() - 1) * kSubsteps,
                      kSubsteps};
  ResponseHistory response;
  const RunSummary summary = RunNewmark(sdof, excitation, grid, NewmarkOptions{}, &response);
  ASSERT_TRUE(summary.ok()) << summary.message;
  ASSERT_EQ(response.rows_written, static_cast<int>(rows.size()));

  double error = 0.0, norm = 0.0, error_first = 0.0, norm_first = 0.0;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const double difference = response.displacement(k, 0) - rows[k][2];
    error += difference * difference;
    norm += rows[k][2] * rows[k][2];
    if (k < 30000) {
      error_first += difference * difference;
      norm_first += rows[k][2] * rows[k][2];
    }
  }
  const double rms = std::sqrt(error / norm), rms_first = std::sqrt(error_first / norm_first);
  std::printf(
      "Bouc-Wen sine sweep: relative RMS error %.3f %% (first 30000 samples %.3f %%), %.2f s\n",
      100 * rms, 100 * rms_first, summary.wall_seconds);
  EXPECT_LT(rms, 0.015);
}

}  // namespace
}  // namespace isolab::integrators
