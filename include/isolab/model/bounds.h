// Nominal, upper-bound and lower-bound models of a model with property modification factors
// (property_modification.h), as model files that run alone: the model's own text with every
// named property times its combined lambda_max (upper) or lambda_min (lower), the modification
// sections removed, the files it names (records, an included isolation) made absolute, and a
// results file named for the bound.
#pragma once

#include <string>
#include <vector>

#include "isolab/model/model_file.h"

namespace isolab::model {

// The first line of every bound model's text: `isolab bounds` replaces a file only when it starts
// so (one it wrote), never a file of someone else's.
inline constexpr const char* kBoundModelHeader = "# isolab bounds: ";

struct BoundModel {
  std::string bound;  // "nominal", "upper", "lower"
  std::string text;   // the model file's YAML, its first line kBoundModelHeader's
};

// One modified property and the values its bound models take (in the text's own unit).
struct BoundProperty {
  std::string bearing, component, key;
  FactorPair lambda;
  std::string nominal, lower, upper;  // the values as written
};

struct BoundModels {
  std::vector<BoundModel> models;  // nominal, upper, lower
  std::vector<BoundProperty> properties;
};

// A bound model's text with every centre of mass (the base's and each story's) at the model's
// own plus `shift` (length), and its description saying so: an accidental eccentricity case as a
// model that runs alone. `model` is the text read (its centres of mass as the text gives them or
// by default).
std::string WithCentresOfMassShiftedText(const std::string& text, const ModelFile& model,
                                         hysteresis::Vec2 shift, const std::string& case_name);

// Throws InputError for a model without modification factors and for a bound model that breaks
// a law's rules (e.g. ku > kd of a lead-rubber bearing whose kd is raised), naming the bound.
BoundModels MakeBoundModels(const ModelFile& model);

}  // namespace isolab::model
