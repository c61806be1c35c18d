// Lead-rubber bearing in two directions (lead_rubber.h for one, with the heating of Kalpakidis &
// Constantinou 2009):
//   f = Kd u + Qd(T) z,   Qd(T) = Qd0 exp(-E2 T),
// z the lead core's variable on a circle (plan_unit_slider.h) and the core heated by the
// RESULTANT slip: C dT/dt = Qd(T) |du_s/dt| - C h(t) T. The update is the 1-D one with the
// travel |u_s - u_s,n| of the circular return map: z exact, the temperature split (Strang) into
// half-step conduction, the increment's adiabatic heating (exact) and half-step conduction.
// Slipping, the strength falls with the travel, which grows with u along z: d f / d u = Kd I +
// Qd dz/du - E2 Qd decay Qd0 / (C w_b) z z^T (1-D: the same with z z^T = 1). Energy as in 1-D with
// z^2 read |z|^2, so work = stored + dissipated holds as there.
#pragma once

#include "isolab/hysteresis/lead_rubber.h"
#include "isolab/hysteresis/plan_law_state.h"

namespace isolab::hysteresis {

struct PlanLeadRubber {
  LeadRubber law;

  void Update(PlanLawStateView committed, const PlanLawInput& in, PlanLawStateSlot trial,
              PlanLawResponse* response) const;

  double StoredEnergy(PlanLawStateView state) const {
    const Vec2 u = Displacement(state);
    const Vec2 z = (u - Slider(state)) / law.slider.uy;
    return 0.5 * law.kd * Dot(u, u) +
           0.5 * law.Strength(state.x.temperature) * law.slider.uy * Dot(z, z);
  }
};

}  // namespace isolab::hysteresis
