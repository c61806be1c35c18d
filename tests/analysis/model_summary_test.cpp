// The model summary printed before a run: fixed-base periods against Chopra's Case E table and a
// two-story closed form, the isolated period of a bilinear bearing at the trial displacement in
// closed form, and the warnings that catch unit slips.
#include "isolab/analysis/model_summary.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "isolab/model/build_structure.h"
#include "isolab/model/model_file.h"

namespace isolab::analysis {
namespace {

constexpr double kPi = std::numbers::pi;

model::ModelFile Load(const std::string& relative) {
  return model::LoadModelFile(std::string(ISOLAB_SOURCE_DIR) + "/" + relative);
}

// The summary of `model` as a run prepares it (problem.cpp): on its isolators with the fixed-base
// superstructure beside, or on a fixed base.
ModelSummary Summarise(const model::ModelFile& model, bool fixed_base, double pga,
                       double trial_displacement) {
  const structure::LaidOutStructure run = model::BuildStructure(model, fixed_base);
  std::optional<structure::LaidOutStructure> fixed;
  if (!fixed_base && !run.layout.stories.empty()) fixed = model::BuildStructure(model, true);
  return SummariseModel(run.structure, run.layout, fixed ? &*fixed : nullptr, model.units, pga,
                        trial_displacement);
}

bool HasWarning(const ModelSummary& summary, const std::string& text) {
  for (const std::string& warning : summary.warnings) {
    if (warning.find(text) != std::string::npos) return true;
  }
  return false;
}

TEST(ModelSummary, FixedBasePeriodsOfChoprasFiveStoryFrame) {
  // Chopra, Dynamics of Structures, Sec. 12.8: 2.0000, 0.6850, 0.4346, 0.3383, 0.2966 s.
  const ModelSummary summary =
      Summarise(Load("models/chopra/case_e_five_story_frame.yaml"), false, 0.0, 4.0);
  const double book[] = {2.0000, 0.6850, 0.4346, 0.3383, 0.2966};
  ASSERT_EQ(summary.FixedBasePeriods().size(), 5u);
  for (int n = 0; n < 5; ++n) EXPECT_NEAR(summary.FixedBasePeriods()[n], book[n], 5e-4) << n;
  // 100 kip/g a floor (the model gives the mass as 0.258799 kip s^2/in, g = 386.4 in/s^2; the
  // weight uses standard gravity, 386.09 in/s^2).
  EXPECT_NEAR(summary.total_weight, 5 * 0.258799 * 9.80665 / 0.0254, 1e-9);
  EXPECT_FALSE(summary.isolated);
  EXPECT_TRUE(summary.warnings.empty());
}

TEST(ModelSummary, BilinearBearingPeriodAtTheTrialDisplacement) {
  const model::ModelFile model = Load("tests/io/data/summary_bilinear_building.yaml");
  const ModelSummary summary = Summarise(model, false, 0.0, 100.0);
  // Two equal stories, m = 0.1 kN s^2/mm, k = 100 kN/mm: w^2 = (k/m)(3 -+ sqrt 5)/2.
  const double k_over_m = 100.0 / 0.1;
  ASSERT_EQ(summary.FixedBasePeriods().size(), 2u);
  EXPECT_NEAR(summary.FixedBasePeriods()[0],
              2 * kPi / std::sqrt(k_over_m * (3 - std::sqrt(5.0)) / 2), 1e-12);
  EXPECT_NEAR(summary.FixedBasePeriods()[1],
              2 * kPi / std::sqrt(k_over_m * (3 + std::sqrt(5.0)) / 2), 1e-12);
  // 300 t on the bearing: F(D) = Qd + Kd D = 50 + 1 x 100 kN at D = 100 mm on first loading.
  EXPECT_NEAR(summary.total_mass, 0.3, 1e-15);
  EXPECT_NEAR(summary.total_weight, 300 * 9.80665, 1e-9);
  EXPECT_NEAR(summary.secant_stiffness, 1.5, 1e-12);
  EXPECT_NEAR(summary.isolated_period, 2 * kPi * std::sqrt(0.3 / 1.5), 1e-12);
  EXPECT_NEAR(summary.LongestPeriod(), summary.isolated_period, 0.0);
  // Without its isolation the building is not isolated, and its longest period is its own.
  const ModelSummary fixed = Summarise(model, true, 0.0, 100.0);
  EXPECT_FALSE(fixed.isolated);
  EXPECT_NEAR(fixed.total_mass, 0.2, 1e-15);
  EXPECT_EQ(fixed.LongestPeriod(), fixed.FixedBasePeriods()[0]);
}

TEST(ModelSummary, WarnsAboutMassesWithoutUnitsAndAnImplausibleRecord) {
  // mass: 25 in a kN-mm model is 25 kN s^2/mm = 25,000 t a floor: both periods are sqrt(1000)
  // times the real building's (0.40 s fixed base, 2.6 s isolated).
  const model::ModelFile slip = Load("tests/io/data/summary_mass_slip.yaml");
  const double g = 9806.65;  // mm/s^2
  const ModelSummary summary = Summarise(slip, false, 0.2 * g, 100.0);
  EXPECT_NEAR(summary.FixedBasePeriods()[0], 0.4004 * std::sqrt(1000.0), 0.01);
  EXPECT_TRUE(HasWarning(summary, "fixed-base first period")) << summary.warnings.size();
  EXPECT_TRUE(HasWarning(summary, "the period at 100 mm"));
  EXPECT_FALSE(HasWarning(summary, "peak ground acceleration"));
  // The same building with its masses in tonnes: no warning, until the record is 100 times too
  // strong (a gal record read as m/s^2).
  const model::ModelFile building = Load("models/buildings/five_story_table9.yaml");
  EXPECT_TRUE(Summarise(building, false, 0.35 * g, 100.0).warnings.empty());
  const ModelSummary strong = Summarise(building, false, 35.0 * g, 100.0);
  ASSERT_EQ(strong.warnings.size(), 1u);
  EXPECT_NE(strong.warnings[0].find("peak ground acceleration, 35 g, exceeds 3 g"),
            std::string::npos)
      << strong.warnings[0];
}

TEST(ModelSummary, IsolatorDisplacementBeyondAnyBearing) {
  const UnitSystem mm("kN", "mm");
  EXPECT_EQ(IsolatorDisplacementWarning(1499.0, mm), "");
  EXPECT_NE(IsolatorDisplacementWarning(75000.0, mm).find("75000 mm, exceeds 1.5 m"),
            std::string::npos);
  EXPECT_NE(IsolatorDisplacementWarning(2.0, UnitSystem("kN", "m")), "");
}

// The range warning's margin and grades: silent up to 1.1 times the identified peaks (a rerun of
// the fitted motion reaches 1.03 to 1.05), "beyond" to twice them, "far beyond" past that; each
// quantity named only where it passes the margin.
TEST(ModelSummary, IdentifiedRangeWarningHasAMarginAndGrades) {
  const UnitSystem mm("kN", "mm");
  const identification::IdentifiedRange range{100.0, 300.0, 10.0, {"ica50"}};
  EXPECT_EQ(IdentifiedRangeWarning(range, 105.0, 310.0, mm), "");
  EXPECT_EQ(IdentifiedRangeWarning(range, 110.0, 330.0, mm), "");
  const std::string beyond = IdentifiedRangeWarning(range, 150.0, 320.0, mm);
  EXPECT_NE(beyond.find("this run reaches 150 mm (1.50 times): beyond the range the fit saw, the "
                        "model extrapolates"),
            std::string::npos)
      << beyond;
  EXPECT_EQ(beyond.find("mm/s ("), std::string::npos) << beyond;  // the velocity is within
  const std::string far = IdentifiedRangeWarning(range, 150.0, 900.0, mm);
  EXPECT_NE(far.find("150 mm (1.50 times) and 900 mm/s (3.00 times): far beyond the range the "
                     "fit saw (more than 2 times it)"),
            std::string::npos)
      << far;
}

}  // namespace
}  // namespace isolab::analysis
