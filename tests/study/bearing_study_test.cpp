// The bundled bearing study (models/studies/five_story_bearings.yaml): every variant under every
// bundled record closes its energy balance with Newmark, and IDA agrees with Newmark on the
// lead-rubber (heated) and friction pendulum variants under the 2 s pulse.
#include <gtest/gtest.h>

#include <cstdio>

#include "isolab/analysis/problem.h"
#include "isolab/analysis/solve.h"
#include "isolab/hysteresis/cyclic_test.h"
#include "isolab/model/study_file.h"

namespace isolab::study {
namespace {

model::StudyFile BearingStudy() {
  return model::LoadStudyFile(ISOLAB_SOURCE_DIR "/models/studies/five_story_bearings.yaml");
}

integrators::ResponseHistory RunVariant(const model::StudyVariant& variant,
                                        const model::StudyRecord& record,
                                        model::AnalysisSection analysis,
                                        integrators::RunSummary* summary, double scale = 0.75) {
  analysis::RunOverrides overrides;
  overrides.records.push_back({.file = record.components[0].file});
  overrides.scale = scale;
  const analysis::Problem problem = analysis::Prepare(variant.model, overrides);
  integrators::ResponseHistory response;
  integrators::HistoryRecorder recorder =
      integrators::RecordHistory(problem.structure, problem.grid, &response);
  integrators::ResponseObserver* const also[] = {&recorder};
  analysis::SolveOptions options;
  options.analysis = analysis;
  *summary = analysis::Solve(options, problem, also).run;
  return response;
}

TEST(BearingStudy, EveryVariantClosesItsEnergyBalanceUnderEveryRecord) {
  const model::StudyFile study = BearingStudy();
  ASSERT_EQ(study.variants.size(), 5u);
  ASSERT_EQ(study.records.size(), 3u);
  for (const model::StudyVariant& variant : study.variants) {
    for (const model::StudyRecord& record : study.records) {
      integrators::RunSummary summary;
      RunVariant(variant, record, variant.model.analysis, &summary);
      ASSERT_TRUE(summary.ok()) << variant.name << " / " << record.name << ": " << summary.message;
      EXPECT_LT(summary.energy_balance_error, 1e-4) << variant.name << " / " << record.name;
    }
  }
}

TEST(BearingStudy, IdaAgreesWithNewmarkOnTheHeatedLeadRubberAndTheFrictionPendulum) {
  const model::StudyFile study = BearingStudy();
  const model::StudyRecord* pulse = nullptr;
  for (const auto& record : study.records) {
    if (record.name == "pulse_tp2") pulse = &record;
  }
  ASSERT_NE(pulse, nullptr);
  for (const model::StudyVariant& variant : study.variants) {
    if (variant.name != "lead_rubber" && variant.name != "friction_pendulum") continue;
    model::AnalysisSection ida = variant.model.analysis;
    ida.integrator = model::AnalysisSection::Integrator::kIda;
    ida.ida.relative_tolerance = 1e-8;
    ida.ida.absolute_tolerance = 1e-8;
    integrators::RunSummary newmark_summary, ida_summary;
    const auto a = RunVariant(variant, *pulse, variant.model.analysis, &newmark_summary);
    const auto b = RunVariant(variant, *pulse, ida, &ida_summary);
    ASSERT_TRUE(ida_summary.ok()) << ida_summary.message;
    const double peak_newmark = a.displacement.col(0).cwiseAbs().maxCoeff();
    const double peak_ida = b.displacement.col(0).cwiseAbs().maxCoeff();
    std::printf(
        "%s under pulse_tp2 x0.75: peak isolator displacement Newmark (dt 0.005 s) %.3f "
        "mm, IDA %.3f mm (%.3f %%); energy balance Newmark %.1e, IDA %.1e\n",
        variant.name.c_str(), peak_newmark, peak_ida, 100 * (peak_newmark / peak_ida - 1),
        newmark_summary.energy_balance_error, ida_summary.energy_balance_error);
    EXPECT_NEAR(peak_newmark / peak_ida, 1.0, 1e-3);  // measured: 1e-5 and 5e-5
    EXPECT_LT(ida_summary.energy_balance_error, 1e-5);
  }
}

// models/studies/bncs_bearings.yaml designs each device for the effective stiffness and the
// energy per cycle of the isolator diagnosed from the BNCS shake-table test, at D = 110 mm and
// T = 2.5 s: the design is right if each variant's steady loop gives them back (the bilinear
// laws' closed forms were solved for them to four digits), and every variant closes its energy
// balance under every record.
TEST(BearingStudy, BncsVariantsMatchTheMeasuredIsolatorAtTheDesignDisplacement) {
  const model::StudyFile study =
      model::LoadStudyFile(ISOLAB_SOURCE_DIR "/models/studies/bncs_bearings.yaml");
  ASSERT_EQ(study.variants.size(), 5u);
  ASSERT_EQ(study.variants[study.reference].name, "measured_diagnosed");
  hysteresis::CyclicProtocol protocol;
  protocol.amplitude = 110.0;
  protocol.period = 2.5;
  protocol.cycles = 3;
  const auto third_cycle = [&](const model::StudyVariant& variant) {
    return hysteresis::RunCyclicTest(variant.model.isolation, protocol).cycles.back();
  };
  const hysteresis::CycleSummary measured = third_cycle(study.variants.front());
  EXPECT_NEAR(measured.peak_force / 110.0, 3.7815, 1e-4);  // K_eff, as the file states
  EXPECT_NEAR(measured.dissipated, 38535.0, 1.0);          // W_d
  for (const model::StudyVariant& variant : study.variants) {
    if (variant.name == "measured_diagnosed" || variant.name == "measured_thm1") continue;
    const hysteresis::CycleSummary designed = third_cycle(variant);
    EXPECT_NEAR(designed.peak_force / measured.peak_force, 1.0, 1e-3) << variant.name;
    EXPECT_NEAR(designed.dissipated / measured.dissipated, 1.0, 2e-3) << variant.name;
    for (const model::StudyRecord& record : study.records) {
      integrators::RunSummary summary;
      RunVariant(variant, record, variant.model.analysis, &summary, study.scales.back());
      ASSERT_TRUE(summary.ok()) << variant.name << " / " << record.name << ": " << summary.message;
      EXPECT_LT(summary.energy_balance_error, 1e-4) << variant.name << " / " << record.name;
    }
  }
}

}  // namespace
}  // namespace isolab::study
