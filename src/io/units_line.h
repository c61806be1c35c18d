// The '# units: force kN, length mm' comment of a test-data file (cyclic tests, displacement
// paths), and the units the file's values are read in: the line's, else those the caller was
// given (--force-unit, force_unit=), else a fallback. A given unit that contradicts the line is an
// error, not a choice between them: data in one unit read in another fit with the same error and
// stiffnesses off by the ratio.
#pragma once

#include <string>
#include <vector>

namespace isolab::io {

struct UnitsLine {
  std::string force, length, time;  // the parts the line names; empty where it names none
  std::vector<std::string> others;  // parts that are none of these, which ResolveUnits refuses
  int line = 0;                     // where it is; 0: the file has none
};

// Reads `text` (a comment line, '#' included) as a units line: true when it is one (the word
// "units" and a colon), with the parts it names merged into `units`.
bool ReadUnitsLine(const std::string& text, int line_number, UnitsLine* units);

struct ResolvedUnits {
  std::string force, length;
};

// The units of `path`'s values. Throws InputError at the line when it names a unit isolab does
// not know, a time unit other than seconds (the files' times are read in s), a part other than
// force, length and time, or, for a given unit (non-empty), another unit than the given one.
ResolvedUnits ResolveUnits(const std::string& path, const UnitsLine& line,
                           const std::string& given_force, const std::string& given_length,
                           const std::string& fallback_force, const std::string& fallback_length);

}  // namespace isolab::io
