#include "isolab/model/build_structure.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace isolab::model {
namespace {

// An uncoupled pair's x and y laws are one bearing in two directions: it carries one weight, so
// its laws must be the same pendulum.
void RefuseUnlikePairs(const hysteresis::ParallelAssembly&, const std::string&,
                       const AxialLoadSection&) {}
void RefuseUnlikePairs(const hysteresis::PlanAssembly& assembly, const std::string& isolator,
                       const AxialLoadSection& section) {
  for (const hysteresis::PlanComponent& c : assembly.components()) {
    if (c.law_y && hysteresis::PendulumWeight(*c.law_y) != hysteresis::PendulumWeight(c.law)) {
      throw InputError(section.location,
                       fmt::format("axial_load: isolator {}'s {} has other laws along x and "
                                   "y; an axial load scales a pair whose x and y laws are "
                                   "the same pendulum",
                                   isolator, c.name));
    }
  }
}

// The W of an isolator's pendulum laws (their sum: they scale together), 0 for an isolator with
// none; an isolator that mixes pendulums with other laws is refused (the other laws' forces do
// not scale with the axial load, and splitting the load among them would be a guess).
template <class Assembly>
double IsolatorWeight(const Assembly& assembly, const std::string& isolator,
                      const AxialLoadSection& section) {
  RefuseUnlikePairs(assembly, isolator, section);
  double weight = 0.0;
  std::size_t pendulums = 0, others = 0;
  for (const auto& component : assembly.components()) {
    if (const std::optional<double> w =
            hysteresis::PendulumWeight(hysteresis::LawAlongX(component))) {
      weight += *w;
      ++pendulums;
    } else {
      ++others;
    }
  }
  if (pendulums > 0 && others > 0) {
    throw InputError(section.location,
                     fmt::format("axial_load: isolator {} mixes friction pendulum laws with "
                                 "others; an axial load scales an isolator whose laws are all "
                                 "pendulums (friction_pendulum, double_friction_pendulum, "
                                 "triple_friction_pendulum)",
                                 isolator));
  }
  return weight;
}

// The axial loads the model asks for, on the structure as laid out.
void AddAxialLoads(const ModelFile& model, structure::LaidOutStructure* built) {
  const AxialLoadSection& section = *model.axial_load;
  const structure::Layout& layout = built->layout;
  std::vector<double> weights;
  for (const structure::IsolatorLayout& isolator : layout.isolators) {
    weights.push_back(built->structure.VisitSlotAssembly(isolator.slot, [&](const auto& assembly) {
      return IsolatorWeight(assembly, isolator.name, section);
    }));
  }
  if (std::none_of(weights.begin(), weights.end(), [](double w) { return w > 0.0; })) {
    throw InputError(section.location,
                     "axial_load: no isolator is a friction pendulum bearing to take it");
  }
  structure::AxialLoadOptions options;
  options.gravity = model.units.Convert(9.80665, "m/s^2", dimension::kAcceleration);
  options.overturning = section.overturning;
  options.base_height = section.base_height;
  try {
    built->structure.SetAxialLoads(
        structure::RigidSlabAxialLoads(built->structure, layout, weights, options));
  } catch (const std::invalid_argument& error) {
    throw InputError(section.location, fmt::format("axial_load: {}", error.what()));
  }
}

structure::LaidOutStructure BuildLaidOut(const ModelFile& model, bool fixed_base,
                                         const std::string& fixed_base_key) {
  if (!model.structure) {
    throw InputError({model.path},
                     "no structure section: nothing to analyse in time (give structure or plan)");
  }
  const StructureSection& section = *model.structure;
  try {
    switch (section.kind) {
      case StructureSection::Kind::kSdof: {
        if (fixed_base) {
          throw InputError({fixed_base_key},
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

}  // namespace

structure::LaidOutStructure BuildStructure(const ModelFile& model, bool fixed_base,
                                           const std::string& fixed_base_key) {
  structure::LaidOutStructure built = BuildLaidOut(model, fixed_base, fixed_base_key);
  if (model.axial_load && built.layout.isolated()) AddAxialLoads(model, &built);
  return built;
}

int Directions(const ModelFile& model) {
  return model.structure && model.structure->kind == StructureSection::Kind::kPlanBuilding ? 2 : 1;
}

const std::vector<structure::PlanIsolatorSite>* PlanIsolators(const ModelFile& model) {
  const bool plan =
      model.structure && model.structure->kind == StructureSection::Kind::kPlanBuilding;
  return plan ? &model.structure->plan.isolators : nullptr;
}

void RefuseAxialLoads(const ModelFile& model, const std::string& what) {
  if (!model.axial_load) return;
  throw InputError(model.axial_load->location,
                   fmt::format("axial_load: {} drives the bearings by their laws, each at its own "
                               "w, not at the axial loads a time-history run gives them (isolab "
                               "run); leave axial_load out to test the bearings at w",
                               what));
}

}  // namespace isolab::model
