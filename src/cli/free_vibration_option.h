// --free-vibration of `isolab run` and `isolab compare`: "auto" or a time in seconds.
#pragma once

#include <string>

#include "isolab/io/model_file.h"
#include "isolab/io/units.h"

namespace isolab::cli {

// Throws InputError({"--free-vibration"}, ...) for anything but "auto" or a time >= 0 (s);
// the time is returned in `units`.
io::FreeVibration ParseFreeVibration(const std::string& text, const io::UnitSystem& units);

}  // namespace isolab::cli
