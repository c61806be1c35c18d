#include "isolab/hysteresis/parallel_assembly.h"

#include <vector>

namespace isolab::hysteresis {

ParallelAssembly::ParallelAssembly(std::vector<Component> components)
    : components_(std::move(components)) {
  kernels_.reserve(components_.size());
  for (const Component& component : components_) kernels_.push_back(component.parameters.Kernel());
}

std::optional<AssemblyResponse> ParallelAssembly::ConstantTangent() const {
  for (const LawKernel& kernel : kernels_) {
    if (!HasConstantTangent(kernel)) return std::nullopt;
  }
  const std::vector<LawState> rest(size());
  std::vector<LawState> trial(size());
  std::vector<LawResponse> responses(size());
  return Update(rest, {}, trial, responses);
}

double ParallelAssembly::StoredEnergy(std::span<const LawState> states) const {
  double energy = 0.0;
  for (std::size_t i = 0; i < kernels_.size(); ++i)
    energy += hysteresis::StoredEnergy(kernels_[i], states[i]);
  return energy;
}

double ParallelAssembly::DissipatedEnergy(std::span<const LawState> states) const {
  double energy = 0.0;
  for (const LawState& state : states) energy += state.dissipated;
  return energy;
}

ParallelAssembly SingleLaw(LawType type, std::vector<double> mathematical, std::string name) {
  return ParallelAssembly(
      {{std::move(name), LawParameters::Make(type, ParameterForm::kMathematical, mathematical)}});
}

}  // namespace isolab::hysteresis
