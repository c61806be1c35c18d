// Building-level shake-table measurements in model units (private to the cli): the channels of
// a shake-table file mapped to the levels of a building model, bottom (isolation slab) to roof,
// with the displacement reference and the level order decided from the data when asked.
#pragma once

#include <string>
#include <vector>

#include "isolab/analysis/shake_table_prediction.h"
#include "isolab/model/model_file.h"
#include "shaketable_command.h"

namespace isolab::cli {

using Series = analysis::Signal;

struct Measured : analysis::BuildingMeasurements {
  std::vector<int> channels;   // channel number of each level
  std::string reference_note;  // how the displacement reference was decided
};

// Reads options.data for a building of `levels` levels. Throws InputError.
Measured ReadMeasured(const ShakeTableOptions& options, const UnitSystem& units,
                      std::size_t levels);

}  // namespace isolab::cli
