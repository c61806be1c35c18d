#include "isolab/study/run_job.h"

#include <chrono>
#include <exception>
#include <filesystem>

#include "isolab/io/analysis_setup.h"
#include "isolab/io/results_file.h"
#include "isolab/io/run_analysis.h"

namespace isolab::study {

JobResult RunJob(const io::StudyFile& study, const Job& job, const std::string& output_directory,
                 const std::string& version) {
  const auto start = std::chrono::steady_clock::now();
  JobResult result;
  result.job = job.index;
  const io::StudyVariant& variant = study.variants[job.variant];
  const io::ModelFile& model = variant.model;
  try {
    const io::StudyRecord& record = study.records[job.record];
    io::RunOverrides overrides;
    overrides.record = record.path;
    overrides.record_units = record.units;
    if (record.dt > 0.0) {
      // The study gives dt in its building's time unit; a `model` variant may use another.
      overrides.record_dt = model.units.Convert(
          record.dt * study.units.SiFactor(io::dimension::kTime), "s", io::dimension::kTime);
    }
    overrides.units_given_by = record.entry + ".units";
    overrides.dt_given_by = record.entry + ".dt";
    overrides.scale = record.scale * study.scales[job.scale];
    overrides.fixed_base = variant.fixed_base;
    if (study.free_vibration) {
      io::FreeVibration free = *study.free_vibration;  // in the study's time unit
      free.duration = model.units.Convert(
          free.duration * study.units.SiFactor(io::dimension::kTime), "s", io::dimension::kTime);
      overrides.free_vibration = free;
    }
    const io::AnalysisSetup setup = io::PrepareAnalysis(model, overrides);
    result.record_units = setup.record.units;
    result.pga = setup.record.pga / model.units.Convert(1.0, "g", io::dimension::kAcceleration);
    integrators::ResponseHistory response;
    const integrators::RunSummary summary = io::RunAnalysis(model.analysis, setup, &response);
    const std::string name = RunFileName(study, job);
    const std::filesystem::path file = std::filesystem::path(output_directory) / name;
    std::error_code ignored;  // a folder that cannot be made shows as the file's write error
    std::filesystem::create_directories(file.parent_path(), ignored);
    const io::ResponsePeaks peaks = io::ComputePeaks(setup, response);
    const io::RunDescription run{&model, &setup, &model.analysis, &summary, &peaks, version, {}};
    io::WriteResultsFile(file.string(), run, response);
    result.file = name;
    result.warnings = io::RunWarnings(run);
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
