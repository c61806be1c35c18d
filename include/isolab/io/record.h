// Earthquake records in the formats engineers have:
//  * PEER AT2, NGA-West2 and the older PEER header ("NPTS= 3000, DT= .02000 SEC") and the oldest
//    ("3000 0.02 NPTS, DT"); units from the header ("UNITS OF G");
//  * the Peknold-style AT2 ("1559 points at equal spacing of 0.02 sec", "*** Begin data ***");
//  * CSV with a header line: time,value (units in parentheses in the header, "acc (g)") or value;
//  * whitespace columns without a header: time value, or one value per line (needs dt).
// Samples are taken to be at t = 0, dt, 2 dt, ... Every error names the file and line.
//
// Units and step given by the caller (a model, a study, the command line) never silently
// override what the file itself declares: when both exist and disagree, the record is refused
// with both named. They are needed where the file is silent (a header without units, a single
// column without a step).
#pragma once

#include <span>
#include <string>
#include <vector>

namespace isolab {
class UnitSystem;
struct SourceLocation;
}  // namespace isolab

namespace isolab::io {

struct RecordOptions {
  std::string units;  // "g", "m/s^2", "cm/s^2", "in/s^2", ...; empty: from the file's header
  double dt = 0.0;    // sampling step (s), for files that do not give it; 0: not given
  // Who gave units and dt, for messages: "--units", "excitation.ground_motion.units in m.yaml".
  std::string units_given_by = "the units given";
  std::string dt_given_by = "the dt given";
};

struct Record {
  std::string path;
  std::string format;        // "PEER AT2", "Peknold AT2", "CSV", "two-column", "single-column"
  std::string description;   // header text, if any
  std::string units;         // of the values
  std::string units_source;  // "header", or RecordOptions::units_given_by
  double dt = 0.0;           // (s)
  std::vector<double> values;

  // Peak absolute value (in `units`).
  double Peak() const;
};

// A record as an analysis applied it: the file, what it was read as, the scale and the scaled
// record's PGA, for printing and for every results file.
struct AppliedRecord {
  std::string path;          // empty without a ground motion
  std::string format;        // as Record::format
  std::string units;         // of the file's values
  std::string units_source;  // "header", or who gave them
  double dt = 0.0;           // (s) the file's step
  double scale = 1.0;        // the factor applied, given or computed for `scaled_to`
  double pga = 0.0;          // peak |a_g| of the scaled record, in the analysis' acceleration unit
  // The target the factor was computed for ("PGA 0.4 g", "Sa(2.5 s, 5 %) 0.6 g"); empty when
  // the factor was given.
  std::string scaled_to{};
};

// "scale 1.5", or with the target it was computed for: "scale 1.734 to PGA 0.4 g".
std::string DescribeScale(const AppliedRecord& record);

// A record's values times `scale`, converted to the acceleration unit of `units`, and the peak
// |a| of the scaled record in that unit.
struct ScaledRecord {
  std::vector<double> values;
  double pga = 0.0;
};

// Throws InputError for record units `units` cannot convert (at the record's file), and for a
// scale so large that the record overflows, at `scale_given_by` (the option that gave it), as
// RequireFiniteScaledRecord does.
ScaledRecord ScaleRecord(const Record& record, double scale, const UnitSystem& units,
                         const std::string& scale_given_by);

// Throws InputError at `scale_at` where a value of the record at `path` scaled by `scale`
// (`scaled`) is not finite: a scale so large that the record overflows (1e308 g) is bad input,
// not a run or a spectrum of infinities. `key` starts the message where `scale_at` is a model's
// line ("excitation.ground_motion: "), and is empty where it is the option that gave the scale.
void RequireFiniteScaledRecord(std::span<const double> scaled, double scale,
                               const std::string& path, const SourceLocation& scale_at,
                               const std::string& key = {});

// Throws InputError (file:line: what) for unreadable, malformed, empty or non-finite records,
// unknown units, and units or a step that disagree with the file's own.
Record ReadRecord(const std::string& path, const RecordOptions& options = {});

}  // namespace isolab::io
