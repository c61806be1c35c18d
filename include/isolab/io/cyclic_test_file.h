// Measured cyclic tests from CSV: one file with a `test` column holding several tests, or one file
// per test (then named after the file):
//   # units: force kN, length mm      (optional; else the caller's, default kN and mm)
//   test,time,displacement,force      (columns in any order; time in seconds)
//   u=50,0.00,0.000,0.000
// Values are converted into the caller's unit system. Errors name the file and line, and the test
// for a test with fewer than two cycles or a displacement that never reverses.
#pragma once

#include <string>
#include <vector>

#include "isolab/identification/cyclic_data.h"
#include "isolab/io/units.h"

namespace isolab::io {

struct CyclicTestUnits {
  std::string force = "kN", length = "mm";  // of the file's values, unless its header says
};

// Throws InputError.
std::vector<identification::CyclicTestData> ReadCyclicTests(const std::vector<std::string>& paths,
                                                            const CyclicTestUnits& file_units,
                                                            const UnitSystem& into);

// Writes tests in the same format (one `test` column), for generated data.
void WriteCyclicTests(const std::string& path,
                      const std::vector<identification::CyclicTestData>& tests,
                      const UnitSystem& units);

}  // namespace isolab::io
