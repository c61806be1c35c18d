// The record as applied, as attributes of an HDF5 file's root: the same names in run results and
// spectra (docs/results.md).
#pragma once

#include <string>

#include "isolab/io/hdf5_file.h"
#include "isolab/io/record.h"

namespace isolab::io {

// record, record_format, record_units, record_units_source, record_dt (s), record_scale,
// record_pga (the file's acceleration unit), record_pga_g; `gravity`: 1 g in that unit. `name`
// replaces "record" (a pair's second component: "record_h2").
void WriteRecordAttributes(Hdf5File& file, const AppliedRecord& record, double gravity,
                           const std::string& name = "record");

}  // namespace isolab::io
