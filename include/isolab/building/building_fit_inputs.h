// What a building-level fit or diagnosis reads: the specification, the model it starts from, and
// the measured motions, shake-table files (shake_table_measurements.h) or, for `input: force`,
// force-driven tests in the cyclic-test format. `isolab fit --building`, `isolab diagnose
// --building` and their Python twins (isolab.fit and isolab.diagnose with building=) read them
// here, so that an option means the same and is refused the same way in both.
#pragma once

#include <string>
#include <vector>

#include "isolab/building/building_fit.h"
#include "isolab/model/building_fit_spec_file.h"
#include "isolab/model/model_file.h"

namespace isolab::building {

struct BuildingFitInputs {
  model::BuildingFitSpecFile file;
  model::ModelFile model;
  BuildingFitSpec spec;            // its motions' specimen set by ReadBuildingMotions
  std::vector<std::string> files;  // every file read: the spec, the model and its includes
};

// How the caller spells its options in refusals: the command line's (the default), or the Python
// module's keywords ("offsets=", ...), so that each front names what its user typed.
struct BuildingOptionNames {
  std::string where = "command line";  // the error's location
  std::string offsets = "--offsets";
  std::string force_unit = "--force-unit", length_unit = "--length-unit";
};

// The data options of both fronts.
struct BuildingData {
  std::vector<std::string> data;
  std::string specimen;  // "sequential", "independent"; empty: the data's header (force tests)
  std::string offsets;   // shake-table accelerometer offsets; empty: pre-event
  std::string force_unit, length_unit;  // of force-driven tests without a "# units:" line
  bool quiet = false;
  std::string command;  // names the command in progress lines
  BuildingOptionNames names;
};

// Throws InputError for a malformed specification or model, and for options that do not apply
// to the spec's input (offsets to force-driven tests, units to shake-table files).
BuildingFitInputs LoadBuildingFit(const std::string& spec_path, const BuildingData& data);

// Reads the motions in the model's units, a progress line each on stderr unless quiet. Throws
// InputError.
std::vector<BuildingMotion> ReadBuildingMotions(BuildingFitInputs* inputs,
                                                const BuildingData& data);

}  // namespace isolab::building
