// The element laws in rate form, for an integrator that carries each law's internal variable z as
// a differential state (SUNDIALS IDA, integrators/ida.h) instead of updating it incrementally:
//   force = f(u, v, z; phase),   dz/dt = r(u, v, z; phase),
// where the phase selects one smooth branch of the piecewise-linear law. Between phase changes
// every law is smooth, so a variable-step integrator's error control is honest; the changes are
// events located by root functions, each positive while its phase holds and falling through zero
// where the phase ends.
//
//   law       z                      phases (roots)
//   THM1      slider u_h             stick (f_slider reaches +-fs) / slip s (s v falls to 0);
//                                     segment of g at u_h (u_h crosses +-uc)
//   THM2      slider u_s             stick (|kp (u - u_s)| reaches fs) / slip s (s v falls to 0);
//                                     segment of g at u (u crosses +-uc)
//   spring    -                      segment of g at u
//   dashpot   -                      -
//   Bouc-Wen  force z (smooth)       -
//   friction  slider u_s             stick (|u - u_s| reaches u_y, where the friction force
//   pendulum                          mu(v) W z reaches the strength mu(v) W) / slip s (s v falls
//                                     to 0); the sign of v while stuck (v falls through 0), since
//                                     mu(|v|) has a kink there
//   lead      slider u_s and, with   stick (|u - u_s| reaches D_y) / slip s (s v falls to 0)
//   rubber    heating, the core's
//             temperature rise w
//
// In a slip phase the force is written s fs + g(z) (THM1) or s fs + g(u) (THM2), which is exact
// on the slip surface and free of the k0 >> k1 cancellation in ke (u - u_h); at every phase change
// z is put back on the new phase's surface (SwitchPhase), so drift of the integrator's nonlinear
// solve never accumulates across events.
#pragma once

#include "isolab/hysteresis/law_kernel.h"

namespace isolab::hysteresis {

// Which smooth branch of a law is active.
struct LawPhase {
  int slip = 0;     // 0: the slider sticks; +-1: it slips in that direction (always slipping, with
                    // direction +1, when fs = 0)
  int segment = 0;  // segment of the trilinear spring g: -1 (below -uc), 0 (inside), +1 (above uc)
  int direction = 1;  // sign of v expected while stuck, for laws of |v| (friction pendulum): its
                      // root restarts the integrator where v changes sign
  bool operator==(const LawPhase&) const = default;
};

// Force and internal-variable rate on the active branch, with their partial derivatives (the
// consistent Jacobian of the rate form).
struct RateResponse {
  double force = 0.0, force_u = 0.0, force_v = 0.0, force_z = 0.0;
  double rate = 0.0, rate_u = 0.0, rate_v = 0.0, rate_z = 0.0;  // dz/dt; all 0 without z
  // A second internal variable w (the lead core's temperature rise): d force / dw, d(dz/dt)/dw,
  // and dw/dt with its partial derivatives; all 0 for laws without w.
  double force_w = 0.0, rate_w = 0.0;
  double w_rate = 0.0, w_rate_u = 0.0, w_rate_v = 0.0, w_rate_z = 0.0, w_rate_w = 0.0;
  double hysteretic_power = 0.0;  // slider work rate s fs dz/dt; Bouc-Wen: z v - d(z^2/2a)/dt
  double viscous_power = 0.0;     // rate of dashpot dissipation, >= 0
};

inline constexpr int kMaxPhaseRoots = 2;

// Whether the law has a rate form in this contract (the degrading BHM2 has none yet: the IDA path
// refuses it and the incremental laws run it; sliders in series have theirs in
// series_rate_form.h, a variable per element).
bool HasRateForm(const LawKernel& kernel);

// How many internal variables the law carries (0; 1: z; 2: z and w), and how many root
// functions it has (0..2).
inline constexpr int kMaxInternalVariables = 2;
int InternalVariableCount(const LawKernel& kernel);
int PhaseRootCount(const LawKernel& kernel);

// The phase at rest (u = v = z = 0).
LawPhase RestPhase(const LawKernel& kernel);

// w is the second internal variable (ignored by laws without one) and t the time since the start
// of the run (read only by the lead core's conduction).
RateResponse EvaluateRate(const LawKernel& kernel, const LawPhase& phase, double u, double v,
                          double z, double w = 0.0, double t = 0.0);

// Writes PhaseRootCount(kernel) root values, each positive while `phase` holds.
void PhaseRoots(const LawKernel& kernel, const LawPhase& phase, double u, double v, double z,
                double* roots);

// The phase after root `root` fell through zero at (u, v, z), and z on that phase's surface.
// A stick root reached while the deformation already unloads (s v <= 0) leaves the slider stuck.
struct PhaseSwitch {
  LawPhase phase;
  double z = 0.0;
};
PhaseSwitch SwitchPhase(const LawKernel& kernel, const LawPhase& phase, int root, double u,
                        double v, double z);

// The law's state (force, slider, deformation) as the incremental laws store it, so stored energy
// and outputs are computed by the same code for both integrators.
LawState RateFormState(const LawKernel& kernel, const LawPhase& phase, double u, double v, double z,
                       double w = 0.0, double t = 0.0);

}  // namespace isolab::hysteresis
