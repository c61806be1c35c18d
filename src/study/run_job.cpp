#include "isolab/study/run_job.h"

#include <chrono>
#include <exception>
#include <filesystem>

#include "isolab/analysis/analysis_setup.h"
#include "isolab/analysis/results_file.h"
#include "isolab/analysis/run_analysis.h"
#include "run_job_parts.h"

namespace isolab::study {

double InModelTime(const model::StudyFile& study, const UnitSystem& model_units, double time) {
  return model_units.Convert(time * study.units.SiFactor(dimension::kTime), "s", dimension::kTime);
}

std::optional<model::FreeVibration> StudyFreeVibration(const model::StudyFile& study,
                                                       const UnitSystem& model_units) {
  if (!study.free_vibration) return std::nullopt;
  model::FreeVibration free = *study.free_vibration;
  free.duration = InModelTime(study, model_units, free.duration);
  return free;
}

std::string PrepareRunFile(const model::StudyFile& study, const Job& job,
                           const std::string& output_directory) {
  const std::filesystem::path file =
      std::filesystem::path(output_directory) / RunFileName(study, job);
  std::error_code ignored;
  std::filesystem::create_directories(file.parent_path(), ignored);
  return file.string();
}

JobResult RunJob(const model::StudyFile& study, const Job& job, const std::string& output_directory,
                 const std::string& version) {
  const auto start = std::chrono::steady_clock::now();
  JobResult result;
  result.job = job.index;
  const model::StudyVariant& variant = study.variants[job.variant];
  const model::ModelFile& model = variant.model;
  try {
    if (study.plan) {
      RunPlanJob(study, job, output_directory, version, &result);
      result.wall_seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      return result;
    }
    const model::StudyRecord& record = study.records[job.record];
    analysis::RunOverrides overrides;
    overrides.record = record.path;
    overrides.record_units = record.units;
    if (record.dt > 0.0) overrides.record_dt = InModelTime(study, model.units, record.dt);
    overrides.units_given_by = record.entry + ".units";
    overrides.dt_given_by = record.entry + ".dt";
    overrides.scale = record.scale * study.scales[job.scale];
    overrides.fixed_base = variant.fixed_base;
    overrides.free_vibration = StudyFreeVibration(study, model.units);
    const analysis::AnalysisSetup setup = analysis::PrepareAnalysis(model, overrides);
    result.record_units = setup.record.units;
    result.pga = setup.record.pga / model.units.Convert(1.0, "g", dimension::kAcceleration);
    integrators::ResponseHistory response;
    const integrators::RunSummary summary = analysis::RunAnalysis(model.analysis, setup, &response);
    const std::string file = PrepareRunFile(study, job, output_directory);
    const analysis::ResponsePeaks peaks = analysis::ComputePeaks(setup, response);
    const analysis::RunDescription run{&model,  &setup, &model.analysis, &summary, &peaks,
                                       version, {}};
    analysis::WriteResultsFile(file, run, response);
    result.file = RunFileName(study, job);
    result.warnings = analysis::RunWarnings(run);
    if (summary.ok()) {
      result.completed = true;
      result.values = MeasureQuantities(setup, response, peaks, model.units, study.units);
    } else {
      result.message = summary.message;
    }
  } catch (const std::exception& error) {
    // Bad records (InputError), unwritable results, anything a run throws: this job's failure.
    result.message = error.what();
  }
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace isolab::study
