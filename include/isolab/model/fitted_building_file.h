// Writes a building model identified by `isolab fit --building` (building/building_fit.h) as a
// model file: the model it started from, with the fitted values and their uncertainty.
#pragma once

#include <string>

#include "isolab/model/model_file.h"

namespace isolab::model {

// The text of `fitted` (a one-direction shear building whose values a fit changed; its `text` the
// model it started from): its isolation written inline (components in mathematical parameters,
// the layer's name and count kept, with its identified range), its stories as a list of masses and stiffnesses, its base
// mass, its modal damping ratios, and its `uncertainty`, each number to nine digits. The text is
// read back first: a model the readers would refuse is an InputError naming `fitted.path`.
// `note` ("identified by ...") begins the description, followed by the model it started from.
std::string FittedBuildingText(const ModelFile& fitted, const std::string& note);

}  // namespace isolab::model
