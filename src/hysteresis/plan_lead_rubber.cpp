#include "isolab/hysteresis/plan_lead_rubber.h"

#include <cmath>

#include "isolab/hysteresis/plan_unit_slider.h"

namespace isolab::hysteresis {

// The 1-D update (lead_rubber.cpp) with z a vector; see there for each step's reasoning.
void PlanLeadRubber::Update(PlanLawStateView committed, const PlanLawInput& in,
                            PlanLawStateSlot trial, PlanLawResponse* response) const {
  const PlanUnitSlider core{law.slider};
  const Vec2 u_n = Displacement(committed);
  const PlanUnitSlider::Step step = core.Update(Slipping(committed), u_n, Slider(committed), in.u);
  const Vec2 z_n = core.Z(u_n, Slider(committed));
  CoupledState next;
  next.slider = step.slider;
  next.slipping = step.slipping;
  next.accumulated_slip = committed.x.accumulated_slip + step.travel;
  response->damping = {};
  const LeadCoreHeating& heating = law.heating;
  if (!heating.heats()) {
    next.dissipated = committed.x.dissipated + law.qd * step.travel;
    next.force = law.kd * in.u + law.qd * step.z;
    response->force = next.force;
    response->stiffness = Identity(law.kd) + law.qd * step.dz_du;
    Store(in, next, trial);
    return;
  }
  const LeadCoreHeating::Step heat_step =
      heating.Advance(law.qd, committed.x.temperature, committed.x.t, in.t, step.travel);
  next.temperature = heat_step.temperature;

  const double uy = law.slider.uy;
  const double zz = Dot(step.z, step.z), zz_n = Dot(z_n, z_n);
  const double work = 0.5 * heat_step.strength_a * uy * (zz - zz_n) + heat_step.heat;
  const double stored_change = 0.5 * uy * (heat_step.strength * zz - heat_step.strength_n * zz_n);
  next.dissipated = committed.x.dissipated + work - stored_change;
  next.force = law.kd * in.u + heat_step.strength * step.z;
  response->force = next.force;
  const double softening = step.travel > 0.0 ? heat_step.softening : 0.0;
  response->stiffness =
      Identity(law.kd) + heat_step.strength * step.dz_du - softening * Outer(step.z, step.z);
  Store(in, next, trial);
}

}  // namespace isolab::hysteresis
