// Displacement paths from CSV: what `isolab cyclic --path` drives a model along, a measured
// test's displacement history in one direction or two, with its time and, when it was measured,
// its force (so the model's prediction can be set against it):
//   # units: force kN, length mm        (or the caller's units; see ReadDisplacementPaths)
//   test,time,displacement,force        one direction; test and force optional
//   test,time,displacement_x,displacement_y,force_x,force_y   two (ux, uy, fx, fy also read)
// Several paths in one file under a `test` column, or one file per path (named after the file);
// the cyclic test data of `isolab fit` are one-direction paths. Time in seconds, increasing.
// Errors name the file and line (and column).
#pragma once

#include <string>
#include <vector>

#include "isolab/core/units.h"
#include "isolab/hysteresis/plan_vector.h"

namespace isolab::io {

struct DisplacementPath {
  std::string name;
  std::vector<double> time;
  std::vector<hysteresis::Vec2> displacement;  // y = 0 for one direction
  std::vector<hysteresis::Vec2> force;         // measured; empty when the file has none
  bool plan = false;                           // two displacement columns
};

struct DisplacementPathSet {
  std::vector<DisplacementPath> paths;     // in file order
  std::vector<std::string> without_units;  // files with no "# units:" line
};

// Values are converted from the file's units (its "# units:" line, else `force_unit` and
// `length_unit` where given, else `into`'s) into `into`. Throws InputError, also for a given unit
// that contradicts a file's line.
DisplacementPathSet ReadDisplacementPaths(const std::vector<std::string>& files,
                                          const std::string& force_unit,
                                          const std::string& length_unit, const UnitSystem& into);

}  // namespace isolab::io
