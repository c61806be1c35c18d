// `isolab run`: a time-history analysis of a model file's structure under its excitation, for
// every kind of model (an SDOF, a shear building, a building in plan). Before the run it prints
// the record as applied (units, scale, PGA) and the model summary (weight, periods) with warnings
// about implausible values; after it, the peaks, the residual isolator displacement after free
// vibration, the energy balance and integrator statistics (analysis/run_text.h); the response
// goes to HDF5 or CSV as it is computed (results_writer.h), thinned as the model's `output:`
// section and the options --every, --quantities, --levels and --summary-only ask
// (output_selection.h).
#pragma once

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "isolab/analysis/problem.h"

namespace CLI {
class App;
}

namespace isolab::cli {

struct RunOptions {
  std::string model;
  std::string record;     // replaces the model's ground motion (and its units, dt and scale): H1
  std::string record_h2;  // with `record`, its second horizontal component (buildings in plan)
  std::string record_v;   // with `record`, its vertical component (axial_load: {vertical: true})
  std::optional<double> angle;  // with `record`, degrees from x to H1
  std::string units;  // the record's acceleration unit; must agree with its header if it has one
  std::optional<double> record_dt;  // the record's sampling step (s), for a single column
  std::optional<double> scale;
  std::optional<double> dt;                             // analysis step (model time unit)
  std::int64_t max_steps = analysis::kDefaultMaxSteps;  // the most analysis steps
  std::string free_vibration;                           // "auto" or a time (s); empty: the model's
  std::optional<double> trial_displacement;             // (model length) for the isolated period
  std::string output;  // .h5/.hdf5 or .csv; default: the model's output.file or <model stem>.h5
  std::optional<int> every;             // output every N steps, overriding output.every
  std::vector<std::string> quantities;  // overriding output.quantities
  std::vector<std::string> levels;      // "0", "3", "roof", ...; overriding output.levels
  bool summary_only = false;            // overriding output.summary_only (when set)
  bool fixed_base = false;
  std::string integrator;      // "newmark" or "ida"; empty: the model's analysis.integrator
  std::optional<double> rtol;  // IDA relative tolerance, overriding analysis.ida.rtol
  std::optional<double> atol;  // IDA absolute tolerance, overriding analysis.ida.atol
  int samples = 0;             // parameter sets drawn from a fitted model's uncertainty; 0: no band
  std::optional<unsigned> seed;  // of the drawn sets (default 1); only with samples
  bool json = false;
  bool quiet = false;               // -q: no preamble (record, model, grid) before the peaks
  std::optional<std::string> plot;  // --plot[=DIR]: PNGs by plot_result.py (default DIR: beside
                                    // the results file); needs HDF5 results
};

void RegisterRunCommand(CLI::App& app, RunOptions& options);

// Returns the process exit code: 0 when the run completed, 1 when it stopped early (results up
// to that step are written and flagged). Throws InputError for bad input.
int RunRunCommand(const RunOptions& options, std::ostream& out);

}  // namespace isolab::cli
