// Writes an identified isolator as a model file (an isolation section in the paper's mathematical
// parameters) that `isolab run`, `isolab cyclic` and `isolation: {file: ...}` read back.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "isolab/core/units.h"
#include "isolab/identification/cyclic_data.h"
#include "isolab/identification/parametrisation.h"

namespace isolab::model {

struct FittedModel {
  std::vector<std::string> comment;  // lines written as "# ..." at the top
  std::string description;
  UnitSystem units{"kN", "mm", "s"};
  std::vector<identification::ComponentSpec> components;  // names and types
  std::vector<std::vector<double>> mathematical;          // per component, ParameterKeys order
  std::string specification;  // the file the components were asked for in, for messages
  // The range of the data the fit saw (identification::RangeOf), in `units`: written as
  // isolation.identified_range (model_file.h).
  std::optional<identification::IdentifiedRange> range;
};

// Written atomically (a temporary file renamed), so a failure leaves no half-written file. The
// text is read back first as `isolab cyclic` and `isolab run` read it: a model they would refuse
// (a component the data gave no stiffness, k0 = 0) is an InputError at the specification, and
// nothing is written.
void WriteFittedModel(const std::string& path, const FittedModel& model);

}  // namespace isolab::model
