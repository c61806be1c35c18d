// Linear viscous dashpot in two directions, f = c v (dashpot.h for one). Its dissipated energy is
// the trapezoidal work (f_n + f) . (u - u_n) / 2, as in 1-D.
#pragma once

#include "isolab/hysteresis/dashpot.h"
#include "isolab/hysteresis/plan_law_state.h"

namespace isolab::hysteresis {

struct PlanDashpot {
  Dashpot law;

  void Update(PlanLawStateView committed, const PlanLawInput& in, PlanLawStateSlot trial,
              PlanLawResponse* response) const {
    CoupledState next;
    next.force = law.c * in.v;
    next.dissipated = committed.x.dissipated +
                      0.5 * Dot(Force(committed) + next.force, in.u - Displacement(committed));
    response->force = next.force;
    response->stiffness = {};
    response->damping = Identity(law.c);
    Store(in, next, trial);
  }

  double StoredEnergy(PlanLawStateView) const { return 0.0; }
};

}  // namespace isolab::hysteresis
