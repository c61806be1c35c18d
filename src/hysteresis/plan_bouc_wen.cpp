#include "isolab/hysteresis/plan_bouc_wen.h"

#include <cmath>

namespace isolab::hysteresis {
namespace {

double SignOr(double value, double fallback) {
  return value > 0.0 ? 1.0 : (value < 0.0 ? -1.0 : fallback);
}

}  // namespace

// T = m^nu q e with m = |z|, e = z / m, q = gamma |e.d| + delta e.d, so
//   dT/dz = m^(nu-1) [q (I + (nu - 2) e e^T) + q' e d^T],   dT/dd = m^nu q' e e^T,
// q' = gamma s + delta; both bounded as z -> 0 for nu >= 1.
PlanBoucWen::Term PlanBoucWen::Hysteretic(Vec2 z, Vec2 d, Vec2 sign_direction) const {
  const double nu = law.nu;
  const double m = Norm(z);
  Term term;
  Vec2 e;
  if (m > 0.0) {
    e = z / m;
  } else if (nu == 1.0 && Norm(d) > 0.0) {
    e = d / Norm(d);  // nu = 1: dT/dz has a limit at z = 0 along the way z leaves it
  } else {
    return term;  // T and its derivatives vanish at z = 0
  }
  const double ed = Dot(e, d);
  const double s = SignOr(ed, SignOr(Dot(e, sign_direction), 1.0));
  const double q = law.gamma * std::abs(ed) + law.delta * ed;
  const double q_slope = law.gamma * s + law.delta;
  const double m_nu1 = nu == 1.0 ? 1.0 : (nu == 2.0 ? m : std::pow(m, nu - 1.0));
  term.value = (m_nu1 * m * q) * e;
  term.d_z = m_nu1 * (q * (Identity() + (nu - 2.0) * Outer(e, e)) + q_slope * Outer(e, d));
  term.d_d = (m_nu1 * m * q_slope) * Outer(e, e);
  return term;
}

void PlanBoucWen::Update(PlanLawStateView committed, const PlanLawInput& in, PlanLawStateSlot trial,
                         PlanLawResponse* response) const {
  const double alpha = law.alpha, beta = law.beta;
  const Vec2 du = in.u - Displacement(committed);
  const Vec2 z0 = Force(committed);
  const Term t0 = Hysteretic(z0, du, in.v);
  const Vec2 g0 = alpha * du - beta * t0.value;
  Vec2 z = z0 + g0;  // explicit predictor
  bool converged = false;
  for (int iteration = 0; iteration < 50 && !converged; ++iteration) {
    const Term t = Hysteretic(z, du, in.v);
    const Vec2 residual = z - z0 - 0.5 * (g0 + alpha * du - beta * t.value);
    const Vec2 correction = Solve(Identity() + (0.5 * beta) * t.d_z, residual);
    z = z - correction;
    converged = Norm(correction) <= 1e-14 * (Norm(z) + alpha * Norm(du)) + 1e-300;
  }
  if (!converged || !std::isfinite(Norm(z))) z = {NAN, NAN};
  const Term t1 = Hysteretic(z, du, in.v);
  const Mat2 slope = 0.5 * ((Identity(alpha) - beta * t0.d_d) + (Identity(alpha) - beta * t1.d_d));
  response->force = z;
  response->stiffness = Inverse(Identity() + (0.5 * beta) * t1.d_z) * slope;
  response->damping = {};
  CoupledState next;
  next.force = z;
  const double stored_change = (Dot(z, z) - Dot(z0, z0)) / (2.0 * alpha);
  next.dissipated = committed.x.dissipated + 0.5 * Dot(z0 + z, du) - stored_change;
  Store(in, next, trial);
}

}  // namespace isolab::hysteresis
