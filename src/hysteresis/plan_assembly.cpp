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
  state_size_ = kernels_.size();
  for (std::size_t i = 0; i < kernels_.size(); ++i) {
    element_offsets_.push_back(state_size_);
    if (auto* series = std::get_if<PlanSeriesArrangement>(&kernels_[i])) {
      series->law.elements_at = static_cast<std::ptrdiff_t>(state_size_ - i);
    }
    state_size_ += PlanStateSlots(kernels_[i]) - 1;
  }
}

std::optional<PlanResponse> PlanAssembly::ConstantTangent() const {
  for (const PlanLawKernel& kernel : kernels_) {
    if (!HasConstantTangent(kernel)) return std::nullopt;
  }
  const std::vector<PlanLawState> rest(state_size());
  std::vector<PlanLawState> trial(state_size());
  std::vector<PlanLawResponse> responses(size());
  return Update(rest, {}, trial, responses);
}

double PlanAssembly::StoredEnergy(std::span<const PlanLawState> states) const {
  double energy = 0.0;
  for (std::size_t i = 0; i < kernels_.size(); ++i) {
    energy += PlanStoredEnergyInPlace(kernels_[i], states[i]);
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

std::optional<double> PendulumWeight(const PlanAssembly& assembly) {
  if (assembly.size() == 0) return std::nullopt;
  double weight = 0.0;
  for (const PlanComponent& component : assembly.components()) {
    const std::optional<double> w = PendulumWeight(component.law);
    if (!w || (component.law_y && PendulumWeight(*component.law_y) != w)) return std::nullopt;
    weight += *w;
  }
  return weight;
}

}  // namespace isolab::hysteresis
