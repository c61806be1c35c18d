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
  const double e2 = heating.e2, qd = law.qd;
  const double decay = heating.HalfStepDecay(committed.x.t, in.t - committed.x.t);
  const double t_n = committed.x.temperature;
  const double t_a = t_n * decay;
  const double w_a = std::exp(e2 * t_a);
  const double strength_a = qd / w_a;
  const double growth = e2 * qd * step.travel / heating.capacity;
  const double w_b = w_a + growth;
  const double rise = std::log1p(growth / w_a) / e2;
  const double t_1 = (t_a + rise) * decay;
  const double strength = decay == 1.0 ? qd / w_b : law.Strength(t_1);
  const double strength_n = decay == 1.0 ? strength_a : law.Strength(t_n);
  next.temperature = t_1;

  const double uy = law.slider.uy;
  const double zz = Dot(step.z, step.z), zz_n = Dot(z_n, z_n);
  const double work = 0.5 * strength_a * uy * (zz - zz_n) + heating.capacity * rise;
  const double stored_change = 0.5 * uy * (strength * zz - strength_n * zz_n);
  next.dissipated = committed.x.dissipated + work - stored_change;
  next.force = law.kd * in.u + strength * step.z;
  response->force = next.force;
  const double softening =
      step.travel > 0.0 ? e2 * strength * decay * qd / (heating.capacity * w_b) : 0.0;
  response->stiffness =
      Identity(law.kd) + strength * step.dz_du - softening * Outer(step.z, step.z);
  Store(in, next, trial);
}

}  // namespace isolab::hysteresis
