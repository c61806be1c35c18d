// `isolab cyclic`: imposes u(t) = u_a sin(2 pi t / T) on the isolation assembly of one or more
// model files and reports, per cycle, the dissipated energy, the peak force and each component's
// slider displacement at +u_a; the loop goes to CSV on request.
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
  std::string test_data;    // the runs as test,time,displacement,force CSV (for isolab fit)
  double noise = 0.0;       // force noise on test_data, relative to each test's RMS force
  unsigned seed = 1;        // of that noise
  bool sequential = false;  // a model's runs on one specimen, in order
  bool json = false;
  bool quiet = false;  // -q: no component table before the cycles
};

void RegisterCyclicCommand(CLI::App& app, CyclicOptions& options);

// Throws InputError for bad files or options.
void RunCyclicCommand(const CyclicOptions& options, std::ostream& out);

}  // namespace isolab::cli
