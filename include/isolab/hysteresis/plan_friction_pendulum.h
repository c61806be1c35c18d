// Friction pendulum in two directions (friction_pendulum.h for one; the biaxial friction of
// Constantinou, Mokha & Reinhorn 1990): the spherical surface's restoring force and the friction
// of the sliding interface, whose strength is a circle,
//   f = (W / R) u + mu(|v|) W z,   mu(|v|) = mu_fast - (mu_fast - mu_slow) exp(-a |v|),
// z the interface's variable (plan_unit_slider.h), the friction coefficient read at the
// RESULTANT sliding velocity |v|, not component by component. With constant friction it is BHM2
// in two directions exactly.
//
// Tangents: d f / d u = (W / R) I + mu W dz/du; d f / d v = W z mu'(|v|) (v / |v|)^T, rank one
// along the velocity, taken as 0 at v = 0 where |v| has no derivative. Energy as in 1-D: the
// recoverable energy is the pendulum's, W |u|^2 / (2R); the friction work W mu z_work, with mu the
// mean of its values at the increment's two ends, is all booked as dissipated.
#pragma once

#include "isolab/hysteresis/friction_pendulum.h"
#include "isolab/hysteresis/plan_law_state.h"
#include "isolab/hysteresis/plan_unit_slider.h"

namespace isolab::hysteresis {

struct PlanFrictionPendulum {
  FrictionPendulum law;

  void Update(PlanLawStateView committed, const PlanLawInput& in, PlanLawStateSlot trial,
              PlanLawResponse* response) const {
    const PlanUnitSlider interface { law.slider };
    const PlanUnitSlider::Step step =
        interface.Update(Slipping(committed), Displacement(committed), Slider(committed), in.u);
    const double speed = Norm(in.v);
    // mu and its slope share one exponential, as in 1-D.
    const double mu_v = law.FrictionSlope(speed);
    const double mu = law.constant() ? law.mu_fast
                                     : law.mu_fast - mu_v / law.rate -
                                           (speed == 0.0 ? law.mu_fast - law.mu_slow : 0.0);
    const double w = law.weight;
    CoupledState next;
    next.slider = step.slider;
    next.slipping = step.slipping;
    next.accumulated_slip = committed.x.accumulated_slip + step.travel;
    next.dissipated = committed.x.dissipated +
                      0.5 * (law.Friction(Norm(Velocity(committed))) + mu) * w * step.z_work;
    next.force = law.stiffness * in.u + (mu * w) * step.z;
    response->force = next.force;
    response->stiffness = Identity(law.stiffness) + (mu * w) * step.dz_du;
    response->damping = speed > 0.0 ? Outer((w * mu_v) * step.z, in.v / speed) : Mat2{};
    Store(in, next, trial);
  }

  double StoredEnergy(PlanLawStateView state) const {
    const Vec2 u = Displacement(state);
    return 0.5 * law.stiffness * Dot(u, u);
  }
};

}  // namespace isolab::hysteresis
