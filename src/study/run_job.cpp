#include "isolab/study/run_job.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <filesystem>
#include <limits>
#include <optional>
#include <span>

#include "isolab/analysis/problem.h"
#include "isolab/analysis/results_file.h"
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

std::string RecordEntryName(const model::StudyRecord& record, std::size_t component) {
  return record.components.size() > 1 ? fmt::format("{}.h{}", record.entry, component + 1)
                                      : record.entry;
}

JobResult RunJob(const model::StudyFile& study, const Job& job, const std::string& output_directory,
                 const std::string& version, const StudyRecords* records) {
  const auto start = std::chrono::steady_clock::now();
  JobResult result;
  result.job = job.index;
  const model::StudyVariant& variant = study.variants[job.variant];
  const model::ModelFile& model = variant.model;
  try {
    const model::StudyRecord& record = study.records[job.record];
    analysis::RunOverrides overrides;
    for (std::size_t c = 0; c < record.components.size(); ++c) {
      const model::GroundMotionSection& component = record.components[c];
      const std::string entry = RecordEntryName(record, c);
      analysis::RecordOverride given;
      given.name = entry;
      given.file = component.file;
      given.units = component.units;
      if (component.dt > 0.0) given.dt = InModelTime(study, model.units, component.dt);
      if (records != nullptr) {
        const double dt_seconds = given.dt * model.units.SiFactor(dimension::kTime);
        if (const io::Record* read = records->Find(job.record, c, dt_seconds)) given.data = *read;
      }
      given.scale = component.scale * study.scales[job.scale];
      given.target = component.target;
      given.units_given_by = entry + ".units";
      given.dt_given_by = entry + ".dt";
      overrides.records.push_back(std::move(given));
    }
    overrides.angle = record.angle;
    overrides.fixed_base = variant.fixed_base;
    overrides.free_vibration = StudyFreeVibration(study, model.units);
    overrides.names.free_vibration = study.free_vibration_given_by;
    overrides.names.max_steps.clear();  // a study has no option that raises the limit
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
    options.version = version;
    options.output.summary_only = study.runs == model::RunFiles::kSummary;
    // The run goes to memory, its file is written from there once the run is over: no HDF5
    // call during the run.
    std::optional<analysis::HeldResultsFile> held;
    std::vector<integrators::ResponseObserver*> observers;
    if (study.runs != model::RunFiles::kNone) {
      held.emplace(PrepareRunFile(study, job, output_directory),
                   analysis::RunDescription{&problem, &options.analysis, nullptr, nullptr, version,
                                            options.output});
      if (study.runs == model::RunFiles::kFull) observers.push_back(&*held);
    }
    const analysis::Summary summary = analysis::Solve(options, problem, observers);
    if (held) {
      // The one machine-dependent value of a results file: unknown here, so that a study's files
      // are the same bytes whichever process, rank or machine ran them.
      integrators::RunSummary run = summary.run;
      run.wall_seconds = std::numeric_limits<double>::quiet_NaN();
      const auto writing = std::chrono::steady_clock::now();
      held->Write({&problem, &options.analysis, &run, &summary.peaks, version, options.output});
      result.output_seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - writing).count();
      result.file = RunFileName(study, job);
    }
    result.warnings = summary.warnings;
    if (summary.ok()) {
      result.completed = true;
      result.values = MeasureQuantities(problem, summary.peaks, model.units, study.units);
      result.parts = MeasurePartPeaks(problem, summary.peaks, model.units, study.units);
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

ScheduleOutcome RunStudy(const model::StudyFile& study, const std::vector<Job>& jobs,
                         const std::string& output_directory, const std::string& version,
                         Scheduler& scheduler, const ProgressFunction& progress) {
  const StudyRecords records(study);
  return scheduler.Run(
      jobs.size(),
      [&](std::size_t job) {
        return RunJob(study, jobs[job], output_directory, version, &records);
      },
      progress);
}

}  // namespace isolab::study
