// A plan study's run: the variant's plan model with the job's record pair in place of its own
// excitation, through the library calls `isolab run` makes on a plan model (plan_analysis.h),
// so the study's numbers are the run command's.
#include <fmt/format.h>

#include <filesystem>

#include "isolab/analysis/model_summary.h"
#include "isolab/analysis/plan_analysis.h"
#include "run_job_parts.h"

namespace isolab::study {
namespace {

// A component as the plan model's reader would hold it: the study's scale applied, the path
// absolute (the model resolves relative ones against its own folder) and dt in its time unit.
model::GroundMotionSection ForModel(model::GroundMotionSection component, double scale,
                                    const model::StudyFile& study, const UnitSystem& model_units) {
  component.file = std::filesystem::absolute(component.file).lexically_normal().string();
  component.scale *= scale;
  if (component.dt > 0.0) component.dt = InModelTime(study, model_units, component.dt);
  return component;
}

std::string PairUnits(const analysis::PlanAnalysisSetup& setup) {
  if (setup.h1.units == setup.h2.units) return setup.h1.units;
  return fmt::format("{} / {}", setup.h1.units, setup.h2.units);
}

}  // namespace

void RunPlanJob(const model::StudyFile& study, const Job& job, const std::string& output_directory,
                const std::string& version, JobResult* result) {
  model::PlanModelFile model = *study.variants[job.variant].plan;
  const model::StudyRecord& record = study.records[job.record];
  const double scale = study.scales[job.scale];
  model::PlanGroundMotion motion = *record.pair;
  motion.h1 = ForModel(motion.h1, scale, study, model.units);
  motion.h2 = ForModel(*motion.h2, scale, study, model.units);
  model.ground_motion = motion;
  // Results files keep the model's YAML as the record of what ran: it says what replaced what.
  model.text += fmt::format(
      "\n# isolab compare, study {}, variant {}: excitation.ground_motion replaced by\n# h1: {} "
      "(scale {:g}), h2: {} (scale {:g}), angle {:g}\n",
      study.path, study.variants[job.variant].name, motion.h1.file, motion.h1.scale,
      motion.h2->file, motion.h2->scale, motion.angle);

  analysis::PlanOverrides overrides;
  overrides.free_vibration = StudyFreeVibration(study, model.units);
  const analysis::PlanAnalysisSetup setup = analysis::PreparePlanAnalysis(model, overrides);
  const double g = model.units.Convert(1.0, "g", dimension::kAcceleration);
  result->record_units = PairUnits(setup);
  result->pga = std::max(setup.h1.pga, setup.h2.pga) / g;
  integrators::ResponseHistory response;
  const integrators::RunSummary summary =
      analysis::RunPlanAnalysis(model.analysis, setup, &response);
  const analysis::PlanPeaks peaks = analysis::ComputePlanPeaks(setup, response);
  analysis::WritePlanResults(PrepareRunFile(study, job, output_directory), model, setup, response,
                             summary, peaks, version);
  result->file = RunFileName(study, job);
  const std::string bearing =
      analysis::IsolatorDisplacementWarning(peaks.largest_resultant.value, model.units);
  if (!bearing.empty()) result->warnings.push_back(bearing);
  if (summary.ok()) {
    result->completed = true;
    result->values = MeasurePlanQuantities(peaks, model.units, study.units);
  } else {
    result->message = summary.message;
  }
}

}  // namespace isolab::study
