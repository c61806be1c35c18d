// Sliders in series in two directions (series_arrangement.h for one): a spring ke in series with
// N elements under one force vector F, element k a rigid-plastic slider of circular (isotropic)
// strength f_k in parallel with the pendulum spring k_k and a rigid circular stop |z_k| <= d_k:
//   u = F / ke + sum_k z_k,   F = k_k z_k + f_k m_k + N_k e_k,   |z_k| <= d_k,
// m_k the unit slip direction (dz_k = lambda m_k, lambda >= 0: associative flow on the circle of
// friction), N_k >= 0 the stop's reaction along e_k = z_k / d_k, nonzero only on the stop. Each
// surface of a double or triple pendulum is one element (multiple_pendulum.h), so the bearing's
// surfaces slide in plan along their own directions and a slider against its restrainer ring slides
// around it.
//
// Update (backward Euler, as the other coupled laws): element k's end displacement minimises
//   psi_k(z) = k_k |z|^2 / 2 + f_k |z - z_k,n| - F . z   over |z| <= d_k,
// a strictly convex problem whose solution z_k(F) is a closed form or one scalar equation:
//   * stick, z = z_n, while the trial friction w = F - k z_n lies in the circle of radius f (at a
//     stop: while its part along the ring does, the stop taking the outward rest);
//   * slide inside the stop: z = z_n + (|w| - f) / k n, n = w / |w| (the radial return of a
//     force-driven slider), dz/dF = (n n^T + (1 - f/|w|)(I - n n^T)) / k;
//   * slide onto or along the stop ring: z = d e(theta), where the force less friction has no
//     part along the ring, (F - f m(theta)) . t(theta) = 0 (t the ring's tangent, m the chord
//     direction from z_n), the minimum of psi on the ring, solved by safeguarded Newton on theta;
//     dz/dF = -d t t^T / h_theta, h that equation.
// The bearing's force solves U(F) = u with U(F) = u_n + (F - F_n) / ke + sum_k (z_k(F) - z_k,n),
// the gradient of the strictly convex Phi(F) = |F - F_n|^2 / (2 ke) - F . (u - u_n) +
// sum_k max_z (F . (z - z_k,n) - psi_k(z) terms), so the solution is unique; it is found by Newton
// on U with a line search on Phi (Armijo), from the elastic trial F_n + ke (u - u_n), which is the
// answer when every element sticks. The Jacobian of U is H = I / ke + sum_k dz_k/dF, symmetric
// positive definite, and the consistent tangent is
//   d F / d u = H^-1,
// the exact derivative of the computed update. Along a line through the origin every element
// stays on it (its trial friction, slide and stop are along the line), so the 1-D law is
// reproduced to round-off. If Newton fails (it has not been seen to), the force is NaN and the
// integrator cuts the step.
//
// A slide that continues (plan_slip_decision.h): an element that slid into the committed state
// slides on when the force does not turn back against its friction, (F - F_n) . m_n >= 0, with zero
// travel for a zero increment, so the tangent there is the slide's (slip_direction.h).
//
// Energy: element k dissipates f_k |z_k - z_k,n| (its slider's work, with the backward-Euler slip
// direction); the recoverable energy is |F|^2 / (2 ke) + sum_k k_k |z_k|^2 / 2.
//
// State: 1 + N PlanLawStates. The first is the law's own (plan_law_state.h's layout, as every
// coupled law: force, slider = sum_k z_k, dissipated, accumulated_slip, x.slip = 1 while any
// element slides). Then one per element: slider = z_k (x and y), x.slip = 1 if it slid over the
// increment (zero travel included), y.slip = 1 if it is against its stop, x.accumulated_slip = its
// travel since rest; their dissipated energy is 0 (the law's own state carries the sum).
#pragma once

#include <array>
#include <span>

#include "isolab/hysteresis/plan_law_state.h"
#include "isolab/hysteresis/series_arrangement.h"

namespace isolab::hysteresis {

// The element variables of the plan form, gathered from and stored back to the element states.
struct PlanSeriesElementStates {
  std::array<Vec2, kMaxSeriesElements> z{};
  std::array<double, kMaxSeriesElements> travel{};
  std::array<bool, kMaxSeriesElements> sliding{};  // slid over the last increment
  std::array<bool, kMaxSeriesElements> at_stop{};  // against its stop ring
};

struct PlanSeriesArrangement {
  SeriesArrangement law;  // ke and the elements, as the 1-D kernel of the same law has them

  int state_slots() const { return law.state_slots(); }

  void Update(PlanLawStateView committed, std::span<const PlanLawState> committed_elements,
              const PlanLawInput& in, PlanLawStateSlot trial,
              std::span<PlanLawState> trial_elements, PlanLawResponse* response) const;

  double StoredEnergy(PlanLawStateView state, std::span<const PlanLawState> elements) const;

  // The same with the element states kept as LawState pairs in a flat array, element k's x at
  // 2k and y at 2k + 1 (a structure's state array, structure/structure.h).
  void UpdateFlat(PlanLawStateView committed, std::span<const LawState> committed_elements,
                  const PlanLawInput& in, PlanLawStateSlot trial,
                  std::span<LawState> trial_elements, PlanLawResponse* response) const;
  double StoredEnergyFlat(PlanLawStateView state, std::span<const LawState> elements) const;

  struct Step {
    Vec2 force;
    Mat2 stiffness;
    double dissipated = 0.0;  // over the increment
    double travel = 0.0;      // sum over elements of |dz_k| over the increment
    bool sliding = false;     // any element slid
    int iterations = 0;       // Newton iterations (0: the elastic trial held)
    PlanSeriesElementStates elements;
  };
  Step Solve(Vec2 u_n, Vec2 force_n, const PlanSeriesElementStates& elements_n, Vec2 u) const;

  PlanSeriesElementStates Gather(std::span<const PlanLawState> element_states) const;
  void Scatter(const PlanSeriesElementStates& elements,
               std::span<PlanLawState> element_states) const;
};

}  // namespace isolab::hysteresis
