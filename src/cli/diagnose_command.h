// `isolab diagnose`: fits a base isolator model to measured cyclic tests, names the physical
// effects it lacks one by one (diagnosis/diagnose.h), judges what remains, and writes the report
// (diagnosis/report.h) as Markdown and JSON, the residual as CSV with its plot, and the final
// model file. With --building, the same on a building's shake-table motions
// (building/building_diagnosis.h).
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace isolab::cli {

struct DiagnoseOptions {
  std::vector<std::string> data;  // CSV files of cyclic tests
  std::string base;               // --base: component types, bounds optional (fit specification)
  std::string building;           // --building: a building fit's specification (shake-table data)
  std::string offsets;            // --building: accelerometer offsets; empty: pre-event
  // Report stem: OUT.md, OUT.json, OUT.model.yaml, OUT.residual.csv, OUT.residual.png.
  std::string out;
  unsigned seed = 1;
  std::string specimen;  // "sequential", "independent"; empty: the data's header
  long budget = 12000;   // evaluations per fit
  // Of the data, unless a file's "# units:" line says; a file without one needs both.
  std::string force_unit, length_unit;
  int threads = 0;     // 0: every hardware thread, one per rank under mpirun (speed only)
  bool plot = true;    // the residual plot (needs Python's matplotlib; skipped with a note)
  bool force = false;  // beyond the work limit
  bool json = false;
  bool quiet = false;
};

void RegisterDiagnoseCommand(CLI::App& app, DiagnoseOptions& options);
// Throws InputError for bad data or base model; under mpirun (search_ranks.h) only rank 0 does,
// and the others return exit code 2 without a word. Each fit spreads over the ranks.
int RunDiagnoseCommand(const DiagnoseOptions& options, std::ostream& out);

}  // namespace isolab::cli
