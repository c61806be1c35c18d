#include "isolab/design/accidental_torsion.h"

#include <fmt/format.h>

#include "isolab/core/errors.h"

namespace isolab::design {

std::vector<EccentricityCase> AccidentalEccentricities(const model::ModelFile& model, double ratio,
                                                       const std::string& key) {
  if (!model.structure || model.structure->kind != model::StructureSection::Kind::kPlanBuilding) {
    throw InputError({key}, fmt::format("accidental eccentricity shifts floors in plan; '{}' is "
                                        "not a building in plan (give 0, or a plan model)",
                                        model.path));
  }
  if (!(ratio > 0.0 && ratio < 0.5)) {
    throw InputError({key}, fmt::format("{:g} (a fraction of the plan dimension in (0, 0.5): "
                                        "0.05 for the codes' 5 %)",
                                        ratio));
  }
  const hysteresis::Vec2 size = model.structure->footprint_size;
  std::vector<EccentricityCase> cases;
  for (const int sx : {1, -1}) {
    for (const int sy : {1, -1}) {
      cases.push_back({fmt::format("ex{}ey{}", sx > 0 ? '+' : '-', sy > 0 ? '+' : '-'),
                       {sx * ratio * size.x, sy * ratio * size.y}});
    }
  }
  return cases;
}

model::ModelFile WithCentresOfMassShifted(model::ModelFile model, hysteresis::Vec2 shift) {
  model.description += fmt::format(
      " (accidental eccentricity: every centre of mass moved by [{:g}, {:g}])", shift.x, shift.y);
  structure::PlanBuilding& plan = model.structure->plan;
  plan.base.centre_of_mass = plan.base.centre_of_mass + shift;
  for (structure::PlanStory& story : plan.stories) {
    story.floor.centre_of_mass = story.floor.centre_of_mass + shift;
  }
  return model;
}

}  // namespace isolab::design
