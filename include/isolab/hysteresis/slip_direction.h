// The stick-or-slip decision of a rigid-plastic slider (characteristic force fs) over an
// increment du from its committed state, shared by every kernel with a slider.
//
// Why not simply |stick force| <= fs: a slider that slipped to reach its committed state sits on
// the yield surface, so over an increment of zero or of round-off size (a Newton iterate that
// repeats the committed displacement, a dof at rest) its stick force recomputed from the
// committed state equals +-fs up to round-off, and the test decides stick or slip by the sign of
// that round-off. The committed phase is known instead
// (LawState::slip), so the decision below is exact:
//   * committed slipping in direction s and s du >= 0: the slip goes on (the yield function only
//     grows), whatever the round-off;
//   * committed slipping and s du < 0: the stick force is s fs + k du exactly (the slider force
//     was s fs), which stays inside the surface until the reversal exceeds 2 fs / k;
//   * committed stuck: the kernel's own stick force, well inside the surface or well beyond it
//     except on a set of measure zero.
//
// The tangent at a corner. At du = 0 on the yield surface the update has two one-sided
// derivatives: the slip slope for s du > 0 and the stick slope for s du < 0. Both are exact
// derivatives of the update actually computed; the kernels return the slip side, the phase this
// decision gives at du = 0. A slider that slipped over one step nearly always slips over the
// next, so an iterate with no increment then takes the tangent of the step's own phase; when the
// motion reverses, the iterate lands in the stick phase and the next iterations use its (exact)
// stick slope. (Newmark's predictor carries the committed acceleration through the step, so its
// increment usually has a sign and the first two cases decide.)
#pragma once

#include <cmath>

namespace isolab::hysteresis {

// +1 or -1: the slider slips that way over the increment; 0: it sticks.
//   committed_slip  LawState::slip of the committed state (+-1 slipping, 0 stuck)
//   du              increment of the kernel's driving deformation from the committed state
//   stick_force     slider force if it sticks over the increment, from the committed state (read
//                   only when the committed state stuck)
//   stick_stiffness d stick_force / d du (force/length), > 0
//   fs              characteristic force (force), >= 0; 0: the slider never sticks
inline int SlipDirection(int committed_slip, double du, double stick_force, double stick_stiffness,
                         double fs) {
  if (committed_slip != 0) {
    if (committed_slip * du >= 0.0) return committed_slip;
    stick_force = committed_slip * fs + stick_stiffness * du;
  }
  if (fs > 0.0 && std::abs(stick_force) <= fs) return 0;
  return stick_force >= 0.0 ? 1 : -1;
}

}  // namespace isolab::hysteresis
