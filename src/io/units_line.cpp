#include "units_line.h"

#include <fmt/format.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "csv_fields.h"
#include "isolab/core/errors.h"
#include "isolab/core/units.h"

namespace isolab::io {
namespace {

// Whether two spellings name one unit ("kN" and "kn" do not; "kN" and "1000 N" are not units).
bool SameUnit(const std::string& a, const std::string& b, Dimension dimension) {
  if (a == b) return true;
  try {
    const UnitSystem system("kN", "mm");
    return std::abs(system.Convert(1.0, a, dimension) / system.Convert(1.0, b, dimension) - 1.0) <
           1e-12;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

}  // namespace

bool ReadUnitsLine(const std::string& text, int line_number, UnitsLine* units) {
  const auto colon = text.find(':');
  if (Lower(text).find("units") == std::string::npos || colon == std::string::npos) return false;
  for (const std::string& part : Split(text.substr(colon + 1))) {
    std::stringstream words(part);
    std::string what, unit;
    words >> what >> unit;
    if (Lower(what) == "force") units->force = unit;
    if (Lower(what) == "length") units->length = unit;
  }
  units->line = line_number;
  return true;
}

ResolvedUnits ResolveUnits(const std::string& path, const UnitsLine& line,
                           const std::string& given_force, const std::string& given_length,
                           const std::string& fallback_force, const std::string& fallback_length) {
  for (const auto& [declared, given, what, dimension] :
       {std::tuple{line.force, given_force, "force", dimension::kForce},
        std::tuple{line.length, given_length, "length", dimension::kLength}}) {
    if (!declared.empty() && !given.empty() && !SameUnit(declared, given, dimension)) {
      throw InputError({path, line.line},
                       fmt::format("units: the file's line says {} {}, the {} unit given beside "
                                   "it says {}: give the file's, or none",
                                   what, declared, what, given));
    }
  }
  const auto pick = [](const std::string& declared, const std::string& given,
                       const std::string& fallback) {
    return !declared.empty() ? declared : !given.empty() ? given : fallback;
  };
  return {pick(line.force, given_force, fallback_force),
          pick(line.length, given_length, fallback_length)};
}

}  // namespace isolab::io
