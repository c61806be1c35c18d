#include "isolab/model/build_structure.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace isolab::model {

structure::LaidOutStructure BuildStructure(const ModelFile& model, bool fixed_base) {
  if (!model.structure) {
    throw InputError({model.path},
                     "no structure section: nothing to analyse in time (give structure or plan)");
  }
  const StructureSection& section = *model.structure;
  try {
    switch (section.kind) {
      case StructureSection::Kind::kSdof: {
        if (fixed_base) {
          throw InputError({"--fixed-base"},
                           "applies to a building on isolators; an SDOF has no base to hold");
        }
        double c = section.damping_coefficient;
        if (section.damping_ratio) {  // on the initial stiffness of every bearing together
          c = 2.0 * *section.damping_ratio *
              std::sqrt(structure::InitialStiffness(model.isolation) *
                        model.isolation_count.value_or(1) * section.mass);
        }
        return structure::BuildSdof(section.mass, c, model.isolation, IsolationBearings(model));
      }
      case StructureSection::Kind::kShearBuilding: {
        structure::ShearBuilding building = section.building;
        building.isolated = !fixed_base && model.isolation.size() > 0;
        if (building.isolated) {
          building.isolation = model.isolation;
          building.bearings = IsolationBearings(model);
        }
        return structure::BuildShearBuilding(building);
      }
      case StructureSection::Kind::kPlanBuilding:
        return structure::BuildPlanBuilding(section.plan, fixed_base);
    }
  } catch (const std::invalid_argument& error) {
    const bool plan = section.kind == StructureSection::Kind::kPlanBuilding;
    throw InputError({model.path}, fmt::format("{}{}", plan ? "plan." : "", error.what()));
  }
  throw std::logic_error("unknown structure kind");
}

int Directions(const ModelFile& model) {
  return model.structure && model.structure->kind == StructureSection::Kind::kPlanBuilding ? 2 : 1;
}

const std::vector<structure::PlanIsolatorSite>* PlanIsolators(const ModelFile& model) {
  const bool plan =
      model.structure && model.structure->kind == StructureSection::Kind::kPlanBuilding;
  return plan ? &model.structure->plan.isolators : nullptr;
}

}  // namespace isolab::model
