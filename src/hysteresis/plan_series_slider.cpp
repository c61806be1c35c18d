#include "isolab/hysteresis/plan_series_slider.h"

#include <cmath>

#include "isolab/hysteresis/radial_spring.h"

namespace isolab::hysteresis {
namespace {

constexpr int kMaxIterations = 50;
constexpr int kMaxHalvings = 40;

// The slip equation of the header, R(xi) = fs xi / |xi| - f_s(x_n + xi), with the slider force
// f_s(x) = ke (u - x) - g(x), and its Jacobian ke I + B.
struct SlipEquation {
  const SeriesSlider& law;
  Vec2 xn, u;

  Vec2 SliderForce(Vec2 x) const { return law.ke * (u - x) - RadialForce(law.spring, x); }
  Vec2 Residual(Vec2 xi) const { return (law.fs / Norm(xi)) * xi - SliderForce(xn + xi); }
  // The slip's linearisation: B = Dg(x) + c t t^T (c = fs / |xi|, t normal to xi) and
  // (ke I + B)^-1 by Sherman-Morrison on A = ke I + Dg(x): A^-1 - c w w^T / (1 + c t.w),
  // w = A^-1 t. Inverting ke I + B whole cancels catastrophically when the slip is of round-off
  // size (c ~ 1e17: a trial a unit in the last place outside the circle, as every Newmark
  // predictor from a slipping state is); this form has no cancellation and tends to its limit.
  struct Linearisation {
    Mat2 dg, inverse;  // Dg(x), (ke I + B)^-1
    Vec2 t, w;
    double c = INFINITY;
    // ke B (ke I + B)^-1, with c t t^T (ke I + B)^-1 = c / (1 + c t.w) t w^T: no cancellation
    // for ke >> Dg either (ke I - ke^2 (ke I + B)^-1 would lose the digits of Dg).
    // c = infinity (zero travel) takes the factor's limit 1 / t.w.
    Mat2 Tangent(double ke) const {
      const double factor = std::isinf(c) ? 1.0 / Dot(t, w) : c / (1.0 + c * Dot(t, w));
      return ke * (dg * inverse + factor * Outer(t, w));
    }
  };
  // The limit of Linearise(s n) as s -> 0+: a slip of zero travel along the unit n.
  Linearisation LineariseAtZeroTravel(Vec2 n) const {
    Linearisation l;
    l.dg = RadialStiffness(law.spring, xn);
    const Mat2 a_inverse = Inverse(law.ke * Identity() + l.dg);
    l.t = Perpendicular(n);
    l.w = a_inverse * l.t;
    l.inverse = a_inverse - (1.0 / Dot(l.t, l.w)) * Outer(l.w, l.w);
    return l;
  }
  Linearisation Linearise(Vec2 xi) const {
    const double m = Norm(xi);
    Linearisation l;
    l.dg = RadialStiffness(law.spring, xn + xi);
    const Mat2 a_inverse = Inverse(law.ke * Identity() + l.dg);
    l.t = Perpendicular(xi / m);
    l.w = a_inverse * l.t;
    l.c = law.fs / m;
    l.inverse = a_inverse - (l.c / (1.0 + l.c * Dot(l.t, l.w))) * Outer(l.w, l.w);
    return l;
  }
};

// g_r(r) / r at r = |x|: the stiffness of g along x, exact for the radial return while g is linear.
double Secant(const TrilinearSpring& g, Vec2 x) {
  const double r = Norm(x);
  return r <= g.uc ? g.kh1 : g.kh2 + (g.kh1 - g.kh2) * g.uc / r;
}

// The slip increment xi (fs > 0, the trial slider force outside the circle), or NaN if Newton
// fails.
Vec2 SolveSlip(const SlipEquation& eq, Vec2 trial_force) {
  const SeriesSlider& law = eq.law;
  const double trial_norm = Norm(trial_force);
  const Vec2 n0 = trial_force / trial_norm;
  // Start 1: the radial return with g's secant at x_n, exact while g stays on one linear piece.
  Vec2 xi = ((trial_norm - law.fs) / (law.ke + Secant(law.spring, eq.xn))) * n0;
  Vec2 residual = eq.Residual(xi);
  // Start 2: the slider force fs n0 exactly, x from the radial series solve: exact whenever x_n,
  // u and n0 lie on one line through the origin (motion along one axis).
  const Vec2 xi_line = SolveRadialInSeries(law.spring, law.ke, law.ke * eq.u - law.fs * n0) - eq.xn;
  if (Norm(xi_line) > 0.0) {
    const Vec2 residual_line = eq.Residual(xi_line);
    if (Norm(residual_line) < Norm(residual)) {
      xi = xi_line;
      residual = residual_line;
    }
  }
  const double length_scale = Norm(eq.u) + Norm(eq.xn);
  const double force_scale = law.fs + law.ke * length_scale + Norm(RadialForce(law.spring, eq.xn));
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    const Vec2 step = -(eq.Linearise(xi).inverse * residual);
    if (!std::isfinite(Norm(step))) break;
    if (Norm(step) <= 1e-13 * (length_scale + Norm(xi))) {
      // A trial force a unit in the last place outside the circle (a zero increment from a
      // slipping state, every Newmark predictor) has a slip of round-off size that this last
      // step may cancel exactly; the slip is not zero (the trial is outside), so keep xi.
      const Vec2 converged = xi + step;
      return Norm(converged) > 0.0 ? converged : xi;
    }
    // Backtracking on |R|: the Newton step is a descent direction of |R|^2 (J is nonsingular).
    double fraction = 1.0;
    bool decreased = false;
    for (int halving = 0; halving < kMaxHalvings && !decreased; ++halving, fraction *= 0.5) {
      const Vec2 candidate = xi + fraction * step;
      if (!(Norm(candidate) > 0.0)) continue;
      const Vec2 candidate_residual = eq.Residual(candidate);
      if (Norm(candidate_residual) < Norm(residual)) {
        xi = candidate;
        residual = candidate_residual;
        decreased = true;
      }
    }
    // No decrease at all: |R| is at its round-off floor, or the iteration is lost.
    if (!decreased) return Norm(residual) <= 1e-10 * force_scale ? xi : Vec2{NAN, NAN};
  }
  return {NAN, NAN};
}

}  // namespace

void PlanSeriesSlider::Update(const PlanLawState& committed, const PlanLawInput& in,
                              PlanLawState* trial, PlanLawResponse* response) const {
  const double ke = law.ke, fs = law.fs;
  const Vec2 xn = Slider(committed);
  const Vec2 trial_force = ke * (in.u - xn) - RadialForce(law.spring, xn);
  CoupledState next = Carried(committed);
  response->damping = {};
  if (Sticks(committed, in.u, trial_force)) {
    next.force = ke * (in.u - xn);
    response->force = next.force;
    response->stiffness = Identity(ke);
    Store(in, next, trial);
    return;
  }
  next.slipping = true;   // the committed phase of the next increment's decision
  Mat2 slider_stiffness;  // B of the header
  Vec2 x;
  if (fs == 0.0) {  // no slider: ke in series with g, x from the radial series solve
    x = SolveRadialInSeries(law.spring, ke, ke * in.u);
    const Mat2 dg = RadialStiffness(law.spring, x);
    response->stiffness = ke * (dg * Inverse(Identity(ke) + dg));
    next.force = RadialForce(law.spring, x);
  } else if (const double trial_norm = Norm(trial_force); trial_norm <= fs) {
    // A continuing slip decided by the phase with its trial on or a round-off inside the circle.
    const SlipEquation eq{law, xn, in.u};
    const Vec2 n = trial_force / trial_norm;
    x = xn;
    response->stiffness = eq.LineariseAtZeroTravel(n).Tangent(ke);
    next.force = fs * n + RadialForce(law.spring, xn);
  } else {
    const SlipEquation eq{law, xn, in.u};
    const Vec2 xi = SolveSlip(eq, trial_force);
    const double travel = Norm(xi);
    x = xn + xi;
    response->stiffness = eq.Linearise(xi).Tangent(ke);
    next.force = (fs / travel) * xi + RadialForce(law.spring, x);
    next.dissipated += fs * travel;
    next.accumulated_slip += travel;
  }
  next.slider = x;
  response->force = next.force;
  Store(in, next, trial);
}

double PlanSeriesSlider::StoredEnergy(const PlanLawState& state) const {
  const Vec2 f = Force(state);
  return 0.5 * Dot(f, f) / law.ke + RadialEnergy(law.spring, Slider(state));
}

}  // namespace isolab::hysteresis
