// What `isolab fit` identifies: the unit system and the component types with their counts, and
// optionally, per component, bounds, fixed values and starting values of its shape coordinates
// (identification/parametrisation.h). Stiffnesses need none: they are solved exactly.
//   units: {force: kN, length: mm}
//   components:
//     - {type: trilinear_elastic, count: 3}
//     - {type: thm1, count: 4, bounds: {uy: [1, 50]}, start: {uy: 10}}
//     - {type: elastoplastic, count: 2, name: lead}
#pragma once

#include <string>
#include <vector>

#include "isolab/core/units.h"
#include "isolab/identification/parametrisation.h"

namespace isolab::model {

struct FitSpec {
  std::string path;
  UnitSystem units{"kN", "mm", "s"};
  std::vector<identification::ComponentSpec> components;
};

// Throws InputError with file:line:column for anything malformed.
FitSpec LoadFitSpec(const std::string& path);

}  // namespace isolab::model
