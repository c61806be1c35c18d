// Any number of element laws acting in parallel on one deformation (an isolation layer, a
// bearing): the force is the sum of the components' forces. Laws are stored by value in one flat
// array; the assembly itself holds no state, callers own committed and trial state arrays of
// state_size() LawStates and commit by swapping them.
//
// State layout: component i's own state is at index i, as when every law took one LawState (so a
// caller reads component i's force, slider or dissipated energy there, and its response at
// responses[i]); the further states of a law that takes several (sliders in series, law_kernel.h)
// follow all the components' own, component i's from ElementStatesOffset(i) (each such law knows
// where: UpdateLawInPlace, law_kernel.h), so the loop dispatches every law alike.
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
// A component's law (its x law, as for a bidirectional component: LawAlongX in plan_assembly.h).
inline const LawParameters& LawAlongX(const Component& component) { return component.parameters; }

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
  // LawStates the assembly's state takes, >= size().
  std::size_t state_size() const { return state_size_; }
  const std::vector<Component>& components() const { return components_; }
  const std::vector<LawKernel>& kernels() const { return kernels_; }

  // Where component i's further states start (StateSlots - 1 of them; none for one-state laws).
  std::size_t ElementStatesOffset(std::size_t i) const { return element_offsets_[i]; }
  // Component i's further states within an assembly's state array (empty for one-state laws).
  template <class State>
  std::span<State> ElementStates(std::size_t i, std::span<State> states) const {
    return states.subspan(element_offsets_[i], StateSlots(kernels_[i]) - 1);
  }

  // Trial of every component at `in` from `committed`, writing `trial` (each of state_size())
  // and per-component `responses` (at least size()); returns the sums. Allocates nothing.
  AssemblyResponse Update(std::span<const LawState> committed, const LawInput& in,
                          std::span<LawState> trial, std::span<LawResponse> responses) const {
    // Walked by pointers: the loop's cost does not depend on the size of a kernel.
    AssemblyResponse total;
    const LawState* from = committed.data();
    LawState* to = trial.data();
    LawResponse* response = responses.data();
    for (const LawKernel& kernel : kernels_) {
      UpdateLawInPlace(kernel, *from++, in, to++, response);
      total.force += response->force;
      total.stiffness += response->stiffness;
      total.damping += response->damping;
      ++response;
    }
    return total;
  }

  // The summed stiffness and damping when every law's are the same at every state
  // (HasConstantTangent); nullopt otherwise. Its force is the force at rest (zero).
  std::optional<AssemblyResponse> ConstantTangent() const;

  // Recoverable energy and dissipated energy summed over components (the first inline: a
  // structure sums it over its members at every step).
  double StoredEnergy(std::span<const LawState> states) const {
    double energy = 0.0;
    const LawState* state = states.data();
    for (const LawKernel& kernel : kernels_) energy += StoredEnergyInPlace(kernel, *state++);
    return energy;
  }
  double DissipatedEnergy(std::span<const LawState> states) const;

 private:
  std::vector<Component> components_;
  std::vector<LawKernel> kernels_;
  std::vector<std::size_t> element_offsets_;  // per component; state_size_ for one-state laws
  std::size_t state_size_ = 0;
};

// The weight W of an assembly whose every law is a friction pendulum (PendulumWeight; their sum,
// as they act in parallel); nullopt when any law is not, or there is none.
std::optional<double> PendulumWeight(const ParallelAssembly& assembly);

// An assembly of one law in mathematical form, e.g. a linear story spring; throws
// InvalidParameter like LawParameters::Make.
ParallelAssembly SingleLaw(LawType type, std::vector<double> mathematical,
                           std::string name = "law");

}  // namespace isolab::hysteresis
