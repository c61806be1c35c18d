// The bidirectional laws in rate form (rate_form.h for one direction), for an integrator that
// carries each law's internal variables q as differential states (SUNDIALS IDA):
//   force = f(u, v, q; phase),   dq/dt = r(u, v, q, t; phase),
// with u, v, f 2-vectors and q up to four numbers. Between phase changes every law is smooth;
// the changes are events located by root functions, each positive while its phase holds and
// falling through zero where it ends, and SwitchPlanPhase puts q back on the new phase's surface.
//
//   law             q                      phases (roots)
//   THM1 family     slider x (2)           stick (|f_s| reaches fs, f_s = ke (u - x) - g(x)) /
//                                          slip (the loading rate n . v falls to 0, n = f_s/|f_s|);
//                                          segment of g at |x| (|x| crosses uc)
//   THM2 family     slider u_s (2)         stick (|kp (u - u_s)| reaches fs) / slip (n . v falls
//                                          to 0, n along u - u_s); segment of g at |u|
//   spring          -                      segment of g at |u|
//   dashpot         -                      -
//   Bouc-Wen        force z (2)            - (smooth but for |z . v|, which stays continuous)
//   friction        slider u_s (2)         stick (|u - u_s| reaches u_y) / slip (n . v falls to
//   pendulum                               0); while stuck, v . d for the side d of the velocity,
//                                          a restart where mu(|v|) has its kink if v passes 0
//   lead rubber     u_s (2) and, heating,  stick (|u - u_s| reaches D_y) / slip (n . v falls to 0)
//                   the core's rise w (1)
//   uncoupled pair  the x law's q, then    the x law's roots, then the y law's (rate_form.h)
//                   the y law's
//
// Slip rates, from the consistency of |f_s| = fs with flow along n:
//   THM1: dx/dt = ke (n . v) / (n^T H n) n,  H = ke I + Dg(x);  THM2 and the bearings: n (n . v);
// with fs = 0 (no slider) THM1 follows ke x + g(x) = ke u: dx/dt = ke H^-1 v. In slip the force is
// written fs n + g, exact on the slip surface; the slider's work rate is fs n . dq/dt (fs lambda),
// which is its dissipation while the phase holds and stays smooth past its end.
//
// The integrator's Jacobian takes force_u, force_v, force_q and rate_u, rate_v, rate_q as they
// are: each is the exact partial derivative of what EvaluatePlanRate computes. A plan structure
// maps an isolator's u = T q_structure as in plan_assembly.h and adds
// T^T force_u T, T^T force_q, rate_u T, ... to its fixed sparse pattern through precomputed slots,
// q's PlanInternalVariableCount rows and columns per law.
#pragma once

#include <array>

#include "isolab/hysteresis/plan_law_kernel.h"
#include "isolab/hysteresis/rate_form.h"

namespace isolab::hysteresis {

inline constexpr int kMaxPlanInternalVariables = 4;
inline constexpr int kMaxPlanPhaseRoots = 4;

// Which smooth branch of a plan law is active.
struct PlanLawPhase {
  int slip = 0;     // coupled laws: 0 the slider sticks, 1 it slips (always 1 when fs = 0)
  int segment = 0;  // coupled laws: segment of g at its argument's norm, 0 inside uc, 1 beyond
  Vec2 direction{1.0, 0.0};   // friction pendulum while stuck: the side the velocity is on
  LawPhase along_x, along_y;  // uncoupled pairs: each direction's phase
  bool operator==(const PlanLawPhase&) const = default;
};

// Force and internal-variable rates with their partial derivatives (zero where a law has none).
struct PlanRateResponse {
  using Row = std::array<double, 2>;
  using QRow = std::array<double, kMaxPlanInternalVariables>;
  Vec2 force;
  Mat2 force_u, force_v;
  std::array<QRow, 2> force_q{};                                  // d force_i / d q_k
  QRow rate{};                                                    // dq/dt
  std::array<Row, kMaxPlanInternalVariables> rate_u{}, rate_v{};  // d rate_k / d u_j, d v_j
  std::array<QRow, kMaxPlanInternalVariables> rate_q{};           // d rate_k / d q_l
  double hysteretic_power = 0.0;  // slider work rate; Bouc-Wen: z . v - d(|z|^2 / 2 alpha)/dt
  double viscous_power = 0.0;     // rate of dashpot dissipation, >= 0
};

using PlanInternalVariables = std::array<double, kMaxPlanInternalVariables>;

// Whether the law has a rate form in this contract (not for a pair with a degrading law,
// rate_form.h; sliders in series have theirs in plan_series_rate_form.h): the one-direction
// HasRateForm's overload, so that a slot's assembly of either kind is checked alike.
bool HasRateForm(const PlanLawKernel& kernel);
// How many internal variables q it carries (0..4) and how many root functions it has (0..4).
int PlanInternalVariableCount(const PlanLawKernel& kernel);
int PlanPhaseRootCount(const PlanLawKernel& kernel);
// The phase at rest (u = v = q = 0).
PlanLawPhase PlanRestPhase(const PlanLawKernel& kernel);

// q holds PlanInternalVariableCount(kernel) values; t is the time since the start of the run
// (read only by the lead core's conduction).
PlanRateResponse EvaluatePlanRate(const PlanLawKernel& kernel, const PlanLawPhase& phase, Vec2 u,
                                  Vec2 v, const double* q, double t);

// Writes PlanPhaseRootCount(kernel) root values, each positive while `phase` holds.
void PlanPhaseRoots(const PlanLawKernel& kernel, const PlanLawPhase& phase, Vec2 u, Vec2 v,
                    const double* q, double* roots);

// The phase after root `root` fell through zero at (u, v, q), and q on that phase's surface
// (variables the switch does not move are copied). A stick root reached while already unloading
// (n . v <= 0) leaves the slider stuck.
struct PlanPhaseSwitch {
  PlanLawPhase phase;
  PlanInternalVariables q{};
};
PlanPhaseSwitch SwitchPlanPhase(const PlanLawKernel& kernel, const PlanLawPhase& phase, int root,
                                Vec2 u, Vec2 v, const double* q);

// The law's state as the incremental laws store it (force, slider, temperature, deformation), so
// stored energy and outputs are computed by the same code for both integrators.
PlanLawState PlanRateFormState(const PlanLawKernel& kernel, const PlanLawPhase& phase, Vec2 u,
                               Vec2 v, const double* q, double t);

}  // namespace isolab::hysteresis
