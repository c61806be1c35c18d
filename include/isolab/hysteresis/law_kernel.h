// The closed set of update kernels, stored by value. Every named law (law_parameters.h) compiles
// to one of these, so a parallel assembly is a flat array dispatched by a switch, with no heap
// object or virtual call per component.
//
// A law's state is StateSlots(kernel) consecutive LawStates: one for every law but the sliders in
// series (series_arrangement.h), whose elements each keep their own. The single-state calls below
// are for the one-state laws; the block calls take any law's whole state.
#pragma once

#include <cmath>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <variant>

#include "isolab/hysteresis/bouc_wen.h"
#include "isolab/hysteresis/dashpot.h"
#include "isolab/hysteresis/degrading_slider.h"
#include "isolab/hysteresis/elastic_spring.h"
#include "isolab/hysteresis/friction_pendulum.h"
#include "isolab/hysteresis/lead_rubber.h"
#include "isolab/hysteresis/parallel_slider.h"
#include "isolab/hysteresis/play_slider.h"
#include "isolab/hysteresis/series_arrangement.h"
#include "isolab/hysteresis/series_slider.h"

namespace isolab::hysteresis {

using LawKernel =
    std::variant<SeriesSlider, ParallelSlider, ElasticSpring, Dashpot, BoucWen, DegradingSlider,
                 FrictionPendulum, LeadRubber, PlaySlider, SeriesArrangement>;

// Whether a kernel's state takes more than one LawState.
template <class Kernel>
inline constexpr bool kTakesSeveralStates = std::is_same_v<Kernel, SeriesArrangement>;

[[noreturn]] inline void SeveralStatesGivenOne() {
  throw std::logic_error(
      "a law whose state takes several LawStates (sliders in series) was given one: pass its "
      "whole state block");
}

// How many consecutive LawStates the law's state takes (1 + elements for sliders in series).
inline int StateSlots(const LawKernel& kernel) {
  const auto* series = std::get_if<SeriesArrangement>(&kernel);
  return series ? series->state_slots() : 1;
}

// A one-state law; a law of several states throws std::logic_error.
inline void UpdateLaw(const LawKernel& kernel, const LawState& committed, const LawInput& in,
                      LawState* trial, LawResponse* response) {
  std::visit(
      [&](const auto& law) {
        if constexpr (kTakesSeveralStates<std::decay_t<decltype(law)>>) {
          SeveralStatesGivenOne();
        } else {
          law.Update(committed, in, trial, response);
        }
      },
      kernel);
}

// Any law, on its state block: `committed` and `trial` hold StateSlots(kernel) states each.
inline void UpdateLaw(const LawKernel& kernel, std::span<const LawState> committed,
                      const LawInput& in, std::span<LawState> trial, LawResponse* response) {
  std::visit(
      [&](const auto& law) {
        if constexpr (kTakesSeveralStates<std::decay_t<decltype(law)>>) {
          law.Update(committed[0], committed.subspan(1), in, &trial[0], trial.subspan(1), response);
        } else {
          law.Update(committed[0], in, &trial[0], response);
        }
      },
      kernel);
}

// A one-state law's recoverable energy; a law of several states throws std::logic_error.
inline double StoredEnergy(const LawKernel& kernel, const LawState& state) {
  return std::visit(
      [&](const auto& law) -> double {
        if constexpr (kTakesSeveralStates<std::decay_t<decltype(law)>>) {
          SeveralStatesGivenOne();
        } else {
          return law.StoredEnergy(state);
        }
      },
      kernel);
}

// For assemblies, which keep every law's own state at its component's index and a law's further
// states elsewhere in the same array: `committed` and `trial` are elements of state arrays in which
// a law of several states finds its further ones at its elements_at (series_arrangement.h). The
// dispatch is the single-state call's, so the assemblies' loops cost what they did before any law
// took several states.
inline void UpdateLawInPlace(const LawKernel& kernel, const LawState& committed, const LawInput& in,
                             LawState* trial, LawResponse* response) {
  std::visit(
      [&](const auto& law) {
        if constexpr (kTakesSeveralStates<std::decay_t<decltype(law)>>) {
          const auto count = static_cast<std::size_t>(law.count);
          law.Update(committed, std::span(&committed + law.elements_at, count), in, trial,
                     std::span(trial + law.elements_at, count), response);
        } else {
          law.Update(committed, in, trial, response);
        }
      },
      kernel);
}

inline double StoredEnergyInPlace(const LawKernel& kernel, const LawState& state) {
  return std::visit(
      [&](const auto& law) -> double {
        if constexpr (kTakesSeveralStates<std::decay_t<decltype(law)>>) {
          return law.StoredEnergy(
              state, std::span(&state + law.elements_at, static_cast<std::size_t>(law.count)));
        } else {
          return law.StoredEnergy(state);
        }
      },
      kernel);
}

// Any law's recoverable energy, from its state block.
inline double StoredEnergy(const LawKernel& kernel, std::span<const LawState> state) {
  return std::visit(
      [&](const auto& law) -> double {
        if constexpr (kTakesSeveralStates<std::decay_t<decltype(law)>>) {
          return law.StoredEnergy(state[0], state.subspan(1));
        } else {
          return law.StoredEnergy(state[0]);
        }
      },
      kernel);
}

// Whether the law's stiffness and damping are the same at every state (a linear spring, a
// dashpot), so a structure may assemble them once per step size instead of every iteration.
inline bool HasConstantTangent(const LawKernel& kernel) {
  if (const auto* elastic = std::get_if<ElasticSpring>(&kernel)) {
    return elastic->spring.kh1 == elastic->spring.kh2 || !std::isfinite(elastic->spring.uc);
  }
  return std::holds_alternative<Dashpot>(kernel);
}

}  // namespace isolab::hysteresis
