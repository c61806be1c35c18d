// The structure a model describes, laid out (structure/layout.h): the one place that reads which
// kind of structure a model has (an SDOF, a shear building in one direction, a building in plan).
// Everything after it reads the structure and its layout, whatever the kind.
#pragma once

#include <string>
#include <vector>

#include "isolab/model/model_file.h"
#include "isolab/structure/layout.h"

namespace isolab::model {

// `fixed_base`: the superstructure without its isolation, the base held. With axial_load, the
// friction pendulum bearings take their axial loads (structure/axial_load.h). Throws InputError
// (naming the model) for a model without a structure section, for `fixed_base` on an SDOF (named
// `fixed_base_key`, as the caller names that option), and for a description the builder refuses.
structure::LaidOutStructure BuildStructure(const ModelFile& model, bool fixed_base = false,
                                           const std::string& fixed_base_key = "--fixed-base");

// The horizontal directions the model's structure moves in, as BuildStructure lays it out: 1, or
// 2 for a building in plan (whose levels also rotate); 1 without a structure section.
int Directions(const ModelFile& model);

// A building in plan's isolators, each its own assembly at its own position; nullptr for a model
// whose isolation is one assembly (an SDOF, a shear building) or that has none.
const std::vector<structure::PlanIsolatorSite>* PlanIsolators(const ModelFile& model);

// For what drives a model's isolation or isolators by their laws alone (isolab cyclic's tests,
// paths and orbits, `what`): the laws carry their own w there, so a model whose axial_load would
// give its bearings other loads is refused (InputError at axial_load) rather than run at w.
void RefuseAxialLoads(const ModelFile& model, const std::string& what);

}  // namespace isolab::model
