// Isolator laws acting in parallel on one horizontal deformation in plan (parallel_assembly.h for
// one direction): a bearing, or an isolator position of a plan model. The force is the sum of the
// components' force vectors; laws are stored by value in one flat array of a closed variant
// (plan_law_kernel.h), dispatched with no virtual call; the assembly holds no state. Callers own
// the committed and trial state arrays (one PlanLawState per component) and commit by swapping.
//
// For a structure in plan (structure.h): an isolator at plan position (x_i, y_i) under a
// rigid floor with dofs q = (u_x, u_y, theta) about the floor's reference point deforms by
//   u = T q,   T = [1 0 -(y_i - y_0); 0 1 (x_i - x_0)]   (relative to the ground, or to the floor
// below with T for each), so the structure adds T^T f to its force vector and T^T (K + c_d D) T,
// with K = stiffness and D = damping of PlanResponse, to its tangent. Every entry of that 3x3 (or,
// between two floors, 6x6) block sits at a position fixed for the run: precompute its slots in the
// sparse pattern once (as structure.cpp does with SlotOf) and write through them each iteration.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "isolab/hysteresis/plan_law_kernel.h"

namespace isolab::hysteresis {

// One component: a coupled law (law_y empty), or an uncoupled pair, `law` along x and law_y
// along y.
struct PlanComponent {
  std::string name;
  LawParameters law;
  std::optional<LawParameters> law_y;
};
// A component's law along x (an uncoupled pair's x law; a coupled law's own).
inline const LawParameters& LawAlongX(const PlanComponent& component) { return component.law; }

// Sums over components of PlanLawResponse.
struct PlanResponse {
  Vec2 force;
  Mat2 stiffness;
  Mat2 damping;
};

class PlanAssembly {
 public:
  PlanAssembly() = default;
  // Throws std::invalid_argument for a coupled component whose law has no coupled form
  // (HasCoupledForm).
  explicit PlanAssembly(std::vector<PlanComponent> components);

  std::size_t size() const { return kernels_.size(); }
  // PlanLawStates the assembly's state takes, >= size(): component i's own at i, the further
  // states of sliders in series after all the components' own (parallel_assembly.h's layout).
  std::size_t state_size() const { return state_size_; }
  const std::vector<PlanComponent>& components() const { return components_; }
  const std::vector<PlanLawKernel>& kernels() const { return kernels_; }

  // Where component i's further states start (PlanStateSlots - 1 of them).
  std::size_t ElementStatesOffset(std::size_t i) const { return element_offsets_[i]; }
  template <class State>
  std::span<State> ElementStates(std::size_t i, std::span<State> states) const {
    return states.subspan(element_offsets_[i], PlanStateSlots(kernels_[i]) - 1);
  }

  // Trial of every component at `in` from `committed`, writing `trial` (each of state_size())
  // and per-component `responses` (at least size()); returns the sums. Allocates nothing.
  PlanResponse Update(std::span<const PlanLawState> committed, const PlanLawInput& in,
                      std::span<PlanLawState> trial, std::span<PlanLawResponse> responses) const {
    PlanResponse total;
    for (std::size_t i = 0; i < kernels_.size(); ++i) {
      UpdatePlanLawInPlace(kernels_[i], committed[i], in, &trial[i], &responses[i]);
      total.force = total.force + responses[i].force;
      total.stiffness = total.stiffness + responses[i].stiffness;
      total.damping = total.damping + responses[i].damping;
    }
    return total;
  }

  // The summed stiffness and damping when every law's are the same at every state
  // (HasConstantTangent); nullopt otherwise. Its force is the force at rest (zero).
  std::optional<PlanResponse> ConstantTangent() const;

  // Recoverable energy, and dissipated energy (all of it, and the dashpots' part), summed.
  double StoredEnergy(std::span<const PlanLawState> states) const;
  double DissipatedEnergy(std::span<const PlanLawState> states) const;
  double ViscousEnergy(std::span<const PlanLawState> states) const;

 private:
  std::vector<PlanComponent> components_;
  std::vector<PlanLawKernel> kernels_;
  std::vector<std::size_t> element_offsets_;  // per component; state_size_ for one-state laws
  std::size_t state_size_ = 0;
};

// The weight W of a plan assembly whose every law is a friction pendulum (their sum; an uncoupled
// pair is one bearing: its x law's); nullopt when any law is not, or there is none.
std::optional<double> PendulumWeight(const PlanAssembly& assembly);

}  // namespace isolab::hysteresis
