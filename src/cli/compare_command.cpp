#include "compare_command.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <vector>

#include "common_options.h"
#include "finite_options.h"
#include "heap_thresholds.h"
#include "heavy_commands.h"
#include "isolab/core/errors.h"
#include "isolab/core/hardware_threads.h"
#include "isolab/core/worker_count.h"
#include "isolab/model/free_vibration_text.h"
#include "isolab/model/study_file.h"
#include "isolab/study/jobs.h"
#include "isolab/study/mpi_scheduler.h"
#include "isolab/study/output_folder.h"
#include "isolab/study/run_job.h"
#include "isolab/study/scheduler.h"
#include "isolab/study/summary.h"
#include "isolab/study/summary_file.h"
#include "isolab/study/summary_table.h"
#include "plot_script.h"

namespace isolab::cli {
namespace {

std::string Count(std::size_t n, const char* noun) {
  return fmt::format("{} {}{}", n, noun, n == 1 ? "" : "s");
}

// Summary files (CSV and HDF5) and the table on `out`.
void WriteSummary(const CompareOptions& options, const model::StudyFile& study_file,
                  const std::vector<study::JobResult>& results, const std::string& directory,
                  std::ostream& out) {
  const study::Summary summary = study::BuildSummary(study::ShapeOf(study_file), results);
  const std::filesystem::path folder(directory);
  const std::string csv = (folder / "summary.csv").string();
  const std::string h5 = (folder / "summary.h5").string();
  study::WriteSummaryCsv(csv, summary);
  study::WriteSummaryHdf5(h5, summary, options.study, ISOLAB_VERSION);
  fmt::print(out, "== {} ==\n", options.study);
  if (!study_file.description.empty()) fmt::print(out, "{}\n", study_file.description);
  fmt::print(out, "\n");
  study::PrintSummaryTable(summary, out);
  fmt::print(out, "\nsummary: {}, {}\n", csv, h5);
  if (study_file.runs != model::RunFiles::kNone) {
    fmt::print(out, "runs: {}{}\n", (folder / "runs").string(),
               study_file.runs == model::RunFiles::kSummary ? " (summaries only)" : "");
  }
  if (summary.failed() > 0) {
    fmt::print(out, "{} of {} runs failed (see the summary's status and message)\n",
               summary.failed(), summary.runs.size());
  }
}

int LocalWorkers(const CompareOptions& options) { return ThreadsOrHardware(options.jobs); }

std::unique_ptr<study::Scheduler> MakeScheduler(const CompareOptions& options, bool mpi) {
  if (mpi) {
    if (options.jobs > 0 && !options.quiet && study::LaunchRank() == 0) {
      fmt::print(stderr,
                 "isolab compare: under mpirun each rank runs one job at a time; "
                 "--jobs is ignored\n");
    }
    return study::MakeMpiScheduler();
  }
  return study::MakeLocalScheduler(LocalWorkers(options));
}

}  // namespace

void RegisterCompareCommand(CLI::App& app, CompareOptions& options) {
  CLI::App* command =
      app.add_subcommand(std::string(kCompareCommand.name), std::string(kCompareCommand.help));
  command->add_option("study", options.study, "Study file (YAML)")
      ->required()
      ->check(CLI::ExistingFile);
  AddOutputOption(command, &options.output,
                  "Output folder (default: the study's output.directory, else its name)");
  AddJobsOption(command, &options.jobs, "Worker processes without mpirun");
  AddQuietFlag(command, &options.quiet);
  command->add_flag("--plot", options.plot,
                    "Bar charts of the summary in <output>/plots (plot_study.py)");
  command->add_option("--free-vibration", options.free_vibration,
                      "Free vibration after each record, where the residual displacement is "
                      "read: auto (5 x the longest period; the default), a time in s, or 0");
  command
      ->add_option("--runs", options.runs,
                   "Per-run files: none, summary (peaks and attributes) or full (every "
                   "history; the default unless the study's output.runs says otherwise)")
      ->check(CLI::IsMember({"none", "summary", "full"}));
}

int RunCompareCommand(const CompareOptions& options, std::ostream& out) {
  const bool mpi = study::LaunchedByMpirun();
  if (!mpi) CheckedWorkers(options.jobs, "--jobs");
  model::StudyFile study_file;
  std::string directory;
  try {
    study_file = model::LoadStudyFile(options.study);
    if (!options.free_vibration.empty()) {
      model::SetStudyFreeVibration(
          study_file,
          model::ParseFreeVibration(options.free_vibration, study_file.units, "--free-vibration"),
          "--free-vibration");
    }
    if (!options.runs.empty()) study_file.runs = model::ParseRunFiles(options.runs, "--runs");
    if (options.plot) CheckPlotScript("plot_study.py");  // before the runs, not after
    directory = study::PrepareOutputFolder(options.output, options.study, study_file);
  } catch (const InputError&) {
    // Every rank reads the same input and fails alike; rank 0 alone says why.
    if (mpi && study::LaunchRank() != 0) return 2;
    throw;
  }
  const std::vector<study::Job> jobs = study::ExpandJobs(study_file);
  KeepLargeBuffersInTheHeap();
  std::size_t failed = 0;
  {
    // MPI lives as long as the scheduler: the plot script below runs after MPI_Finalize.
    const std::unique_ptr<study::Scheduler> scheduler = MakeScheduler(options, mpi);
    const bool coordinator = scheduler->IsCoordinator();
    if (coordinator) study::WriteCompareManifest(directory, study_file);
    if (coordinator && !options.quiet) {
      fmt::print(stderr, "isolab compare: {} ({} x {} x {}) on {}\n", Count(jobs.size(), "run"),
                 Count(study_file.variants.size(), "variant"),
                 Count(study_file.records.size(), "record"),
                 Count(study_file.scales.size(), "scale"), scheduler->Describe());
    }
    const study::ProgressFunction progress = [&](const study::JobResult& result, std::size_t done,
                                                 std::size_t total) {
      if (options.quiet) return;
      fmt::print(stderr, "{}\n",
                 study::JobProgressLine(study_file, jobs[result.job], result, done, total));
    };
    const study::ScheduleOutcome outcome =
        study::RunStudy(study_file, jobs, directory, ISOLAB_VERSION, *scheduler, progress);
    failed = outcome.failed;
    // Rank 0 reports failed runs in its summary and exit code. A worker leaving with 1 would
    // make mpirun abort the job while rank 0 may still be plotting.
    if (!coordinator) return 0;

    if (!options.quiet) {
      fmt::print(stderr, "{} runs in {:.2f} s on {}: {:.1f} runs/s; {} failed\n", jobs.size(),
                 outcome.wall_seconds, scheduler->Describe(),
                 outcome.wall_seconds > 0.0
                     ? static_cast<double>(jobs.size()) / outcome.wall_seconds
                     : 0.0,
                 failed);
      // Time the jobs spent waiting on one another bounds what more cores give (Amdahl). Writing
      // their files waits on nothing (each worker process has its own HDF5): it is the output's
      // cost, shown apart.
      double job_seconds = 0.0, output_seconds = 0.0;
      for (const study::JobResult& result : outcome.results) {
        job_seconds += result.wall_seconds;
        output_seconds += result.output_seconds;
      }
      const auto share = [&](double seconds) {
        return job_seconds > 0.0 ? 100.0 * seconds / job_seconds : 0.0;
      };
      if (!mpi) {
        fmt::print(stderr, "waiting on one another: {:.2f} % of the jobs' time\n",
                   share(outcome.waiting_seconds));
      }
      if (study_file.runs != model::RunFiles::kNone) {
        fmt::print(stderr, "per-run files ({}): {:.1f} % of the jobs' time writing them\n",
                   model::RunFilesName(study_file.runs), share(output_seconds));
      }
    }
    for (const study::JobResult& result : outcome.results) {
      for (const std::string& warning : result.warnings) {
        fmt::print(stderr, "isolab compare: warning: {}: {}\n",
                   study::JobLabel(study_file, jobs[result.job]), warning);
      }
    }
    WriteSummary(options, study_file, outcome.results, directory, out);
  }
  if (options.plot) {
    const std::filesystem::path folder(directory);
    try {
      RunPlotScript("plot_study.py",
                    {(folder / "summary.h5").string(), "-o", (folder / "plots").string()},
                    options.quiet);
    } catch (const std::runtime_error& error) {
      fmt::print(stderr, "isolab compare: --plot: {}\n", error.what());
      study::WriteCompareManifest(directory, study_file);
      return 1;
    }
    study::WriteCompareManifest(directory, study_file);  // with the plots
  }
  return failed > 0 ? 1 : 0;
}

}  // namespace isolab::cli
