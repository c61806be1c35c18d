// Measured tests of a bearing from CSV, any displacement history (sinusoidal cycles, a seismic or
// shake-table history): one file with a `test` column holding several tests, or one file per test
// (then named after the file):
//   # units: force kN, length mm      (optional; else the caller's, default kN and mm)
//   # specimen: one, in order         (optional; else independent specimens)
//   test,time,displacement,force      (columns in any order; time in seconds)
//   u=50,0.00,0.000,0.000
// "specimen: one" says the tests ran one after another on one specimen, in the order of the file
// (and of the files): each continues from the state the previous one left. Values are converted
// into the caller's unit system. Errors name the file and line (and column), and the test for a
// test too short to identify anything (no half-cycle between two reversals).
#pragma once

#include <string>
#include <vector>

#include "isolab/core/units.h"
#include "isolab/identification/cyclic_data.h"

namespace isolab::io {

// The units the caller was given for the files' values (--force-unit, force_unit=); empty where
// none. A file's "# units:" line gives its own (a given unit that contradicts it is refused);
// without either, kN and mm.
struct CyclicTestUnits {
  std::string force, length;
};

struct CyclicTestSet {
  std::vector<identification::CyclicTestData> tests;  // in file order
  bool one_specimen = false;                          // a file's "# specimen: one" header
  std::vector<std::string> source;                    // per test: the file it was read from
  std::vector<std::string> without_units;             // files with no "# units:" line
};

// Throws InputError.
CyclicTestSet ReadCyclicTests(const std::vector<std::string>& paths,
                              const CyclicTestUnits& file_units, const UnitSystem& into);

// Writes tests in the same format (one `test` column), for generated data; `one_specimen` writes
// the "# specimen: one, in order" header.
void WriteCyclicTests(const std::string& path,
                      const std::vector<identification::CyclicTestData>& tests,
                      const UnitSystem& units, bool one_specimen = false);

// "independent" or "sequential" (one specimen in order), as --specimen takes it: the files'
// header unless the option is given. Throws InputError for another word.
bool OneSpecimen(const std::string& option, bool from_files);

}  // namespace isolab::io
