// The properties of a one-direction building model (a shear building on its isolation layer) that
// a building-level fit identifies and a prediction samples, by name:
//
//   isolation.<component>.<key>   a parameter of an isolation component, in the form the model
//                                 gives it (isolation.c1.k0; isolation.isolators.uy)
//   stories.stiffness             every story's stiffness, one value (linear stories)
//   story.<n>.stiffness           story n's (1: the lowest)
//   damping.ratio                 the superstructure's modal damping ratio of every mode
//   damping.ratio.<n>             mode n's (the other modes keep theirs)
//   mass.base, mass.floor.<n>     a level's mass; the levels not named share what is left of the
//                                 model's total mass equally
//
// The total mass stays as the model gives it: floor motions alone cannot fix a mass scale (the
// equations of motion are homogeneous in mass and stiffness), only how the mass is distributed.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "isolab/model/model_file.h"

namespace isolab::analysis {

// The value `name` has in `model` (model units). Throws InputError naming the parameter when the
// model has no such property or it cannot be set (a story with hysteretic components, damping
// that is not modal, a plan model).
double ParameterValue(const model::ModelFile& model, const std::string& name);

// Sets every named parameter to its value, the masses together so that the total is kept. Throws
// InputError as ParameterValue does, for every level's mass named (nothing would hold the total),
// and InvalidParameter for values that break a law's rules or leave a level no mass.
void SetParameters(model::ModelFile* model, std::span<const std::string> names,
                   std::span<const double> values);

// A range a fit searches when none is given: a third to three times the value (log-uniform), for
// a damping ratio 0.002 to 0.3; a non-positive value (a softening stiffness) from -3 |v| to 3 |v|.
struct ParameterRange {
  double low = 0.0, high = 0.0;
  bool log = true;
};
ParameterRange DefaultRange(const std::string& name, double value);

}  // namespace isolab::analysis
