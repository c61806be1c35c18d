// `isolab cyclic`: imposes u(t) = u_a sin(2 pi t / T) on the isolation assembly of one or more
// model files and reports, per cycle, the dissipated energy, the peak force and each component's
// slider displacement at +u_a; the loop goes to CSV on request. With --path or --orbit it drives
// the model along a given path instead (cyclic/path_replay.h): a measured test's displacement
// history in one direction or two (against its measured force when the file has one), or a circle
// or figure-eight in plan, through a one-direction model's laws in their coupled forms or a plan
// model's isolators.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace isolab::cli {

struct CyclicOptions {
  std::vector<std::string> models;
  std::vector<double> amplitudes;      // overrides the files' cyclic.amplitude; one run each
  std::vector<double> periods;         // override cyclic.period; one run each
  std::optional<int> cycles;           // overrides cyclic.cycles
  std::optional<int> steps_per_cycle;  // overrides cyclic.steps_per_cycle
  std::string csv;                     // loop output; one file per run, suffixed when several
  std::string test_data;           // the runs as test,time,displacement,force CSV (for isolab fit)
  double noise = 0.0;              // force noise on test_data, relative to each test's RMS force
  std::optional<unsigned> seed;    // of that noise (default 1)
  bool sequential = false;         // a model's runs on one specimen, in order
  std::vector<std::string> paths;  // --path: displacement paths (CSV) to drive the model along
  std::string orbit;               // --orbit: "circle" or "figure8"
  std::string isolator;            // --isolator: one isolator of a plan model (default: all)
  bool uncoupled = false;          // a one-direction model's laws in two directions, uncoupled
  std::string force_unit, length_unit;  // of path files without a "# units:" line
  bool json = false;
  bool quiet = false;  // -q: no component table before the cycles
};

void RegisterCyclicCommand(CLI::App& app, CyclicOptions& options);

// Throws InputError for bad files or options.
void RunCyclicCommand(const CyclicOptions& options, std::ostream& out);

}  // namespace isolab::cli
