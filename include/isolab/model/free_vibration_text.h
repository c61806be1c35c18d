// The free vibration after a record as a user types it (`--free-vibration` of `isolab run` and
// `isolab compare`, the Python module's free_vibration): "auto" or a time in seconds.
#pragma once

#include <string>

#include "isolab/core/units.h"
#include "isolab/model/model_file.h"

namespace isolab::model {

// Throws InputError({key}, ...) for anything but "auto" or a finite time >= 0 (s); the time is
// returned in `units`.
FreeVibration ParseFreeVibration(const std::string& text, const UnitSystem& units,
                                 const std::string& key);

}  // namespace isolab::model
