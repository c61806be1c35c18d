#include "free_vibration_option.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "isolab/core/errors.h"

namespace isolab::cli {

io::FreeVibration ParseFreeVibration(const std::string& text, const io::UnitSystem& units) {
  if (text == "auto") return {};
  double seconds = -1.0;
  std::size_t used = 0;
  try {
    seconds = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(seconds) || seconds < 0.0) {
    throw InputError({"--free-vibration"},
                     fmt::format("'{}' (expected auto, or a time in s >= 0; 0 for none)", text));
  }
  return {false, units.Convert(seconds, "s", io::dimension::kTime)};
}

}  // namespace isolab::cli
