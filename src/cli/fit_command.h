// `isolab fit`: identifies an assembly's parameters from measured cyclic tests with CMA-ES
// (identification/fit.h) and writes the fitted model file, with e^2 per test and their mean (and
// the paper's sum), why the search stopped, what the data do not identify, and a table of energy
// per cycle against amplitude, measured and fitted.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace isolab::cli {

struct FitOptions {
  std::vector<std::string> data;  // CSV files of cyclic tests
  std::string spec;               // --model: component types and counts (YAML)
  std::string building;           // --building: a building fit's specification (YAML)
  std::string offsets;            // --building: accelerometer offsets; empty: pre-event
  unsigned seed = 1;
  long budget = 60000;
  long global_budget = -1;      // --building: the CMA-ES stage's simulations; -1: the default
  bool cross_validate = false;  // --building: each motion predicted by a fit of the others
  bool model_form = false;      // --building: the fit, and the others' fits as its model form
  std::vector<int> cycles;      // 1-based; empty: SelectCycles' default
  std::string specimen;         // "sequential", "independent"; empty: the data's header
  std::string output;           // fitted model file; default: <spec stem>.fitted.yaml
  // Of the data, unless a file's "# units:" line says; a file without one needs both.
  std::string force_unit, length_unit;
  int threads = 0;     // 0: every hardware thread, one per rank under mpirun (speed only)
  bool force = false;  // fit beyond the work limit (cyclic/test_data_checks.h)
  bool json = false;
  bool quiet = false;
};

void RegisterFitCommand(CLI::App& app, FitOptions& options);
// Throws InputError for bad data or specification; under mpirun (search_ranks.h) only rank 0
// does, and the others return exit code 2 without a word.
int RunFitCommand(const FitOptions& options, std::ostream& out);

}  // namespace isolab::cli
