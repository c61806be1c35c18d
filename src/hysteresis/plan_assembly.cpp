#include "isolab/hysteresis/plan_assembly.h"

#include <vector>

namespace isolab::hysteresis {

PlanAssembly::PlanAssembly(std::vector<PlanComponent> components)
    : components_(std::move(components)) {
  kernels_.reserve(components_.size());
  for (const PlanComponent& component : components_) {
    kernels_.push_back(component.law_y ? UncoupledKernel(component.law, *component.law_y)
                                       : CoupledKernel(component.law));
  }
}

std::optional<PlanResponse> PlanAssembly::ConstantTangent() const {
  for (const PlanLawKernel& kernel : kernels_) {
    if (!HasConstantTangent(kernel)) return std::nullopt;
  }
  const std::vector<PlanLawState> rest(size());
  std::vector<PlanLawState> trial(size());
  std::vector<PlanLawResponse> responses(size());
  return Update(rest, {}, trial, responses);
}

double PlanAssembly::StoredEnergy(std::span<const PlanLawState> states) const {
  double energy = 0.0;
  for (std::size_t i = 0; i < kernels_.size(); ++i) {
    energy += PlanStoredEnergy(kernels_[i], states[i]);
  }
  return energy;
}

double PlanAssembly::DissipatedEnergy(std::span<const PlanLawState> states) const {
  double energy = 0.0;
  for (const PlanLawState& state : states) energy += Dissipated(state);
  return energy;
}

double PlanAssembly::ViscousEnergy(std::span<const PlanLawState> states) const {
  double energy = 0.0;
  for (std::size_t i = 0; i < kernels_.size(); ++i) {
    energy += PlanViscousEnergy(kernels_[i], states[i]);
  }
  return energy;
}

}  // namespace isolab::hysteresis
