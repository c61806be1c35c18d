#include "isolab/hysteresis/parallel_assembly.h"

#include <vector>

namespace isolab::hysteresis {

ParallelAssembly::ParallelAssembly(std::vector<Component> components)
    : components_(std::move(components)) {
  kernels_.reserve(components_.size());
  for (const Component& component : components_) kernels_.push_back(component.parameters.Kernel());
  state_size_ = kernels_.size();
  for (std::size_t i = 0; i < kernels_.size(); ++i) {
    element_offsets_.push_back(state_size_);
    if (auto* series = std::get_if<SeriesArrangement>(&kernels_[i])) {
      series->elements_at = static_cast<std::ptrdiff_t>(state_size_ - i);
    }
    state_size_ += StateSlots(kernels_[i]) - 1;
  }
}

std::optional<AssemblyResponse> ParallelAssembly::ConstantTangent() const {
  for (const LawKernel& kernel : kernels_) {
    if (!HasConstantTangent(kernel)) return std::nullopt;
  }
  const std::vector<LawState> rest(state_size());
  std::vector<LawState> trial(state_size());
  std::vector<LawResponse> responses(size());
  return Update(rest, {}, trial, responses);
}

// The further states of sliders in series carry no dissipated energy (series_arrangement.h), so
// the sum over every state counts each law's once.
double ParallelAssembly::DissipatedEnergy(std::span<const LawState> states) const {
  double energy = 0.0;
  for (const LawState& state : states) energy += state.dissipated;
  return energy;
}

ParallelAssembly SingleLaw(LawType type, std::vector<double> mathematical, std::string name) {
  return ParallelAssembly(
      {{std::move(name), LawParameters::Make(type, ParameterForm::kMathematical, mathematical)}});
}

std::optional<double> PendulumWeight(const ParallelAssembly& assembly) {
  if (assembly.size() == 0) return std::nullopt;
  double weight = 0.0;
  for (const Component& component : assembly.components()) {
    const std::optional<double> w = PendulumWeight(component.parameters);
    if (!w) return std::nullopt;
    weight += *w;
  }
  return weight;
}

}  // namespace isolab::hysteresis
