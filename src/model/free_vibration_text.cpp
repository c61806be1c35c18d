#include "isolab/model/free_vibration_text.h"

#include <fmt/format.h>

#include "isolab/core/errors.h"
#include "isolab/core/number.h"

namespace isolab::model {

FreeVibration ParseFreeVibration(const std::string& text, const UnitSystem& units,
                                 const std::string& key) {
  if (text == "auto") return {};
  const double seconds = ParseFiniteNumber(text).value_or(-1.0);
  if (seconds < 0.0) {
    throw InputError({key},
                     fmt::format("'{}' (expected auto, or a time in s >= 0; 0 for none)", text));
  }
  return {false, units.Convert(seconds, "s", dimension::kTime)};
}

}  // namespace isolab::model
