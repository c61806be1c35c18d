// What a building-level fit or diagnosis reads (private to the cli): the specification, the model
// it starts from, and the measured motions, shake-table files or, for `input: force`, force-driven
// tests in the cyclic-test format.
#pragma once

#include <string>
#include <vector>

#include "isolab/analysis/building_fit.h"
#include "isolab/model/building_fit_spec_file.h"
#include "isolab/model/model_file.h"

namespace isolab::cli {

struct BuildingFitInputs {
  model::BuildingFitSpecFile file;
  model::ModelFile model;
  analysis::BuildingFitSpec spec;  // its motions' specimen set by ReadBuildingMotions
  std::vector<std::string> files;  // every file read: the spec, the model and its includes
};

// The command line's data options.
struct BuildingData {
  std::vector<std::string> data;
  std::string specimen;  // "sequential", "independent"; empty: the data's header (force tests)
  std::string offsets;   // shake-table accelerometer offsets; empty: pre-event
  std::string force_unit, length_unit;  // of force-driven tests without a "# units:" line
  bool quiet = false;
  std::string command;  // names the command in progress lines
};

// Throws InputError for a malformed specification or model, and for options that do not apply
// to the spec's input (--offsets to force-driven tests, units to shake-table files).
BuildingFitInputs LoadBuildingFit(const std::string& spec_path, const BuildingData& data);

// Reads the motions in the model's units. Throws InputError.
std::vector<analysis::BuildingMotion> ReadBuildingMotions(BuildingFitInputs* inputs,
                                                          const BuildingData& data);

}  // namespace isolab::cli
