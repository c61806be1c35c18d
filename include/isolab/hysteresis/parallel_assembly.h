// Any number of element laws acting in parallel on one deformation (an isolation layer, a
// bearing): the force is the sum of the components' forces. Laws are stored by value in one flat
// array; the assembly itself holds no state, callers own committed and trial state arrays (one
// LawState per component) and commit by swapping them.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "isolab/hysteresis/law_kernel.h"
#include "isolab/hysteresis/law_parameters.h"

namespace isolab::hysteresis {

struct Component {
  std::string name;
  LawParameters parameters;
};

// Sum over components of LawResponse.
struct AssemblyResponse {
  double force = 0.0;
  double stiffness = 0.0;
  double damping = 0.0;
};

class ParallelAssembly {
 public:
  ParallelAssembly() = default;
  explicit ParallelAssembly(std::vector<Component> components);

  std::size_t size() const { return kernels_.size(); }
  const std::vector<Component>& components() const { return components_; }
  const std::vector<LawKernel>& kernels() const { return kernels_; }

  // Trial of every component at `in` from `committed`, writing `trial` and per-component
  // `responses` (each of size()); returns the sums. Allocates nothing.
  AssemblyResponse Update(std::span<const LawState> committed, const LawInput& in,
                          std::span<LawState> trial, std::span<LawResponse> responses) const {
    AssemblyResponse total;
    for (std::size_t i = 0; i < kernels_.size(); ++i) {
      UpdateLaw(kernels_[i], committed[i], in, &trial[i], &responses[i]);
      total.force += responses[i].force;
      total.stiffness += responses[i].stiffness;
      total.damping += responses[i].damping;
    }
    return total;
  }

  // The summed stiffness and damping when every law's are the same at every state
  // (HasConstantTangent); nullopt otherwise. Its force is the force at rest (zero).
  std::optional<AssemblyResponse> ConstantTangent() const;

  // Recoverable energy and dissipated energy summed over components.
  double StoredEnergy(std::span<const LawState> states) const;
  double DissipatedEnergy(std::span<const LawState> states) const;

 private:
  std::vector<Component> components_;
  std::vector<LawKernel> kernels_;
};

// An assembly of one law in mathematical form, e.g. a linear story spring; throws
// InvalidParameter like LawParameters::Make.
ParallelAssembly SingleLaw(LawType type, std::vector<double> mathematical,
                           std::string name = "law");

}  // namespace isolab::hysteresis
