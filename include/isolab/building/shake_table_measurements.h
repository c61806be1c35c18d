// Building-level shake-table measurements in model units: the channels of a shake-table file
// (io/shake_table_file.h) mapped to the levels of a building model, bottom (isolation slab) to
// roof, with the accelerometer offsets, the displacement reference and the level order decided
// from the data when asked. `isolab shaketable`, the building fits and diagnoses of the command
// line and of the Python module all read their motions through it.
#pragma once

#include <string>
#include <vector>

#include "isolab/building/shake_table_prediction.h"
#include "isolab/core/units.h"

namespace isolab::building {

// How a file's channels are read (`isolab shaketable`'s options of the same names).
struct ShakeTableChannels {
  // Channel numbers of the levels, bottom (isolation slab) to roof, as "6,5,4,3,2,1"; "auto":
  // ordered by RMS displacement relative to the table, the slab moving least.
  std::string levels = "auto";
  std::string acceleration_prefix = "a", displacement_prefix = "d";
  std::string table_acceleration = "table_acceleration";
  std::string table_displacement = "table_displacement";
  // Floor displacements "relative" to the table, "absolute", or "auto": decided from the data.
  std::string displacements = "auto";
  // Accelerometer offsets: "pre-event" (each channel less its mean before the table moves) or
  // "none" (as recorded).
  std::string offsets = "pre-event";
};

struct LevelMeasurements : BuildingMeasurements {
  std::vector<int> channels;   // channel number of each level
  std::string reference_note;  // how the displacement reference was decided
};

// Reads the shake-table file `path` for a building of `levels` levels. Throws InputError (a bad
// `levels` text is named as the command line's --levels).
LevelMeasurements ReadShakeTableMeasurements(const std::string& path,
                                             const ShakeTableChannels& channels,
                                             const UnitSystem& units, std::size_t levels);

}  // namespace isolab::building
