#include "isolab/study/run_job.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <filesystem>

#include "isolab/analysis/problem.h"
#include "isolab/analysis/solve.h"
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
    const model::StudyRecord& record = study.records[job.record];
    analysis::RunOverrides overrides;
    const bool pair = record.components.size() > 1;
    for (std::size_t c = 0; c < record.components.size(); ++c) {
      const model::GroundMotionSection& component = record.components[c];
      const std::string entry = pair ? fmt::format("{}.h{}", record.entry, c + 1) : record.entry;
      analysis::RecordOverride given;
      given.name = entry;
      given.file = component.file;
      given.units = component.units;
      if (component.dt > 0.0) given.dt = InModelTime(study, model.units, component.dt);
      given.scale = component.scale * study.scales[job.scale];
      given.units_given_by = entry + ".units";
      given.dt_given_by = entry + ".dt";
      overrides.records.push_back(std::move(given));
    }
    overrides.angle = record.angle;
    overrides.fixed_base = variant.fixed_base;
    overrides.free_vibration = StudyFreeVibration(study, model.units);
    const analysis::Problem problem = analysis::Prepare(model, overrides);
    const double g = model.units.Convert(1.0, "g", dimension::kAcceleration);
    double pga = 0.0;
    for (const io::AppliedRecord& applied : problem.records) {
      if (!result.record_units.empty() && result.record_units != applied.units) {
        result.record_units += " / " + applied.units;
      } else if (result.record_units.empty()) {
        result.record_units = applied.units;
      }
      pga = std::max(pga, applied.pga);
    }
    result.pga = pga / g;
    analysis::SolveOptions options;
    options.analysis = model.analysis;
    options.results_path = PrepareRunFile(study, job, output_directory);
    options.version = version;
    const analysis::Summary summary = analysis::Solve(options, problem);
    result.file = RunFileName(study, job);
    result.warnings = summary.warnings;
    if (summary.ok()) {
      result.completed = true;
      result.values = MeasureQuantities(problem, summary.peaks, model.units, study.units);
    } else {
      result.message = summary.run.message;
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
