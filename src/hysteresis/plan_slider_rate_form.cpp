// Rate forms of the THM1 and THM2 families, the springs, the dashpot and Bouc-Wen in plan.
#include <cmath>

#include "isolab/hysteresis/radial_spring.h"
#include "plan_rate_form_laws.h"

namespace isolab::hysteresis {
namespace {

Vec2 Unit(Vec2 a) { return a / Norm(a); }

// ---- THM1 family: q = x (slider), force ke (u - x) = f_s + g(x). ----

Vec2 SliderForce(const SeriesSlider& law, const PlanLawPhase& phase, Vec2 u, Vec2 x) {
  return law.ke * (u - x) - RadialSegmentForce(law.spring, x, phase.segment);
}

}  // namespace

PlanRateResponse Evaluate(const PlanSeriesSlider& plan, const PlanLawPhase& phase, Vec2 u, Vec2 v,
                          const double* q, double) {
  const SeriesSlider& law = plan.law;
  const double ke = law.ke, fs = law.fs;
  const Vec2 x = VectorAt(q);
  PlanRateResponse r;
  if (phase.slip == 0) {
    r.force = ke * (u - x);
    r.force_u = Identity(ke);
    SetForceQ(&r, 0, Identity(-ke));
    return r;
  }
  const Vec2 g = RadialSegmentForce(law.spring, x, phase.segment);
  const Mat2 dg = RadialSegmentStiffness(law.spring, x, phase.segment);
  const Mat2 h = Identity(ke) + dg;
  if (fs == 0.0) {  // ke x + g(x) = ke u: dx/dt = ke H^-1 v
    const Mat2 h_inverse = Inverse(h);
    const Vec2 w = h_inverse * v;
    r.force = g;
    SetForceQ(&r, 0, dg);
    SetRate(&r, 0, ke * w);
    SetRateV(&r, 0, ke * h_inverse);
    // d (H^-1 v) / dx = -H^-1 (dDg/dx . w).
    SetRateQ(&r, 0, 0,
             -ke * (h_inverse * RadialStiffnessDerivative(law.spring, x, phase.segment, w)));
    return r;
  }
  const Vec2 slider_force = ke * (u - x) - g;
  const double magnitude = Norm(slider_force);
  const Vec2 n = slider_force / magnitude;
  const Mat2 dn = (1.0 / magnitude) * NormalProjector(n);  // d n / d f_s
  r.force = fs * n + g;
  r.force_u = (fs * ke) * dn;
  SetForceQ(&r, 0, -fs * (dn * h) + dg);
  // dx/dt = c (n . v) n, c = ke / (n^T H n), from d|f_s|/dt = 0 with dx/dt along n.
  const Vec2 hn = h * n;
  const double nhn = Dot(n, hn), c = ke / nhn, nv = Dot(n, v);
  const double lambda = c * nv;
  SetRate(&r, 0, lambda * n);
  SetRateV(&r, 0, c * Outer(n, n));
  // d rate / d n at fixed x, then through n(f_s(u, x)); and through H(x) at fixed n.
  const Mat2 d_rate_dn = (-2.0 * lambda / nhn) * Outer(n, hn) + c * Outer(n, v) + Identity(lambda);
  const Mat2 d_nhn_dx = Transpose(RadialStiffnessDerivative(law.spring, x, phase.segment, n));
  SetRateU(&r, 0, ke * (d_rate_dn * dn));
  SetRateQ(&r, 0, 0, -(d_rate_dn * (dn * h)) - (lambda / nhn) * Outer(n, d_nhn_dx * n));
  r.hysteretic_power = fs * lambda;
  return r;
}

void Roots(const PlanSeriesSlider& plan, const PlanLawPhase& phase, Vec2 u, Vec2 v, const double* q,
           double* roots) {
  const SeriesSlider& law = plan.law;
  const Vec2 x = VectorAt(q);
  if (law.fs == 0.0) {
    roots[0] = 1.0;
  } else if (phase.slip == 0) {
    roots[0] = law.fs - Norm(SliderForce(law, phase, u, x));
  } else {
    roots[0] = Dot(Unit(SliderForce(law, phase, u, x)), v);
  }
  roots[1] = law.spring.SegmentMargin(Norm(x), phase.segment);
}

void Switch(const PlanSeriesSlider& plan, int root, Vec2 u, Vec2 v, PlanPhaseSwitch* next) {
  const SeriesSlider& law = plan.law;
  const PlanLawPhase phase = next->phase;
  const Vec2 n = law.fs > 0.0 ? Unit(SliderForce(law, phase, u, VectorAt(next->q.data()))) : Vec2{};
  if (root == 0) {
    if (phase.slip == 0 && Dot(n, v) <= 0.0) return;  // reached fs while unloading: sticks
    next->phase.slip = phase.slip == 0 ? 1 : 0;
  } else {
    next->phase.segment = 1 - phase.segment;
  }
  // The slider that starts, ends or keeps slipping sits exactly on the surface ke (u - x) -
  // g(x) = fs n of the new segment; one that stays stuck keeps its place.
  if (next->phase.slip != 0 || phase.slip != 0) {
    SetVectorAt(SolveRadialSegmentInSeries(law.spring, law.ke, law.ke * u - law.fs * n,
                                           next->phase.segment),
                next->q.data());
  }
}

// ---- THM2 family: q = u_s, force kp (u - u_s) + g(u), |kp (u - u_s)| <= fs. ----

PlanRateResponse Evaluate(const PlanParallelSlider& plan, const PlanLawPhase& phase, Vec2 u, Vec2 v,
                          const double* q, double) {
  const ParallelSlider& law = plan.law;
  const Vec2 slider = VectorAt(q);
  PlanRateResponse r;
  const Vec2 g = RadialSegmentForce(law.spring, u, phase.segment);
  const Mat2 dg = RadialSegmentStiffness(law.spring, u, phase.segment);
  if (phase.slip == 0) {
    r.force = law.kp * (u - slider) + g;
    r.force_u = Identity(law.kp) + dg;
    SetForceQ(&r, 0, Identity(-law.kp));
    return r;
  }
  if (law.fs == 0.0) {  // no slider: u_s follows u
    r.force = g;
    r.force_u = dg;
    SetRate(&r, 0, v);
    SetRateV(&r, 0, Identity());
    return r;
  }
  const LinkSlip link = SlipOfLink(u, v, slider);
  r.force = law.fs * link.n + g;
  r.force_u = law.fs * link.dn_du + dg;
  SetForceQ(&r, 0, -law.fs * link.dn_du);
  SetRate(&r, 0, link.rate);
  SetRateU(&r, 0, link.rate_u);
  SetRateV(&r, 0, link.rate_v);
  SetRateQ(&r, 0, 0, -link.rate_u);
  r.hysteretic_power = law.fs * Dot(link.n, v);
  return r;
}

void Roots(const PlanParallelSlider& plan, const PlanLawPhase& phase, Vec2 u, Vec2 v,
           const double* q, double* roots) {
  const ParallelSlider& law = plan.law;
  roots[0] = law.fs == 0.0 ? 1.0 : LinkRoot(law.fs / law.kp, phase, u, v, VectorAt(q));
  roots[1] = law.spring.SegmentMargin(Norm(u), phase.segment);
}

void Switch(const PlanParallelSlider& plan, int root, Vec2 u, Vec2 v, PlanPhaseSwitch* next) {
  if (root == 0) {
    LinkSwitch(plan.law.fs / plan.law.kp, u, v, next);
  } else {
    next->phase.segment = 1 - next->phase.segment;
  }
}

// ---- Springs (one segment root), the dashpot and Bouc-Wen (no roots). ----

PlanRateResponse Evaluate(const PlanElasticSpring& plan, const PlanLawPhase& phase, Vec2 u, Vec2,
                          const double*, double) {
  PlanRateResponse r;
  r.force = RadialSegmentForce(plan.law.spring, u, phase.segment);
  r.force_u = RadialSegmentStiffness(plan.law.spring, u, phase.segment);
  return r;
}

void Roots(const PlanElasticSpring& plan, const PlanLawPhase& phase, Vec2 u, Vec2, const double*,
           double* roots) {
  roots[0] = plan.law.spring.SegmentMargin(Norm(u), phase.segment);
}

void Switch(const PlanElasticSpring&, int, Vec2, Vec2, PlanPhaseSwitch* next) {
  next->phase.segment = 1 - next->phase.segment;
}

PlanRateResponse Evaluate(const PlanDashpot& plan, const PlanLawPhase&, Vec2, Vec2 v, const double*,
                          double) {
  PlanRateResponse r;
  r.force = plan.law.c * v;
  r.force_v = Identity(plan.law.c);
  r.viscous_power = plan.law.c * Dot(v, v);
  return r;
}

// dz/dt = alpha v - beta T(z, v), continuous (not smooth) where z . v changes sign, as the law is
// defined; no event is needed for a continuous right-hand side.
PlanRateResponse Evaluate(const PlanBoucWen& plan, const PlanLawPhase&, Vec2, Vec2 v,
                          const double* q, double) {
  const BoucWen& law = plan.law;
  const Vec2 z = VectorAt(q);
  const PlanBoucWen::Term term = plan.Hysteretic(z, v, v);
  PlanRateResponse r;
  r.force = z;
  SetForceQ(&r, 0, Identity());
  const Vec2 rate = law.alpha * v - law.beta * term.value;
  SetRate(&r, 0, rate);
  SetRateV(&r, 0, Identity(law.alpha) - law.beta * term.d_d);
  SetRateQ(&r, 0, 0, -law.beta * term.d_z);
  // Work rate z . v less the rate of the stored |z|^2 / (2 alpha).
  r.hysteretic_power = Dot(z, v) - Dot(z, rate) / law.alpha;
  return r;
}

}  // namespace isolab::hysteresis
