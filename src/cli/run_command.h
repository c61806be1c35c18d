// `isolab run`: a time-history analysis of a model file's structure under its excitation, with a
// summary of peaks, energy balance and integrator statistics, and the full response in HDF5.
#pragma once

#include <optional>
#include <ostream>
#include <string>

namespace CLI {
class App;
}

namespace isolab::cli {

struct RunOptions {
  std::string model;
  std::string record;  // overrides the model's ground motion file
  std::optional<double> scale;
  std::optional<double> dt;
  std::string output;  // HDF5 path; default: the model's output.file or <model stem>.h5
  bool fixed_base = false;
  std::string integrator;        // "newmark" or "ida"; empty: the model's analysis.integrator
  std::optional<double> rtol;    // IDA relative tolerance, overriding analysis.ida.rtol
  std::optional<double> atol;    // IDA absolute tolerance, overriding analysis.ida.atol
  bool json = false;
  std::optional<std::string> plot;  // --plot [DIR]: PNGs by scripts/plot_result.py (default DIR:
                                    // beside the results file)
};

void RegisterRunCommand(CLI::App& app, RunOptions& options);

// Returns the process exit code: 0 when the run completed, 1 when it stopped early (results up
// to that step are written and flagged). Throws InputError for bad input.
int RunRunCommand(const RunOptions& options, std::ostream& out);

}  // namespace isolab::cli
