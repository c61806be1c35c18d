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
    const io::AnalysisSetup setup = io::PrepareAnalysis(
        model, {study.records[job.record].path, study.scales[job.scale], {}, variant.fixed_base});
    integrators::ResponseHistory response;
    const integrators::RunSummary summary = io::RunAnalysis(model.analysis, setup, &response);
    const std::string name = RunFileName(study, job);
    const std::filesystem::path file = std::filesystem::path(output_directory) / name;
    std::error_code ignored;  // a folder that cannot be made shows as the file's write error
    std::filesystem::create_directories(file.parent_path(), ignored);
    io::WriteResultsFile(file.string(),
                         {&model, &setup, &model.analysis, &response, &summary, version});
    result.file = name;
    if (summary.ok()) {
      result.completed = true;
      result.values = MeasureQuantities(setup, response, model.units, study.units);
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
