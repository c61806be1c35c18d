#include "isolab/hysteresis/plan_series_slider.h"

#include <cfloat>
#include <cmath>
#include <optional>

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
  // size (c ~ 1e17: a trial a unit in the last place outside the circle, as a zero increment
  // from a slipping state gives); this form has no cancellation and tends to its limit.
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
  // Newton's step -(ke I + B)^-1 R at xi, as Linearise's inverse applied to R but without
  // forming it: -A^-1 R + c (w.R) / (1 + c t.w) w.
  Vec2 NewtonStep(Vec2 xi, Vec2 residual) const {
    const double m = Norm(xi);
    const Mat2 a_inverse = Inverse(law.ke * Identity() + RadialStiffness(law.spring, xn + xi));
    const Vec2 t = Perpendicular(xi / m), w = a_inverse * t;
    const double c = law.fs / m;
    return (c * Dot(w, residual) / (1.0 + c * Dot(t, w))) * w - a_inverse * residual;
  }
};

// g_r(r) / r at r = |x|: the stiffness of g along x, exact for the radial return while g is linear.
double Secant(const TrilinearSpring& g, Vec2 x) {
  const double r = Norm(x);
  return r <= g.uc ? g.kh1 : g.kh2 + (g.kh1 - g.kh2) * g.uc / r;
}

// A Newton iterate whose residual is within this many units of round-off of the force scale has
// converged: the next step would be round-off itself. (The step test below catches an iteration
// whose residual cannot get that small.)
constexpr double kResidualRoundoff = 16.0 * DBL_EPSILON;

// The slip increment xi (fs > 0, the trial slider force outside the circle), or NaN if Newton
// fails.
Vec2 SolveSlip(const SlipEquation& eq, Vec2 trial_force) {
  const SeriesSlider& law = eq.law;
  const double trial_norm = Norm(trial_force);
  const Vec2 n0 = trial_force / trial_norm;
  // Start 1: the radial return with g's secant at x_n, exact while g stays on one linear piece.
  Vec2 xi = ((trial_norm - law.fs) / (law.ke + Secant(law.spring, eq.xn))) * n0;
  Vec2 residual = eq.Residual(xi);
  double residual_norm = Norm(residual);
  // Start 2: the slider force fs n0 exactly, x from the radial series solve: exact whenever x_n,
  // u and n0 lie on one line through the origin (motion along one axis).
  const Vec2 xi_line = SolveRadialInSeries(law.spring, law.ke, law.ke * eq.u - law.fs * n0) - eq.xn;
  if (Norm(xi_line) > 0.0) {
    const Vec2 residual_line = eq.Residual(xi_line);
    if (const double norm = Norm(residual_line); norm < residual_norm) {
      xi = xi_line;
      residual = residual_line;
      residual_norm = norm;
    }
  }
  const double length_scale = Norm(eq.u) + Norm(eq.xn);
  const double force_scale = law.fs + law.ke * length_scale + Norm(RadialForce(law.spring, eq.xn));
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    if (residual_norm <= kResidualRoundoff * force_scale) return xi;
    const Vec2 step = eq.NewtonStep(xi, residual);
    const double step_norm = Norm(step);
    if (!std::isfinite(step_norm)) break;
    if (step_norm <= 1e-13 * (length_scale + Norm(xi))) {
      // A trial force a unit in the last place outside the circle (a zero increment from a
      // slipping state) has a slip of round-off size that this last step may cancel exactly;
      // the slip is not zero (the trial is outside), so keep xi.
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
      if (const double norm = Norm(candidate_residual); norm < residual_norm) {
        xi = candidate;
        residual = candidate_residual;
        residual_norm = norm;
        decreased = true;
      }
    }
    // No decrease at all: |R| is at its round-off floor, or the iteration is lost.
    if (!decreased) return residual_norm <= 1e-10 * force_scale ? xi : Vec2{NAN, NAN};
  }
  return {NAN, NAN};
}

// ke in series with a spring of stiffness k.
double InSeries(double ke, double k) { return ke * k / (ke + k); }

// A tangent with principal axes n (unit) and its normal: along n n^T + across (I - n n^T).
Mat2 AxisTangent(Vec2 n, double along, double across) {
  return Identity(across) + (along - across) * Outer(n, n);
}

// A slip that ends with g on its inner segment, in closed form. There g(x) = kh1 x, so R = 0 of
// the header reads (ke + kh1) x + fs n = ke u with n along x - x_n: n is along
// w = ke u - (ke + kh1) x_n (the trial slider force when x_n is inside too) and
// x = (ke u - fs n) / (ke + kh1), the 1-D kernel's solution at |w|. When |w| > fs and that x is
// inside uc it is the solution (which is unique), exactly; otherwise the slip ends beyond uc
// (SlipEndingBeyond). Tangent: d n / d u = ke (I - n n^T) / |w|, so d f / d u of f = fs n + kh1 x
// is ke kh1 / (ke + kh1) along n (1-D: ke kh / (ke + kh)) and ke (fs ke + kh1 |w|) /
// ((ke + kh1) |w|) across, the consistent tangent of the header with c = fs / |xi|, written
// without |xi|, which may be round-off.
struct InnerSlip {
  Vec2 x, force;
  Mat2 stiffness;
};
std::optional<InnerSlip> SlipEndingInside(const SeriesSlider& law, Vec2 xn, Vec2 u,
                                          Vec2 trial_force) {
  const TrilinearSpring& g = law.spring;
  const double ke = law.ke, fs = law.fs;
  const Vec2 w = RadialSegment(g, xn) == 0 ? trial_force : ke * u - (ke + g.kh1) * xn;
  const double w_norm = Norm(w);
  if (!(w_norm > fs)) return std::nullopt;
  const Vec2 n = w / w_norm;
  const Vec2 x = SolveRadialSegmentInSeries(g, ke, ke * u - fs * n, 0);
  if (RadialSegment(g, x) != 0) return std::nullopt;
  const double across = ke * (fs * ke + g.kh1 * w_norm) / ((ke + g.kh1) * w_norm);
  return InnerSlip{x, fs * n + g.kh1 * x, AxisTangent(n, InSeries(ke, g.kh1), across)};
}

// A slip that ends with g beyond uc, as one scalar equation in the slip direction n. There
// g(x) = kh2 x + c x / |x| with c = (kh1 - kh2) uc, so R = 0 of the header reads
// (ke + kh2) x + c x / |x| = q := ke u - fs n: given n, x lies along q with
// |x| = (|q| - c) / (ke + kh2) (ke + kh2 > 0, and |x| > uc exactly when |q| > (ke + kh1) uc),
// and n must be the direction of x - x_n, i.e. F(n) = (x - x_n) x n = 0 with (x - x_n).n > 0.
// Newton on F, turning n by t along its normal p (n <- (n + t p) / |n + t p|, a turn of angle
// t to first order, so the iteration is Newton's in the angle), from the trial force's direction.
// A root with |x| > uc and (x - x_n).n > 0 solves R = 0, and the solution is unique, so this is
// it to round-off; if the iteration fails those checks the general solve decides.
struct BeyondSlip {
  Vec2 x, n;
};
constexpr int kMaxTurns = 20;
// Slips whose trial force exceeds the strength by less than this fraction go to the general
// solve, which keeps xi itself: x - x_n would lose a slip that small to round-off.
constexpr double kSmallSlip = 1e-6;
std::optional<BeyondSlip> SlipEndingBeyond(const SeriesSlider& law, Vec2 xn, Vec2 u, Vec2 n) {
  const TrilinearSpring& g = law.spring;
  const double a = law.ke + g.kh2, c = (g.kh1 - g.kh2) * g.uc;
  const Vec2 b = law.ke * u;
  // x(n) and, with dn = p, its derivative: q' = -fs p, |q|' = e.q', e' = (q' - |q|' e) / |q|,
  // |x|' = |q|' / a.
  const auto slider_at = [&](Vec2 n, Vec2* dx) {
    const Vec2 q = b - law.fs * n;
    const double q_norm = Norm(q);
    const Vec2 e = q / q_norm, dq = -law.fs * Perpendicular(n);
    const double r = (q_norm - c) / a, dq_norm = Dot(e, dq);
    if (dx) *dx = (dq_norm / a) * e + (r / q_norm) * (dq - dq_norm * e);
    return r * e;
  };
  for (int turn = 0; turn < kMaxTurns; ++turn) {
    Vec2 dx;
    const Vec2 d = slider_at(n, &dx) - xn, p = Perpendicular(n);
    // F = d x n = -d.p; F' = dx x n + d x p = -dx.p + d.n.
    const double f = -Dot(d, p), df = Dot(d, n) - Dot(dx, p);
    const double t = -f / df;
    if (!(df > 0.0) || !std::isfinite(t)) return std::nullopt;
    n = n + t * p;
    n = n / Norm(n);
    if (std::abs(t) <= 1e-13) {
      const Vec2 x = slider_at(n, nullptr);
      if (!(Norm(x) > g.uc) || !(Dot(x - xn, n) > 0.0)) return std::nullopt;
      return BeyondSlip{x, n};
    }
  }
  return std::nullopt;
}

// The tangent of x -> g(x(u)), x solving ke x + g(x) = ke u (no slider): Dg (ke I + Dg)^-1 ke.
// The solution x lies along u, and Dg(x) has the principal axes x / |x| (slope g_r') and its
// normal (secant g_r / r), so each axis is ke in series with its stiffness.
Mat2 SpringInSeriesTangent(double ke, const TrilinearSpring& g, Vec2 x) {
  if (RadialSegment(g, x) == 0) return Identity(InSeries(ke, g.kh1));
  const double r = Norm(x);
  return AxisTangent(x / r, InSeries(ke, g.kh2), InSeries(ke, Secant(g, x)));
}

}  // namespace

void PlanSeriesSlider::Update(PlanLawStateView committed, const PlanLawInput& in,
                              PlanLawStateSlot trial, PlanLawResponse* response) const {
  const double ke = law.ke, fs = law.fs;
  const Vec2 xn = Slider(committed);
  CoupledState next = Carried(committed);
  response->damping = {};
  Vec2 x;
  // No slider (it never sticks): ke in series with g, x from the radial series solve.
  if (!(fs > 0.0)) {
    next.slipping = true;
    next.slider = x = SolveRadialInSeries(law.spring, ke, ke * in.u);
    response->stiffness = SpringInSeriesTangent(ke, law.spring, x);
    response->force = next.force = RadialForce(law.spring, x);
    Store(in, next, trial);
    return;
  }
  const Vec2 spring_force = RadialForce(law.spring, xn);
  const Vec2 trial_force = ke * (in.u - xn) - spring_force;
  if (Sticks(committed, spring_force, in.u, trial_force)) {
    next.force = ke * (in.u - xn);
    response->force = next.force;
    response->stiffness = Identity(ke);
    Store(in, next, trial);
    return;
  }
  next.slipping = true;  // the committed phase of the next increment's decision
  if (const double trial_norm = Norm(trial_force); trial_norm <= fs) {
    // A continuing slip decided by the phase with its trial on or a round-off inside the circle.
    const SlipEquation eq{law, xn, in.u};
    const Vec2 n = trial_force / trial_norm;
    x = xn;
    response->stiffness = eq.LineariseAtZeroTravel(n).Tangent(ke);
    next.force = fs * n + spring_force;
  } else {
    double travel = 0.0;
    if (const std::optional<InnerSlip> inner = SlipEndingInside(law, xn, in.u, trial_force)) {
      x = inner->x;
      travel = Norm(x - xn);
      response->stiffness = inner->stiffness;
      next.force = inner->force;
    } else {
      const SlipEquation eq{law, xn, in.u};
      const std::optional<BeyondSlip> beyond =
          trial_norm > (1.0 + kSmallSlip) * fs
              ? SlipEndingBeyond(law, xn, in.u, trial_force / trial_norm)
              : std::nullopt;
      // xi itself, not x - x_n, whose round-off may be all of a slip this small.
      const Vec2 xi = beyond ? beyond->x - xn : SolveSlip(eq, trial_force);
      travel = Norm(xi);
      x = beyond ? beyond->x : xn + xi;
      response->stiffness = eq.Linearise(xi).Tangent(ke);
      next.force = beyond ? fs * beyond->n + RadialForce(law.spring, x)
                          : (fs / travel) * xi + RadialForce(law.spring, x);
    }
    next.dissipated += fs * travel;
    next.accumulated_slip += travel;
  }
  next.slider = x;
  response->force = next.force;
  Store(in, next, trial);
}

double PlanSeriesSlider::StoredEnergy(PlanLawStateView state) const {
  const Vec2 f = Force(state);
  return 0.5 * Dot(f, f) / law.ke + RadialEnergy(law.spring, Slider(state));
}

}  // namespace isolab::hysteresis
