// Rate forms of the friction pendulum and the lead-rubber bearing in plan, and the elastoplastic
// link they share with the parallel form.
#include <cmath>

#include "plan_rate_form_laws.h"

namespace isolab::hysteresis {

LinkSlip SlipOfLink(Vec2 u, Vec2 v, Vec2 slider) {
  const Vec2 link = u - slider;
  const double length = Norm(link);
  LinkSlip s;
  s.n = link / length;
  s.dn_du = (1.0 / length) * NormalProjector(s.n);
  const double nv = Dot(s.n, v);
  s.rate = nv * s.n;
  s.rate_v = Outer(s.n, s.n);
  s.rate_u = (Identity(nv) + Outer(s.n, v)) * s.dn_du;
  return s;
}

double LinkRoot(double reach, const PlanLawPhase& phase, Vec2 u, Vec2 v, Vec2 slider) {
  const Vec2 link = u - slider;
  return phase.slip == 0 ? reach - Norm(link) : Dot(link, v) / Norm(link);
}

void LinkSwitch(double reach, Vec2 u, Vec2 v, PlanPhaseSwitch* next) {
  const Vec2 link = u - VectorAt(next->q.data());
  const Vec2 n = link / Norm(link);
  PlanLawPhase& phase = next->phase;
  if (phase.slip == 0) {
    if (Dot(n, v) <= 0.0) return;  // reached the circle while already unloading: sticks
    phase.slip = 1;
    phase.direction = n;
  } else {
    phase.slip = 0;
    phase.direction = -n;  // slip ends where the velocity turns back
  }
  SetVectorAt(u - reach * n, next->q.data());
}

// ---- Friction pendulum: q = u_s; force W/R u + mu(|v|) W z_f. ----

PlanRateResponse Evaluate(const PlanFrictionPendulum& plan, const PlanLawPhase& phase, Vec2 u,
                          Vec2 v, const double* q, double) {
  const FrictionPendulum& law = plan.law;
  const double speed = Norm(v), uy = law.slider.uy, w = law.weight;
  // mu(|v|) itself, whatever the direction phase says (as in 1-D).
  const double mu = law.Friction(speed);
  const Vec2 slider = VectorAt(q);
  PlanRateResponse r;
  Vec2 zf;
  r.force_u = Identity(law.stiffness);
  if (phase.slip == 0) {
    zf = (u - slider) / uy;
    r.force_u = r.force_u + Identity(mu * w / uy);
    SetForceQ(&r, 0, Identity(-mu * w / uy));
  } else {
    const LinkSlip link = SlipOfLink(u, v, slider);
    zf = link.n;
    r.force_u = r.force_u + (mu * w) * link.dn_du;
    SetForceQ(&r, 0, (-mu * w) * link.dn_du);
    SetRate(&r, 0, link.rate);
    SetRateU(&r, 0, link.rate_u);
    SetRateV(&r, 0, link.rate_v);
    SetRateQ(&r, 0, 0, -link.rate_u);
  }
  r.force = law.stiffness * u + (mu * w) * zf;
  if (speed > 0.0) r.force_v = Outer((w * law.FrictionSlope(speed)) * zf, v / speed);
  // All the friction force's work is dissipated, as in the incremental law.
  r.hysteretic_power = mu * w * Dot(zf, v);
  return r;
}

void Roots(const PlanFrictionPendulum& plan, const PlanLawPhase& phase, Vec2 u, Vec2 v,
           const double* q, double* roots) {
  roots[0] = LinkRoot(plan.law.slider.uy, phase, u, v, VectorAt(q));
  roots[1] = phase.slip == 0 ? Dot(phase.direction, v) : 1.0;
}

void Switch(const PlanFrictionPendulum& plan, int root, Vec2 u, Vec2 v, PlanPhaseSwitch* next) {
  if (root == 0) {
    LinkSwitch(plan.law.slider.uy, u, v, next);
  } else {
    next->phase.direction = -next->phase.direction;
  }
}

// ---- Lead-rubber: q = (u_s, w); force Kd u + Qd(w) z_f; C dw/dt = Qd |du_s/dt| - C h(t) w. ----

PlanRateResponse Evaluate(const PlanLeadRubber& plan, const PlanLawPhase& phase, Vec2 u, Vec2 v,
                          const double* q, double t) {
  const LeadRubber& law = plan.law;
  const LeadCoreHeating& heating = law.heating;
  const double uy = law.slider.uy;
  const double temperature = heating.heats() ? q[2] : 0.0;
  const double strength = law.Strength(temperature);
  const Vec2 slider = VectorAt(q);
  PlanRateResponse r;
  Vec2 zf;
  LinkSlip link;
  r.force_u = Identity(law.kd);
  if (phase.slip == 0) {
    zf = (u - slider) / uy;
    r.force_u = r.force_u + Identity(strength / uy);
    SetForceQ(&r, 0, Identity(-strength / uy));
  } else {
    link = SlipOfLink(u, v, slider);
    zf = link.n;
    r.force_u = r.force_u + strength * link.dn_du;
    SetForceQ(&r, 0, -strength * link.dn_du);
    SetRate(&r, 0, link.rate);
    SetRateU(&r, 0, link.rate_u);
    SetRateV(&r, 0, link.rate_v);
    SetRateQ(&r, 0, 0, -link.rate_u);
    r.hysteretic_power = strength * Dot(link.n, v);
  }
  r.force = law.kd * u + strength * zf;
  if (!heating.heats()) return r;
  const double e2 = heating.e2, h = heating.ConductionRate(t);
  const Vec2 force_w = (-e2 * strength) * zf;
  r.force_q[0][2] = force_w.x;
  r.force_q[1][2] = force_w.y;
  double w_rate = -h * temperature;
  r.rate_q[2][2] = -h;
  if (phase.slip != 0) {
    const double heat = strength / heating.capacity;  // d w / d (slip)
    const double nv = Dot(link.n, v);
    w_rate += heat * nv;
    // d (n . v) / d u = v^T dn_du (dn_du is symmetric), and the opposite in u_s.
    const Vec2 d_nv_du = link.dn_du * v;
    r.rate_u[2] = {heat * d_nv_du.x, heat * d_nv_du.y};
    r.rate_v[2] = {heat * link.n.x, heat * link.n.y};
    r.rate_q[2][0] = -heat * d_nv_du.x;
    r.rate_q[2][1] = -heat * d_nv_du.y;
    r.rate_q[2][2] -= e2 * heat * nv;
  }
  r.rate[2] = w_rate;
  // Work rate less the rate of the stored Qd(w) D_y |z_f|^2 / 2: its z_f part cancels the stick
  // work; its temperature part, -E2 Qd dw/dt D_y |z_f|^2 / 2, is left (as in 1-D).
  r.hysteretic_power += 0.5 * e2 * strength * w_rate * uy * Dot(zf, zf);
  return r;
}

void Roots(const PlanLeadRubber& plan, const PlanLawPhase& phase, Vec2 u, Vec2 v, const double* q,
           double* roots) {
  roots[0] = LinkRoot(plan.law.slider.uy, phase, u, v, VectorAt(q));
}

void Switch(const PlanLeadRubber& plan, int, Vec2 u, Vec2 v, PlanPhaseSwitch* next) {
  LinkSwitch(plan.law.slider.uy, u, v, next);
}

}  // namespace isolab::hysteresis
