// Sliders in series (series_arrangement.h) in rate form, for an integrator that carries their
// element displacements z_1..z_N as differential states (IDA): rate_form.h's contract with a
// variable per element, so N internal variables and N + 1 roots instead of rate_form.h's one or
// two (that contract is left as it is: its laws' evaluations do not grow).
//
// Phase: each element sticks (z_k constant, against its stop or not) or slides in the direction
// s of the motion; all that slide slide the same way. With S the sliding elements,
//   none slides:  F = ke (u - sum_k z_k),                           dz/dt = 0;
//   S slides:     F = s f_j + k_j z_j (j the first in S),            dz_k/dt = K v / k_k (k in S),
// 1 / K = 1 / ke + sum_{k in S} 1 / k_k: the rate of u splits among ke and the sliding springs. The
// force in slip is written on element j's slip surface, exact there and free of the cancellation
// in ke (u - sum z) when ke >> k; the switches put every sliding element back on its surface with
// the force that u gives (so drift of the integrator's solve never accumulates across events).
//
// Roots, each positive while the phase holds (root k for element k, root N for the motion):
//   element stuck inside its stop:  f_k - |F - k_k z_k|   (its friction reaches its strength);
//   stuck against its stop at +-d:  f_k +- (F - k_k z_k)   (the force falls enough to pull it
//   back); sliding:                        d_k - s z_k            (it reaches its stop; 1 without
//   one); motion:                         s v while any slides   (the motion reverses: all stick);
//   else 1.
// A stick root reached while the motion goes the other way (touching the friction while
// unloading) leaves the element stuck; the motion's root sticks every element. Strengths must be >
// 0 (every preset's are): an element of strength 0 has no stick phase.
//
// How an integrator indexes it (integrators/rate_form_system.h, for the merger): the law's
// internal variables are SeriesInternalVariableCount(law) consecutive entries of the z block
// (z_k at the law's first index + k), its roots SeriesPhaseRootCount(law) consecutive root
// functions, switched together by one SwitchSeriesPhase call with the law's slice of the roots
// found; force_z[k] goes to the v rows at column z_k, rate_u/rate_v/rate_z[k][l] to row z_k (the
// Jacobian of dz_k/dt is dense in the law's own block), hysteretic_power to the energy rate.
#pragma once

#include <array>
#include <span>

#include "isolab/hysteresis/law_state.h"
#include "isolab/hysteresis/series_arrangement.h"

namespace isolab::hysteresis {

struct SeriesPhase {
  std::array<int, kMaxSeriesElements> slip{};  // 0 stuck, +-1 sliding that way
  bool operator==(const SeriesPhase&) const = default;
};

struct SeriesRateResponse {
  double force = 0.0, force_u = 0.0, force_v = 0.0;
  std::array<double, kMaxSeriesElements> force_z{};  // d force / d z_k
  std::array<double, kMaxSeriesElements> rate{};     // dz_k / dt
  std::array<double, kMaxSeriesElements> rate_u{}, rate_v{};
  std::array<std::array<double, kMaxSeriesElements>, kMaxSeriesElements> rate_z{};  // [k][l]
  double hysteretic_power = 0.0;  // sum over sliding elements of s f_k dz_k/dt
};

inline int SeriesInternalVariableCount(const SeriesArrangement& law) { return law.count; }
inline int SeriesPhaseRootCount(const SeriesArrangement& law) { return law.count + 1; }
// At rest every element sticks.
inline SeriesPhase SeriesRestPhase(const SeriesArrangement&) { return {}; }

// z holds SeriesInternalVariableCount(law) values.
SeriesRateResponse EvaluateSeriesRate(const SeriesArrangement& law, const SeriesPhase& phase,
                                      double u, double v, const double* z);
// Writes SeriesPhaseRootCount(law) roots, each positive while `phase` holds.
void SeriesPhaseRoots(const SeriesArrangement& law, const SeriesPhase& phase, double u, double v,
                      const double* z, double* roots);

struct SeriesPhaseSwitch {
  SeriesPhase phase;
  std::array<double, kMaxSeriesElements> z{};
};
// The phase after the roots flagged in roots_found (SeriesPhaseRootCount(law) entries, nonzero
// for a root that fell through zero, as IDAGetRootInfo reports them, all of one event) fell at
// (u, v, z), and z on its surfaces. Every root is read against `phase`, the phase it was computed
// in; events that fall together but were not reported (two equal surfaces) switch too.
SeriesPhaseSwitch SwitchSeriesPhase(const SeriesArrangement& law, const SeriesPhase& phase,
                                    std::span<const int> roots_found, double u, double v,
                                    const double* z);

// The law's state block (state_slots() LawStates) as the incremental law writes it, so outputs,
// stored energy and the regime (multiple_pendulum.h) come from the same code for both
// integrators. Dissipated energy is the integrator's (the integral of hysteretic_power).
void SeriesRateFormState(const SeriesArrangement& law, const SeriesPhase& phase, double u, double v,
                         const double* z, std::span<LawState> block);

}  // namespace isolab::hysteresis
