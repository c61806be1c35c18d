// Earthquake records in the formats engineers have:
//  * PEER AT2, NGA-West2 and the older PEER header ("NPTS= 3000, DT= .02000 SEC") and the oldest
//    ("3000 0.02 NPTS, DT"); units from the header ("UNITS OF G");
//  * the Peknold-style AT2 ("1559 points at equal spacing of 0.02 sec", "*** Begin data ***");
//  * CSV with a header line: time,value (units in parentheses in the header, "acc (g)") or value;
//  * whitespace columns without a header: time value, or one value per line (needs dt).
// Samples are taken to be at t = 0, dt, 2 dt, ... Every error names the file and line.
#pragma once

#include <string>
#include <vector>

namespace isolab::io {

struct RecordOptions {
  std::string units;  // "g", "m/s^2", "cm/s^2", "in/s^2", ...; empty: from the file's header
  double dt = 0.0;    // sampling step for single-column files without a header (time)
};

struct Record {
  std::string path;
  std::string format;       // "PEER AT2", "Peknold AT2", "CSV", "two-column", "single-column"
  std::string description;  // header text, if any
  std::string units;        // of the values
  double dt = 0.0;          // (s)
  std::vector<double> values;
};

// Throws InputError (file:line: what) for unreadable, malformed, empty or non-finite records.
Record ReadRecord(const std::string& path, const RecordOptions& options = {});

}  // namespace isolab::io
