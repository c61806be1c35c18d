// What `isolab fit --building` identifies (building/building_fit.h): the building model it starts
// from, the parameters it fits (analysis/building_parameters.h names them), the channels it
// compares and the band it reads them in.
//   model: bncs.yaml                 # relative to this file
//   input: table                     # table: shake-table motions; force: force-driven tests
//                                    # (cyclic-test files: time, displacement, force on level 1)
//   parameters:
//     - isolation.isolators.k1       # a name alone: the default range (a third to three times)
//     - {name: stories.stiffness, range: [50, 300], start: 117}   # in the model's units
//   channels: [d1, a6]               # default: every level's displacement and acceleration
//   band: [0.1, 10]                  # (1/time of the model) default: the whole record
//   pause: 60                        # (time) of rest between one specimen's motions
//   substeps: 20                     # integration steps per sample (default 1)
//   priors:                          # not fitted: given from what engineers know
//     - {name: isolation.stiffening.k2, value: 0.8, sigma: 0.2, source: "design data"}
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "isolab/core/errors.h"

namespace isolab::model {

struct BuildingFitParameterEntry {
  std::string name;
  std::optional<double> low{}, high{}, start{};
  SourceLocation where;  // the entry's line, for what only the model can check (its name)
};

// A parameter the data cannot fix, held at a value from outside them (model_file.h's
// ParameterPrior): `value` default the model's, `sigma` in ln p, `source` required.
struct BuildingFitPriorEntry {
  std::string name;
  std::optional<double> value{};
  double sigma = 0.0;
  std::string source;
  SourceLocation where;  // the entry's line, for what only the model can check (its name)
};

struct BuildingFitSpecFile {
  std::string path;
  std::string model;  // resolved against the spec's folder
  std::vector<BuildingFitParameterEntry> parameters;
  std::vector<BuildingFitPriorEntry> priors;
  std::vector<std::string> channels;
  std::vector<SourceLocation> channel_where;  // each channel's place in the file
  std::optional<double> band_low{}, band_high{};
  bool force_driven = false;  // input: force
  double pause = 0.0;         // 0: not given
  int substeps = 1;
};

// Throws InputError with file:line:column for anything malformed.
BuildingFitSpecFile LoadBuildingFitSpec(const std::string& path);

}  // namespace isolab::model
