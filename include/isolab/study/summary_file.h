// A study's summary on disk, both written atomically (temporary name, then renamed).
//
// CSV, one row per run in job order, then per variant and scale a "mean" and a "max" row
// (record column), the mean/max rows' status "completed", "partial" (some runs failed: over
// the completed ones) or "failed":
//   variant,record,scale,status,isolator_displacement [mm],...,ratio isolator_displacement,...,
//   message,file,record_units,pga_g,warnings
// (record_units: the units the record was read in; pga_g: the scaled record's PGA in g;
// warnings: implausible values, "; "-separated; all three empty on mean and max rows). The
// quantities are the study's (StudyShape::quantities): a building in plan's have two more.
// Values are written exactly (shortest decimal that reads back as the same double); a missing
// value is an empty field.
//
// HDF5 (V variants, R records, S scales; quantity datasets carry a "units" attribute):
//   /variants (V) /records (R) /record_files (R) /scales (S)     UTF-8 strings, doubles
//   /status (V x R x S)      int64: 0 completed, 1 failed
//   /message /file /record_units /warnings (V x R x S)   strings
//   /pga (V x R x S)         the scaled record's PGA (g)
//   /runs/<quantity> /ratio/<quantity> (V x R x S)
//   /mean/<quantity> /max/<quantity> /mean_ratio/<quantity> /max_ratio/<quantity> (V x S)
//   /completed (V x S)       int64: runs the statistics are over
//   attributes of /: study, reference, isolab_version, units
// Objects carry no timestamps, so equal summaries give identical files.
#pragma once

#include <string>

#include "isolab/study/summary.h"

namespace isolab::study {

// Throw InputError when the file cannot be written.
void WriteSummaryCsv(const std::string& path, const Summary& summary);
void WriteSummaryHdf5(const std::string& path, const Summary& summary, const std::string& study,
                      const std::string& version);

}  // namespace isolab::study
