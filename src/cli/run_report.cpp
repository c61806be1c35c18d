#include "run_report.h"

#include <fmt/format.h>

#include <cstdio>
#include <filesystem>

namespace isolab::cli {

std::string ChooseResultsPath(const RunOptions& options, const std::string& model_output_file) {
  if (!options.output.empty()) return options.output;
  if (!model_output_file.empty()) return model_output_file;
  return std::filesystem::path(options.model).stem().string() + ".h5";
}

int ExitCode(const integrators::RunSummary& summary, double dt, const std::string& output) {
  if (summary.ok()) return 0;
  fmt::print(stderr, "isolab: the run stopped early: {}; results up to t = {:g} are in {}\n",
             summary.message, summary.steps * dt, output);
  return 1;
}

}  // namespace isolab::cli
