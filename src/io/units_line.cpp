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
    if (Lower(what) == "force") {
      units->force = unit;
    } else if (Lower(what) == "length") {
      units->length = unit;
    } else if (Lower(what) == "time") {
      units->time = unit;
    } else if (!what.empty()) {
      units->others.push_back(Trim(part));
    }
  }
  units->line = line_number;
  return true;
}

ResolvedUnits ResolveUnits(const std::string& path, const UnitsLine& line,
                           const std::string& given_force, const std::string& given_length,
                           const std::string& fallback_force, const std::string& fallback_length) {
  if (!line.others.empty()) {
    throw InputError({path, line.line},
                     fmt::format("units: '{}' is not a part the line names (expected force and "
                                 "length, e.g. '# units: force kN, length mm')",
                                 line.others.front()));
  }
  if (!line.time.empty() && !SameUnit(line.time, "s", dimension::kTime)) {
    throw InputError({path, line.line},
                     fmt::format("units: time {}: the file's times are read in seconds (convert "
                                 "them, and say 'time s' or nothing)",
                                 line.time));
  }
  for (const auto& [declared, dimension] :
       {std::pair{line.force, dimension::kForce}, std::pair{line.length, dimension::kLength}}) {
    try {
      if (!declared.empty()) UnitSystem("kN", "mm").Convert(1.0, declared, dimension);
    } catch (const std::invalid_argument& error) {
      throw InputError({path, line.line}, fmt::format("units: {}", error.what()));
    }
  }
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
