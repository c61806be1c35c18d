// Sliders in series (Fenz & Constantinou 2008, "Modeling triple friction pendulum bearings for
// response-history analysis", Earthquake Spectra 24(4): a multiple pendulum bearing is a series of
// single-pendulum elements): a spring ke in series with N elements, every one under the same
// force F. Element k is a rigid-plastic slider of strength f_k in parallel with a spring k_k and a
// rigid stop at |z_k| = d_k, z_k its displacement:
//   u = F / ke + sum_k z_k,   F = k_k z_k + s_k (+ the stop's reaction),   |s_k| <= f_k,
// z_k moving only while |s_k| = f_k, in the direction of s_k, and never beyond +-d_k. The spring
// ke is the sliding interfaces' elastic deformation before any slides (the pre-slide displacement
// u_y of friction_pendulum.h), so the initial stiffness is finite; d_k = +inf means no stop.
//
// Exact update: over an increment du of one sign s the force changes monotonically in that
// direction (every element's displacement is a nondecreasing function of s F), so each element's
// response is a closed form of the end force alone,
//   z_k(F) = z_k,n                                      until s F reaches s (s f_k + k_k z_k,n),
//   z_k(F) = (F - s f_k) / k_k                          then (sliding),
//   z_k(F) = s d_k                                      once it reaches its stop,
// and u(F) = u_n + (F - F_n) / ke + sum_k (z_k(F) - z_k,n) is piecewise linear and strictly
// increasing in s F, with breakpoints known before the walk: where each element starts to slide
// and where it reaches its stop. The update walks those breakpoints in order to the segment that
// holds u and solves it: any increment, across any number of regime changes (one surface after
// another starting to slide, stops engaged, a reversal that unloads every slider first), lands on
// the exact piecewise-linear path, so one call equals any number of sub-increments. An element
// pressed against its stop stays there until the force has fallen by 2 f_k below where it was
// pushed in: a rigid-plastic slider against a rigid restrainer.
//
// Why the stop is rigid: it keeps the element's displacement bounded by its capacity exactly
// (|z_k| = d_k, not a stiff spring's approximation to it), so "capacity used" is a clean number
// and the update stays a clamp in force space; and the tangent stays finite, because ke (and any
// element not against its stop) stays in series: with every stop engaged the stiffness is ke.
//
// Tangent: d F / d u = 1 / (1/ke + sum over sliding elements not at a stop of 1/k_k), the slope of
// the segment the update ended on, so it is the exact derivative of the update. At a breakpoint
// (an increment of zero included) it is the slope of the segment before it in the direction of
// motion; an increment of zero from a state reached by sliding continues that slide
// (slip_direction.h: its elements start at once), so its tangent is the sliding one.
//
// Energy: an element dissipates f_k |z_k - z_k,n| over an increment; the recoverable energy is
// F^2 / (2 ke) + sum_k k_k z_k^2 / 2 (a rigid stop does no work); so work = stored + dissipated.
//
// State: the law takes 1 + N LawStates (StateSlots). The first is the law's own, as any law's: u,
// v, force F, slider = sum_k z_k (the displacement on the sliders, u - F / ke), accumulated_slip =
// the elements' total travel, dissipated, and slip = s if any element moved over the increment
// (0 if none). Then one per element: slider = z_k, slip = the sign it moved in over the increment
// (0: it stuck, or stayed against its stop), accumulated_slip = its travel since rest; their other
// fields are 0, dissipated included, so a sum of dissipated energy over all states counts each
// element's once (in the first state).
#pragma once

#include <array>
#include <cmath>
#include <span>

#include "isolab/hysteresis/law_state.h"

namespace isolab::hysteresis {

inline constexpr int kMaxSeriesElements = 4;

struct SeriesElement {
  double strength = 0.0;   // f_k (force), >= 0: the slider's characteristic force (mu W)
  double stiffness = 0.0;  // k_k (force/length), > 0: the spring in parallel (W / R)
  double stop = INFINITY;  // d_k (length), > 0: the rigid stop at |z_k| = d_k; +inf for none
};

// The element variables an update reads and writes, gathered from (and stored back to) the
// element states; the plan form and the rate forms use the same variables.
struct SeriesElementStates {
  std::array<double, kMaxSeriesElements> z{};       // z_k (length)
  std::array<double, kMaxSeriesElements> travel{};  // accumulated |dz_k| since rest (length)
  std::array<int, kMaxSeriesElements> slip{};       // sign moved over the last increment, or 0
};

struct SeriesArrangement {
  double ke = 0.0;  // series spring (force/length), > 0 and finite
  int count = 0;    // elements, 1..kMaxSeriesElements
  std::array<SeriesElement, kMaxSeriesElements> elements{};
  // Where the element states are in the caller's state array, counted from the law's own state:
  // 1 (right after it) in a block of state_slots() states; an assembly that keeps them after all
  // its components' own states sets its distance (parallel_assembly.h), so that its loop
  // dispatches this law as any other (UpdateLawInPlace, law_kernel.h).
  std::ptrdiff_t elements_at = 1;

  int state_slots() const { return 1 + count; }

  // committed, trial: the law's own states; committed_elements, trial_elements: the count
  // element states (see the header). Never throws.
  void Update(const LawState& committed, std::span<const LawState> committed_elements,
              const LawInput& in, LawState* trial, std::span<LawState> trial_elements,
              LawResponse* response) const;

  double StoredEnergy(const LawState& state, std::span<const LawState> elements) const;

  // The update on the element variables alone, from the committed displacement, force, direction
  // of the last slide (LawState::slip) and element variables to the displacement u.
  struct Step {
    double force = 0.0;
    double stiffness = 0.0;
    double dissipated = 0.0;  // over the increment
    double travel = 0.0;      // sum over elements of |dz_k|, over the increment
    int slip = 0;             // s if any element moved, else 0
    SeriesElementStates elements;
  };
  Step Solve(double u_n, double force_n, int slip_n, const SeriesElementStates& elements_n,
             double u) const;

  SeriesElementStates Gather(std::span<const LawState> element_states) const;
  void Scatter(const SeriesElementStates& elements, std::span<LawState> element_states) const;
};

}  // namespace isolab::hysteresis
