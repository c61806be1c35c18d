// The one way a prepared problem (problem.h) is run, in the manner of Ceres'
// Solve(options, problem, &summary): the command line, the Python module, studies and the
// shake-table prediction all call Solve, and render its Summary (run_report.h, run_text.h).
//
// A run integrates with the integrator the options name, tracks the peaks, the residual
// displacement and the energies at every step, and, with a results path, streams the histories
// the output selection records to that file (results_writer.h; bounded memory, the file appears
// whole at the end, also for a run that stopped early).
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "isolab/analysis/problem.h"
#include "isolab/analysis/response_peaks.h"
#include "isolab/integrators/response.h"
#include "isolab/model/model_file.h"
#include "isolab/model/output_selection.h"

namespace isolab::analysis {

// The energy balance error is the largest |input - kinetic - damping - elastic - hysteretic| over
// the largest input energy. Above kEnergyBalanceWarning a run is warned about (a coarse step:
// Chopra's ten-step Case B closes to 1.8e-2); above kMaxEnergyBalanceError it is a failure, since
// no passive structure integrated faithfully loses a twentieth of its input.
inline constexpr double kEnergyBalanceWarning = 1e-2;
inline constexpr double kMaxEnergyBalanceError = 5e-2;

struct SolveOptions {
  model::AnalysisSection analysis;  // the integrator and its options
  model::OutputSelection output;    // what the results file records
  std::string results_path;         // .h5/.hdf5 or .csv; empty: no file
  std::string version;              // isolab's, written into the file
  std::size_t buffer_rows = 0;      // rows the writer buffers; 0: about 1 MiB of them

  // Throws InvalidParameter naming the first of the integrator's options out of range, and
  // InputError naming output.every (>= 1) or an unknown name in output.quantities.
  void Validate() const;
};

struct Summary {
  integrators::RunSummary run;        // termination, message, the integrator's statistics
  ResponsePeaks peaks;                // of every step
  std::vector<std::string> warnings;  // about the model and about the response
  std::string results_path;           // written, or empty

  bool ok() const { return run.ok(); }
};

// Validates the options, runs, writes the results file when asked. `observers` also see every
// row (e.g. an in-memory history for Python). Throws InputError for options that do not apply to
// the problem (an output level it does not have, IDA on a law without a rate form) before the run
// starts, and for a results file that cannot be written after it.
Summary Solve(const SolveOptions& options, const Problem& problem,
              std::span<integrators::ResponseObserver* const> observers = {});

// The integrator a run's caller chose over the model's analysis section: "newmark", "ida" or empty
// (the model's), and IDA's tolerances. A tolerance for a run that integrates with Newmark-beta is
// refused (InputError at `option_prefix` + "rtol" or "atol": "--" on the command line, "" in
// Python) rather than ignored.
struct IntegratorChoice {
  std::string integrator;
  std::optional<double> rtol, atol;
};
model::AnalysisSection ChooseIntegrator(model::AnalysisSection analysis,
                                        const IntegratorChoice& choice,
                                        const std::string& option_prefix);

// e.g. "newmark beta=0.25 gamma=0.5 newton=full ... dt=0.005" or "ida rtol=1e-06 atol=1e-09 ...".
std::string DescribeIntegrator(const model::AnalysisSection& analysis, double dt);

}  // namespace isolab::analysis
