// isolab.compare: `isolab compare` (a study's isolator variants under its records and scale
// factors) on local threads, with the command line's options as keyword arguments. It writes
// what the command line writes (each run's HDF5 results and summary.csv/summary.h5 in the output
// folder) and returns the summary as columns of numpy arrays, ready for pandas.DataFrame.
#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <filesystem>
#include <optional>

#include "bindings.h"
#include "isolab/core/errors.h"
#include "isolab/core/hardware_threads.h"
#include "isolab/core/worker_count.h"
#include "isolab/model/free_vibration_text.h"
#include "isolab/model/study_file.h"
#include "isolab/study/jobs.h"
#include "isolab/study/output_folder.h"
#include "isolab/study/quantities.h"
#include "isolab/study/run_job.h"
#include "isolab/study/scheduler.h"
#include "isolab/study/summary.h"
#include "isolab/study/summary_file.h"

namespace py = pybind11;

namespace isolab::python {
namespace {

// One numpy column per quantity, `values(i)[q]` for each of `count` rows, under `prefix`+key.
template <typename Values>
void QuantityColumns(py::dict& columns, const study::StudyShape& shape, const std::string& prefix,
                     std::size_t count, Values values) {
  for (const study::Quantity quantity : shape.quantities) {
    const auto q = static_cast<std::size_t>(quantity);
    py::array_t<double> column(static_cast<py::ssize_t>(count));
    auto out = column.mutable_unchecked<1>();
    for (std::size_t i = 0; i < count; ++i) out(i) = values(i)[q];
    columns[py::str(prefix + std::string(study::InfoOf(quantity).key))] = column;
  }
}

// A row per run in job order: variant, record, scale, completed, message, file, record_units,
// pga, then each quantity (the study's units) and its ratio to the reference ("ratio <key>"),
// as the CSV summary's run rows have them.
py::dict RunColumns(const study::Summary& summary) {
  const std::size_t n = summary.runs.size();
  py::list variant, record, message, file, units;
  py::array_t<double> scale(static_cast<py::ssize_t>(n)), pga(static_cast<py::ssize_t>(n));
  py::array_t<bool> completed(static_cast<py::ssize_t>(n));
  for (const study::Job& job :
       study::ExpandJobs(summary.shape.variants.size(), summary.shape.records.size(),
                         summary.shape.scales.size())) {
    const study::JobResult& run = summary.runs[job.index];
    variant.append(summary.shape.variants[job.variant]);
    record.append(summary.shape.records[job.record]);
    scale.mutable_at(job.index) = summary.shape.scales[job.scale];
    completed.mutable_at(job.index) = run.completed;
    message.append(run.message);
    file.append(run.file);
    units.append(run.record_units);
    pga.mutable_at(job.index) = run.pga;
  }
  py::dict columns(py::arg("variant") = variant, py::arg("record") = record,
                   py::arg("scale") = scale, py::arg("completed") = completed,
                   py::arg("message") = message, py::arg("file") = file,
                   py::arg("record_units") = units, py::arg("pga") = pga);
  QuantityColumns(columns, summary.shape, "", n,
                  [&](std::size_t i) { return summary.runs[i].values; });
  QuantityColumns(columns, summary.shape, "ratio ", n,
                  [&](std::size_t i) { return summary.ratios[i]; });
  return columns;
}

// A row per variant and scale: the mean and max over the records whose runs completed, and
// their ratios to the reference's.
py::dict StatisticColumns(const study::Summary& summary) {
  const std::size_t scales = summary.shape.scales.size();
  const std::size_t n = summary.statistics.size();
  py::list variant;
  py::array_t<double> scale(static_cast<py::ssize_t>(n));
  py::array_t<std::int64_t> completed(static_cast<py::ssize_t>(n));
  for (std::size_t i = 0; i < n; ++i) {
    variant.append(summary.shape.variants[i / scales]);
    scale.mutable_at(i) = summary.shape.scales[i % scales];
    completed.mutable_at(i) = static_cast<std::int64_t>(summary.statistics[i].completed);
  }
  py::dict columns(py::arg("variant") = variant, py::arg("scale") = scale,
                   py::arg("completed") = completed);
  const auto& s = summary.statistics;
  QuantityColumns(columns, summary.shape, "mean ", n, [&](std::size_t i) { return s[i].mean; });
  QuantityColumns(columns, summary.shape, "max ", n, [&](std::size_t i) { return s[i].max; });
  QuantityColumns(columns, summary.shape, "mean_ratio ", n,
                  [&](std::size_t i) { return s[i].mean_ratio; });
  QuantityColumns(columns, summary.shape, "max_ratio ", n,
                  [&](std::size_t i) { return s[i].max_ratio; });
  return columns;
}

py::dict Compare(const std::string& study_path, const std::string& output, int jobs, bool quiet,
                 const std::optional<std::string>& free_vibration,
                 const std::optional<std::string>& runs) {
  model::StudyFile study = model::LoadStudyFile(study_path);
  if (runs) study.runs = model::ParseRunFiles(*runs, "runs");
  if (free_vibration) {
    model::SetStudyFreeVibration(
        study, model::ParseFreeVibration(*free_vibration, study.units, "free_vibration"),
        "free_vibration");
  }
  const int threads = CheckedWorkers(jobs, "jobs");
  const std::string folder = study::PrepareOutputFolder(output, study_path, study);
  study::WriteCompareManifest(folder, study);
  const std::vector<study::Job> expanded = study::ExpandJobs(study);
  study::ScheduleOutcome outcome;
  {
    // The runs touch no Python object; progress goes to stderr as the command line's does.
    py::gil_scoped_release release;
    const std::unique_ptr<study::Scheduler> scheduler = study::MakeLocalScheduler(threads);
    outcome = study::RunStudy(
        study, expanded, folder, ISOLAB_VERSION, *scheduler,
        [&](const study::JobResult& result, std::size_t done, std::size_t total) {
          if (!quiet) {
            fmt::print(stderr, "{}\n",
                       study::JobProgressLine(study, expanded[result.job], result, done, total));
          }
        });
  }
  const study::Summary summary =
      study::BuildSummary(study::ShapeOf(study), std::move(outcome.results));
  const std::filesystem::path path(folder);
  study::WriteSummaryCsv((path / "summary.csv").string(), summary);
  study::WriteSummaryHdf5((path / "summary.h5").string(), summary, study_path, ISOLAB_VERSION);

  py::dict units;
  for (const study::Quantity q : summary.shape.quantities) {
    units[py::str(std::string(study::InfoOf(q).key))] =
        summary.shape.units[static_cast<std::size_t>(q)];
  }
  py::dict result;
  result["runs"] = RunColumns(summary);
  result["statistics"] = StatisticColumns(summary);
  result["units"] = units;
  result["reference"] = summary.shape.variants[summary.shape.reference];
  result["failed"] = summary.failed();
  result["output"] = folder;
  return result;
}

}  // namespace

void BindCompare(py::module_& module) {
  module.def("_compare", &Compare, py::arg("study"), py::arg("output"), py::arg("jobs"),
             py::arg("quiet"), py::arg("free_vibration"), py::arg("runs"));
}

}  // namespace isolab::python
