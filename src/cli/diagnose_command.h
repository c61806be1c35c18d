// `isolab diagnose`: fits a base isolator model to measured cyclic tests, names the physical
// effects it lacks one by one (diagnosis/diagnose.h), and writes a Markdown and a JSON report and
// the final model file.
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
  std::string out;                // report stem: OUT.md, OUT.json, OUT.model.yaml
  unsigned seed = 1;
  std::string specimen;  // "sequential", "independent"; empty: the data's header
  long budget = 12000;   // evaluations per fit
  std::string force_unit = "kN", length_unit = "mm";  // of the data, unless its header says
  bool json = false;
  bool quiet = false;
};

void RegisterDiagnoseCommand(CLI::App& app, DiagnoseOptions& options);
// Throws InputError for bad data or base model.
void RunDiagnoseCommand(const DiagnoseOptions& options, std::ostream& out);

}  // namespace isolab::cli
