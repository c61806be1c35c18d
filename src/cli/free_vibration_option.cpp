#include "free_vibration_option.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "isolab/core/errors.h"
#include "isolab/core/number.h"

namespace isolab::cli {

io::FreeVibration ParseFreeVibration(const std::string& text, const io::UnitSystem& units) {
  if (text == "auto") return {};
  const double seconds = ParseFiniteNumber(text).value_or(-1.0);
  if (seconds < 0.0) {
    throw InputError({"--free-vibration"},
                     fmt::format("'{}' (expected auto, or a time in s >= 0; 0 for none)", text));
  }
  return {false, units.Convert(seconds, "s", io::dimension::kTime)};
}

}  // namespace isolab::cli
