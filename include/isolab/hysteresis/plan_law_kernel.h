// The closed set of bidirectional (plan) kernels, stored by value (law_kernel.h for one
// direction). Each coupled kernel carries its 1-D law's kernel as its parameters, so a plan law is
// built from the same validated LawParameters, the same keys and rules, as the 1-D law; an
// uncoupled pair carries two 1-D kernels.
//
// As in one direction (law_kernel.h), a plan law's state is PlanStateSlots(kernel) PlanLawStates:
// one for every law but the sliders in series (plan_series_arrangement.h), whose elements keep
// their own; the single-state calls are for the one-state laws.
#pragma once

#include <span>
#include <type_traits>
#include <variant>

#include "isolab/hysteresis/law_parameters.h"
#include "isolab/hysteresis/plan_bouc_wen.h"
#include "isolab/hysteresis/plan_dashpot.h"
#include "isolab/hysteresis/plan_elastic_spring.h"
#include "isolab/hysteresis/plan_friction_pendulum.h"
#include "isolab/hysteresis/plan_lead_rubber.h"
#include "isolab/hysteresis/plan_parallel_slider.h"
#include "isolab/hysteresis/plan_series_arrangement.h"
#include "isolab/hysteresis/plan_series_slider.h"
#include "isolab/hysteresis/uncoupled_pair.h"

namespace isolab::hysteresis {

using PlanLawKernel =
    std::variant<PlanSeriesSlider, PlanParallelSlider, PlanElasticSpring, PlanDashpot, PlanBoucWen,
                 PlanFrictionPendulum, PlanLeadRubber, UncoupledPair, PlanSeriesArrangement>;

template <class Kernel>
inline constexpr bool kPlanTakesSeveralStates = std::is_same_v<Kernel, PlanSeriesArrangement>;

// How many consecutive PlanLawStates the law's state takes (1 + elements for sliders in series).
inline int PlanStateSlots(const PlanLawKernel& kernel) {
  const auto* series = std::get_if<PlanSeriesArrangement>(&kernel);
  return series ? series->state_slots() : 1;
}

// Whether a law has a coupled bidirectional form: every law but degrading_bhm2 (whose damage
// has no 2-D energy bookkeeping yet); it can still act as an uncoupled pair.
bool HasCoupledForm(LawType type);

// The coupled form of a validated law (hdr_bearing is BHM2, so it comes as PlanParallelSlider).
// Throws std::invalid_argument naming the law when HasCoupledForm is false: a model reader checks
// HasCoupledForm first and reports its own located error.
PlanLawKernel CoupledKernel(const LawParameters& law);

// Two independent 1-D laws along x and y. Throws std::invalid_argument for a law whose state
// takes several LawStates (sliders in series): use its coupled form.
PlanLawKernel UncoupledKernel(const LawParameters& along_x, const LawParameters& along_y);

// A one-state law; a law of several states throws std::logic_error.
inline void UpdatePlanLaw(const PlanLawKernel& kernel, PlanLawStateView committed,
                          const PlanLawInput& in, PlanLawStateSlot trial,
                          PlanLawResponse* response) {
  std::visit(
      [&](const auto& law) {
        if constexpr (kPlanTakesSeveralStates<std::decay_t<decltype(law)>>) {
          SeveralStatesGivenOne();
        } else {
          law.Update(committed, in, trial, response);
        }
      },
      kernel);
}

// Any law: its own state and its further ones (PlanStateSlots - 1 of them; empty for a one-state
// law), wherever the caller keeps them.
inline void UpdatePlanLaw(const PlanLawKernel& kernel, PlanLawStateView committed,
                          std::span<const PlanLawState> committed_elements, const PlanLawInput& in,
                          PlanLawStateSlot trial, std::span<PlanLawState> trial_elements,
                          PlanLawResponse* response) {
  std::visit(
      [&](const auto& law) {
        if constexpr (kPlanTakesSeveralStates<std::decay_t<decltype(law)>>) {
          law.Update(committed, committed_elements, in, trial, trial_elements, response);
        } else {
          law.Update(committed, in, trial, response);
        }
      },
      kernel);
}

// A one-state law's recoverable energy; a law of several states throws std::logic_error.
inline double PlanStoredEnergy(const PlanLawKernel& kernel, PlanLawStateView state) {
  return std::visit(
      [&](const auto& law) -> double {
        if constexpr (kPlanTakesSeveralStates<std::decay_t<decltype(law)>>) {
          SeveralStatesGivenOne();
        } else {
          return law.StoredEnergy(state);
        }
      },
      kernel);
}

// For the plan assembly (law_kernel.h's UpdateLawInPlace): `committed` and `trial` are elements of
// PlanLawState arrays in which a law of several states finds its further ones at its
// law.elements_at.
inline void UpdatePlanLawInPlace(const PlanLawKernel& kernel, const PlanLawState& committed,
                                 const PlanLawInput& in, PlanLawState* trial,
                                 PlanLawResponse* response) {
  std::visit(
      [&](const auto& law) {
        if constexpr (kPlanTakesSeveralStates<std::decay_t<decltype(law)>>) {
          const auto count = static_cast<std::size_t>(law.law.count);
          law.Update(committed, std::span(&committed + law.law.elements_at, count), in, trial,
                     std::span(trial + law.law.elements_at, count), response);
        } else {
          law.Update(committed, in, trial, response);
        }
      },
      kernel);
}

inline double PlanStoredEnergyInPlace(const PlanLawKernel& kernel, const PlanLawState& state) {
  return std::visit(
      [&](const auto& law) -> double {
        if constexpr (kPlanTakesSeveralStates<std::decay_t<decltype(law)>>) {
          return law.StoredEnergy(state, std::span(&state + law.law.elements_at,
                                                   static_cast<std::size_t>(law.law.count)));
        } else {
          return law.StoredEnergy(state);
        }
      },
      kernel);
}

// Any law's recoverable energy, from its own state and its further ones.
inline double PlanStoredEnergy(const PlanLawKernel& kernel, PlanLawStateView state,
                               std::span<const PlanLawState> elements) {
  return std::visit(
      [&](const auto& law) -> double {
        if constexpr (kPlanTakesSeveralStates<std::decay_t<decltype(law)>>) {
          return law.StoredEnergy(state, elements);
        } else {
          return law.StoredEnergy(state);
        }
      },
      kernel);
}

// Whether the law's stiffness and damping are the same at every state (law_kernel.h): a linear
// spring, a dashpot, or an uncoupled pair of such.
bool HasConstantTangent(const PlanLawKernel& kernel);

// The part of Dissipated(state) that dashpots took (the rest is hysteretic), for the energy
// balance's split.
double PlanViscousEnergy(const PlanLawKernel& kernel, PlanLawStateView state);

}  // namespace isolab::hysteresis
