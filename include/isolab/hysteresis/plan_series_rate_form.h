// Sliders in series in plan (plan_series_arrangement.h) in rate form, for an integrator that
// carries the element displacements z_1..z_N (2 N numbers, z_k = (q[2k], q[2k + 1])) as
// differential states: plan_rate_form.h's contract with room for them (it has four; these laws
// take up to eight, and the rate-form responses of the other plan laws are left their size).
//
// Each element is in one of four modes: stuck inside its ring, sliding inside it, stuck against
// the ring, sliding round the ring (towards side * t, t = Perpendicular(e), e = z / |z|). The force
// is F = ke (u - sum_k z_k) in every phase, and the rate of u splits among ke and the sliding
// elements: with C_k the element's compliance while it slides,
//   inside:        C = m m^T / k,                m = (F - k z) / |F - k z| (its friction
//   direction), round the ring: C = (|z| / F.e) t t^T         (its friction along the ring, f side,
//   held), dF/dt = H^-1 v,   H = I / ke + sum_k C_k,   dz_k/dt = C_k dF/dt,
// from the consistency of |F - k z| = f inside and of (F - k z) . t = f side round the ring. Every
// partial derivative (force_u, force_q, rate_u, rate_v, rate_q) is exact, d(C_k w) / d(F, z_k)
// included (tests/hysteresis/plan_series_rate_form_test.cpp checks them against central
// differences).
//
// Two roots per element, each positive while its mode holds (2k and 2k + 1):
//   stuck inside:          f - |F - k z|            and 1;
//   sliding inside:        m . dF/dt (its loading)  and d - |z| (it reaches the ring);
//   stuck against the ring: f - |(F - k z) . t|     and (F - k z) . e (the ring's reaction);
//   sliding round the ring: side t . dF/dt          and (F - k z) . e.
// A switch moves the element to the mode the root leads to (a loading root touched while
// unloading leaves it stuck), puts a sliding element back on its friction circle with the force u
// gives and an element on the ring exactly on it, and switches with it any element whose event
// falls at the same time.
//
// For the merger (integrators/plan_rate_form_system.h): the law's internal variables are
// PlanSeriesInternalVariableCount(law) consecutive entries of the q block, its roots
// PlanSeriesPhaseRootCount(law) consecutive root functions switched together by one
// SwitchPlanSeriesPhase call with the law's slice of the roots found; force_q[i][j] goes to the
// force rows (u's x and y) at column q_j, rate_u/rate_v/rate_q[j] to row q_j, dense in the law's
// own block.
#pragma once

#include <array>
#include <span>

#include "isolab/hysteresis/plan_law_state.h"
#include "isolab/hysteresis/plan_series_arrangement.h"

namespace isolab::hysteresis {

inline constexpr int kMaxPlanSeriesVariables = 2 * kMaxSeriesElements;

enum class RingMode { kStuck, kSliding, kStuckOnRing, kSlidingOnRing };

struct PlanSeriesPhase {
  std::array<RingMode, kMaxSeriesElements> mode{};
  std::array<int, kMaxSeriesElements> side{};  // round the ring: +-1 along Perpendicular(e)
  bool operator==(const PlanSeriesPhase&) const = default;
};

struct PlanSeriesRateResponse {
  using QRow = std::array<double, kMaxPlanSeriesVariables>;
  Vec2 force;
  Mat2 force_u, force_v;
  std::array<QRow, 2> force_q{};  // d force_i / d q_j
  QRow rate{};                    // dq/dt
  std::array<std::array<double, 2>, kMaxPlanSeriesVariables> rate_u{}, rate_v{};
  std::array<QRow, kMaxPlanSeriesVariables> rate_q{};  // d rate_i / d q_j
  double hysteretic_power = 0.0;                       // sum over sliding elements of f m . dz/dt
};

inline int PlanSeriesInternalVariableCount(const SeriesArrangement& law) { return 2 * law.count; }
inline int PlanSeriesPhaseRootCount(const SeriesArrangement& law) { return 2 * law.count; }
inline PlanSeriesPhase PlanSeriesRestPhase(const SeriesArrangement&) { return {}; }

PlanSeriesRateResponse EvaluatePlanSeriesRate(const SeriesArrangement& law,
                                              const PlanSeriesPhase& phase, Vec2 u, Vec2 v,
                                              const double* q);
void PlanSeriesPhaseRoots(const SeriesArrangement& law, const PlanSeriesPhase& phase, Vec2 u,
                          Vec2 v, const double* q, double* roots);

struct PlanSeriesPhaseSwitch {
  PlanSeriesPhase phase;
  std::array<double, kMaxPlanSeriesVariables> q{};
};
// roots_found: PlanSeriesPhaseRootCount(law) entries, nonzero for a root that fell, all read
// against `phase`.
PlanSeriesPhaseSwitch SwitchPlanSeriesPhase(const SeriesArrangement& law,
                                            const PlanSeriesPhase& phase,
                                            std::span<const int> roots_found, Vec2 u, Vec2 v,
                                            const double* q);

// The law's state block (state_slots() PlanLawStates) as the incremental law writes it (its
// dissipated energy is the integrator's, the integral of hysteretic_power).
void PlanSeriesRateFormState(const SeriesArrangement& law, const PlanSeriesPhase& phase, Vec2 u,
                             Vec2 v, const double* q, std::span<PlanLawState> block);

}  // namespace isolab::hysteresis
