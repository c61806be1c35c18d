// Linear viscous dashpot, f = c v. Its dissipated energy is accumulated with the trapezoidal rule
// over the displacement increment, (f_n + f) (u - u_n) / 2, which is the work the average-
// acceleration Newmark scheme assigns to it; under a smooth imposed history it converges to the
// integral of c v^2 dt at second order.
#pragma once

#include "isolab/hysteresis/law_state.h"

namespace isolab::hysteresis {

struct Dashpot {
  double c = 0.0;  // damping coefficient (force*time/length), >= 0

  // The force at `in` alone: it depends on the rate only, never on the state.
  double Force(const LawInput& in) const { return c * in.v; }

  void Update(const LawState& committed, const LawInput& in, LawState* trial,
              LawResponse* response) const {
    trial->u = in.u;
    trial->v = in.v;
    trial->slider = 0.0;
    trial->force = response->force = Force(in);
    trial->dissipated =
        committed.dissipated + 0.5 * (committed.force + trial->force) * (in.u - committed.u);
    response->stiffness = 0.0;
    response->damping = c;
  }

  double StoredEnergy(const LawState&) const { return 0.0; }
};

}  // namespace isolab::hysteresis
