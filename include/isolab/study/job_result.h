// What one run of a study reports back: its status and the quantities measured. An MPI worker
// sends it to rank 0 as bytes (Serialize), doubles bit for bit, so the summary is the same
// whichever process ran the job.
#pragma once

#include <cstddef>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "isolab/study/quantities.h"

namespace isolab::study {

struct JobResult {
  std::size_t job = 0;
  bool completed = false;
  std::string message;                 // why the run failed; empty when it completed
  QuantityValues values = NoValues();  // NaN when failed or not applicable
  std::string file;  // the run's HDF5 results, relative to the output folder; empty: none written
  std::string record_units;  // the record's units as read ("g", "cm/s^2"); empty: not read
  double pga = std::numeric_limits<double>::quiet_NaN();  // of the scaled record (g)
  std::vector<std::string> warnings;                      // implausible values (model_summary.h)
  std::vector<PartPeak> parts;  // the peaks of its stories, floors and bearings (quantities.h)
  double wall_seconds = 0.0;    // for progress only: never in a summary (machine-dependent)
  // Of wall_seconds, the time spent writing the run's file. Like wall_seconds, never in a
  // summary.
  double output_seconds = 0.0;
};

std::vector<char> Serialize(const JobResult& result);
// Throws std::runtime_error for a buffer that Serialize did not write.
JobResult Deserialize(std::span<const char> bytes);

}  // namespace isolab::study
