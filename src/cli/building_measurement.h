// Building-level shake-table measurements in model units (private to the cli): the channels of
// a shake-table file mapped to the levels of a building model, bottom (isolation slab) to roof,
// with the displacement reference and the level order decided from the data when asked, and the
// signal arithmetic the comparison needs.
#pragma once

#include <string>
#include <vector>

#include "isolab/model/model_file.h"
#include "shaketable_command.h"

namespace isolab::cli {

using Series = std::vector<double>;

struct Measured {
  Series time, table_acceleration;
  std::vector<Series> acceleration;  // absolute, per level
  std::vector<Series> displacement;  // relative to the table, per level
  std::vector<int> channels;         // channel number of each level
  std::string reference_note;        // how the displacement reference was decided
};

// Reads options.data for a building of `levels` levels. Throws InputError.
Measured ReadMeasured(const ShakeTableOptions& options, const UnitSystem& units,
                      std::size_t levels);

// Floor masses bottom (isolation slab) to roof. Throws InputError for a model without a shear
// building on a base mass.
std::vector<double> LevelMasses(const model::ModelFile& model);

// Minus the sum over levels of mass x absolute acceleration: the force the isolators carry.
Series BaseShear(const std::vector<Series>& acceleration, const std::vector<double>& masses);

double PeakAbs(const Series& x);

// RMS of the difference over the RMS of the measured history.
double Nrmse(const Series& measured, const Series& predicted);

}  // namespace isolab::cli
