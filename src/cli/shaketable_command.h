// `isolab shaketable`: building-level shake-table measurements of an isolated building (floor
// absolute accelerations and displacements, table motion; io/shake_table_file.h) read with the
// building model's floor masses. It writes
//  * the isolator's measured history as cyclic-test data (time, isolator displacement = base slab
//    relative to the table, isolator force = -sum over every level of mass x absolute
//    acceleration), which `isolab fit` and `isolab diagnose` read;
//  * the table acceleration as a record (CSV, m/s^2) that `isolab run --record` reads;
//  * with --predict, the model run under that record and the measured-vs-predicted table (peak
//    isolator displacement, peak base shear, peak roof absolute acceleration, NRMSE of the
//    isolator displacement and roof acceleration histories) and histories for an overlay plot.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "isolab/building/shake_table_measurements.h"

namespace CLI {
class App;
}

namespace isolab::cli {

struct ShakeTableOptions {
  std::string data;   // shake-table CSV
  std::string model;  // building model (shear building with base mass; isolation for --predict)
  building::ShakeTableChannels channels;  // --levels, --displacements, --offsets, prefixes
  std::string isolator;                   // isolator history CSV (cyclic-test format)
  std::string record;                     // table acceleration record CSV
  bool predict = false;
  int samples = 0;               // parameter sets drawn for a band on the prediction; 0: none
  std::optional<unsigned> seed;  // of the drawn sets (default 1); only with samples
  std::string results;     // HDF5 results of the prediction (default <data stem>.predicted.h5)
  std::string comparison;  // CSV of measured and predicted histories
  bool json = false;
  bool quiet = false;
};

void RegisterShakeTableCommand(CLI::App& app, ShakeTableOptions& options);
// Throws InputError for bad data, model or options.
void RunShakeTableCommand(const ShakeTableOptions& options, std::ostream& out);

}  // namespace isolab::cli
