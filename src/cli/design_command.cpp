#include "design_command.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "common_options.h"
#include "finite_options.h"
#include "heavy_commands.h"
#include "isolab/core/errors.h"
#include "isolab/core/worker_count.h"
#include "isolab/model/design_file.h"
#include "isolab/study/design.h"
#include "isolab/study/design_report.h"
#include "isolab/study/design_workflow.h"
#include "isolab/study/mpi_scheduler.h"
#include "plot_script.h"

namespace isolab::cli {
namespace {

constexpr const char* kDesignPlotScript = "plot_design.py";

}  // namespace

void RegisterDesignCommand(CLI::App& app, DesignOptions& options) {
  CLI::App* command =
      app.add_subcommand(std::string(kDesignCommand.name), std::string(kDesignCommand.help));
  command->add_option("design", options.design, "Design file (YAML)")
      ->required()
      ->check(CLI::ExistingFile);
  AddOutputOption(command, &options.output,
                  "Output folder (default: the design's output.directory, else its name)");
  AddJobsOption(command, &options.jobs);
  AddQuietFlag(command, &options.quiet);
  command->add_flag("!--no-figures", options.figures,
                    "Skip the report's figures (plot_design.py, which needs matplotlib and h5py)");
}

int RunDesignCommand(const DesignOptions& options, std::ostream& out) {
  if (study::LaunchedByMpirun()) {
    throw InputError(
        {"mpirun"},
        "isolab design runs on local worker processes (-j); under mpirun run the suite with "
        "isolab compare");
  }
  CheckedWorkers(options.jobs, "--jobs");
  const model::DesignFile design = model::LoadDesignFile(options.design);
  if (options.figures) CheckPlotScript(kDesignPlotScript);  // before the runs, not after
  const study::DesignFolderOptions folder_options{options.output, "--output", options.jobs,
                                                  options.figures, ISOLAB_VERSION};
  // A figure script that fails rolls the design back, said as the figures' failure.
  struct FiguresFailed : std::runtime_error {
    using std::runtime_error::runtime_error;
  };
  study::DesignRun run;
  try {
    run = study::RunDesignIntoFolder(
        design, folder_options,
        [&](const std::string& line) {
          if (!options.quiet) fmt::print(stderr, "{}\n", line);
        },
        [&](const std::string& folder) {
          if (!options.figures) return;
          try {
            RunPlotScript(kDesignPlotScript, {folder}, options.quiet);
          } catch (const std::runtime_error& error) {
            throw FiguresFailed(error.what());
          }
        });
  } catch (const FiguresFailed& error) {
    fmt::print(stderr, "isolab design: figures: {}\n", error.what());
    return 1;
  }
  const study::DesignOutcome& outcome = run.outcome;
  if (!run.committed) {
    for (const study::JobResult& job : outcome.runs) {
      if (!job.completed) fmt::print(stderr, "isolab design: run failed: {}\n", job.message);
    }
    fmt::print(stderr, "isolab design: {} of {} runs failed; no design values written\n",
               outcome.failed, outcome.runs.size());
    return 1;
  }
  fmt::print(out, "{}", study::DesignSummaryText(design, outcome));
  fmt::print(out, "report: {}\n", (std::filesystem::path(run.folder) / "design.md").string());
  if (!options.quiet) {
    fmt::print(stderr,
               "isolab design: the suite in {:.1f} s, {} runs in {:.1f} s on {}, {:.1f} s in all "
               "before the figures\n",
               outcome.suite_seconds, outcome.runs.size(), outcome.runs_seconds, run.scheduler,
               outcome.wall_seconds);
  }
  return 0;
}

}  // namespace isolab::cli
