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

namespace CLI {
class App;
}

namespace isolab::cli {

struct ShakeTableOptions {
  std::string data;   // shake-table CSV
  std::string model;  // building model (shear building with base mass; isolation for --predict)
  // Channel numbers of the levels, bottom (isolation slab) to roof, as "6,5,4,3,2,1"; "auto":
  // ordered by RMS displacement relative to the table, the slab moving least.
  std::string levels = "auto";
  std::string acceleration_prefix = "a", displacement_prefix = "d";
  std::string table_acceleration = "table_acceleration";
  std::string table_displacement = "table_displacement";
  // Floor displacements "relative" to the table, "absolute", or "auto": decided from the data.
  std::string displacements = "auto";
  std::string offsets = "pre-event";  // accelerometer offsets: "pre-event" or "none"
  std::string isolator;               // isolator history CSV (cyclic-test format)
  std::string record;                 // table acceleration record CSV
  bool predict = false;
  int samples = 0;  // parameter sets drawn for a band on the prediction; 0: none
  unsigned seed = 1;
  std::string results;     // HDF5 results of the prediction (default <data stem>.predicted.h5)
  std::string comparison;  // CSV of measured and predicted histories
  bool json = false;
  bool quiet = false;
};

void RegisterShakeTableCommand(CLI::App& app, ShakeTableOptions& options);
// Throws InputError for bad data, model or options.
void RunShakeTableCommand(const ShakeTableOptions& options, std::ostream& out);

}  // namespace isolab::cli
