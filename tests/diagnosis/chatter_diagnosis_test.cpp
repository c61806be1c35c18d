// The friction damper of friction_damper_case.h (backlash and asymmetric friction), chattering
// while it slides and at rest for a quarter of a second before each test, diagnosed from the
// same tests at 1024 Hz and decimated to 128 Hz. At 1024 Hz the samples at rest read the load
// cell alone, at 128 Hz there are too few of them: a floor read at rest at one rate and above the
// response at the other made the two diagnoses differ (on a real damper, backlash named at one
// rate and refused at the other). With both reads taken and the larger used where they disagree,
// the two rates must name the same effects, in the same order, from floors within a factor two,
// and the report at 1024 Hz must say in its first lines that the floor is uncertain.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "diagnosis/friction_damper_case.h"
#include "isolab/diagnosis/diagnose.h"
#include "isolab/diagnosis/report.h"

namespace isolab::diagnosis {
namespace {

struct Diagnosed {
  Diagnosis diagnosis;
  nlohmann::json report;  // RenderJson's
};

Diagnosed DiagnoseAt(const std::vector<identification::CyclicTestData>& tests, const char* rate) {
  DiagnoseOptions options;
  options.seed = 7;
  options.budget = 4000;
  const identification::FitData data = AllCycles(tests);
  const Diagnosis d = Diagnose({{"base", hysteresis::LawType::kBhm2, {}, {}, {}}}, data, options);
  std::printf("%s: base e^2 %.4g %%, floor %.4g %%, final %.4g %%, %.1f s; %s\n  %s\n", rate,
              100 * d.base.fit.error.total, 100 * d.noise_floor,
              100 * d.final_model.fit.error.total, d.seconds, d.stop_reason.c_str(),
              d.verdict.headline.c_str());
  for (const DiagnosisStep& step : d.steps) {
    std::printf("  step: %s, e^2 %.4g %% -> %.4g %%\n",
                std::string(EffectName(step.effect)).c_str(), 100 * step.e2_before,
                100 * step.e2_after);
  }
  return {d, nlohmann::json::parse(RenderJson(BuildReport(d, data, {})))};
}

// The head's lines that say the floor is uncertain.
int UncertainNotes(const nlohmann::json& report) {
  int notes = 0;
  for (const auto& line : report["head"]) {
    notes += line.get<std::string>().starts_with("Note: the noise floor is uncertain: for ");
  }
  return notes;
}

TEST(ChatterDiagnosis, TheSameEffectsAt1024And128Hz) {
  testing::DamperNoise noise;
  noise.rest_seconds = 0.25;
  noise.chatter = 0.1;  // kip, five times the load cell's noise
  const auto all = testing::FrictionDamperTests(1024.0, noise, 3);
  std::vector<identification::CyclicTestData> high;
  for (std::size_t k = 0; k < all.size(); k += 2) high.push_back(all[k]);
  const auto [d1024, report_1024] = DiagnoseAt(high, "1024 Hz");
  const auto [d128, report_128] = DiagnoseAt(testing::Decimate(high, 8), "128 Hz");
  ASSERT_EQ(d1024.steps.size(), d128.steps.size());
  for (std::size_t k = 0; k < d128.steps.size(); ++k)
    EXPECT_EQ(d1024.steps[k].effect, d128.steps[k].effect) << "step " << k + 1;
  EXPECT_LT(
      std::max(d1024.noise_floor, d128.noise_floor) / std::min(d1024.noise_floor, d128.noise_floor),
      2.0);
  EXPECT_EQ(UncertainNotes(report_1024), 1) << report_1024["head"].dump(1);
  EXPECT_EQ(UncertainNotes(report_128), 0) << report_128["head"].dump(1);
  // Each test's sigma by the rule: the rest read where the two agree, the larger where not. (A
  // short fast test can read the chatter hardly at all: its band starts at 25 Hz, its quarter
  // octaves are at least 128 bins wide, and their low quantile passes over chatter below 40 Hz.)
  for (const auto& noise : report_1024["noise"]) {
    std::printf("  1024 Hz: %s\n", noise["source"].get<std::string>().c_str());
    const double rest = noise["rest_sigma"], band = noise["band_sigma"];
    EXPECT_EQ(noise["uncertain"].get<bool>(), std::max(rest, band) > 2 * std::min(rest, band));
    EXPECT_EQ(noise["sigma"].get<double>(), noise["uncertain"] ? std::max(rest, band) : rest);
  }
  for (const auto& noise : report_128["noise"]) {
    EXPECT_FALSE(noise["uncertain"].get<bool>());
    EXPECT_FALSE(noise.contains("rest_sigma"));
  }
}

}  // namespace
}  // namespace isolab::diagnosis
