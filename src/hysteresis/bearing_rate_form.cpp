#include "bearing_rate_form.h"

#include <cmath>

namespace isolab::hysteresis {
namespace {

int SignOf(double x) { return x > 0.0 ? 1 : (x < 0.0 ? -1 : 0); }

// The slider's variable z_f = (u - u_s) / u_y while it sticks, s while it slips.
double SliderVariable(const UnitSlider& slider, const LawPhase& phase, double u, double z) {
  return phase.slip == 0 ? slider.Z(u, z) : phase.slip;
}

// Stick root and stick/slip switch shared by both laws: the slider sticks while |u - u_s| < u_y
// (for the friction pendulum: while the friction force mu(v) W z_f is below the strength mu(v) W,
// which, both scaling with mu(v), is the same event whatever the velocity, and stays defined for
// mu = 0); slip ends where s v falls to zero.
double StickSlipRoot(const UnitSlider& slider, const LawPhase& phase, double u, double v,
                     double z) {
  return phase.slip == 0 ? slider.uy - std::abs(u - z) : phase.slip * v;
}

PhaseSwitch StickSlipSwitch(const UnitSlider& slider, const LawPhase& phase, double u, double v,
                            double z) {
  PhaseSwitch next{phase, z};
  if (phase.slip == 0) {
    const int s = SignOf(u - z);
    if (s * v <= 0.0) return next;  // reached u_y while already unloading: still sticks
    next.phase.slip = s;
    next.phase.direction = s;
    next.z = u - s * slider.uy;
  } else {
    next.z = u - phase.slip * slider.uy;
    next.phase.slip = 0;
    next.phase.direction = -phase.slip;  // slip ends where v reverses
  }
  return next;
}

}  // namespace

// ---- Friction pendulum: z = u_s; force W/R u + mu(|v|) W z_f. ----

RateResponse Evaluate(const FrictionPendulum& law, const LawPhase& phase, double u, double v,
                      double z) {
  RateResponse r;
  // mu(|v|) itself, not its branch for phase.direction: the direction root restarts the
  // integrator at the kink of |v| where it can, but a sign change it cannot see (v leaving 0 at
  // the start of a run, where a root that starts at zero is inactive) must not put the law on
  // the wrong branch; the right-hand side stays continuous there, as Bouc-Wen's does.
  const double mu = law.Friction(v);
  const double mu_v = law.FrictionSlope(v);
  const double zf = SliderVariable(law.slider, phase, u, z);
  r.force = law.stiffness * u + mu * law.weight * zf;
  r.force_v = law.weight * zf * mu_v;
  r.force_u = law.stiffness;
  if (phase.slip == 0) {
    r.force_u += mu * law.weight / law.slider.uy;
    r.force_z = -mu * law.weight / law.slider.uy;
  } else {
    r.rate = v;
    r.rate_v = 1.0;
  }
  // All the friction force's work is dissipated, as in the incremental law.
  r.hysteretic_power = mu * law.weight * zf * v;
  return r;
}

void Roots(const FrictionPendulum& law, const LawPhase& phase, double u, double v, double z,
           double* roots) {
  roots[0] = StickSlipRoot(law.slider, phase, u, v, z);
  roots[1] = phase.slip == 0 ? phase.direction * v : 1.0;
}

PhaseSwitch Switch(const FrictionPendulum& law, const LawPhase& phase, int root, double u, double v,
                   double z) {
  if (root == 0) return StickSlipSwitch(law.slider, phase, u, v, z);
  PhaseSwitch next{phase, z};
  next.phase.direction = -phase.direction;
  return next;
}

// ---- Lead-rubber: z = u_s, w = T; force Kd u + Qd(T) z_f; C dT/dt = Qd |du_s/dt| - C h(t) T. --

RateResponse Evaluate(const LeadRubber& law, const LawPhase& phase, double u, double v, double z,
                      double w, double t) {
  RateResponse r;
  const double uy = law.slider.uy;
  const double strength = law.Strength(w);
  const double zf = SliderVariable(law.slider, phase, u, z);
  r.force = law.kd * u + strength * zf;
  r.force_u = law.kd;
  if (phase.slip == 0) {
    r.force_u += strength / uy;
    r.force_z = -strength / uy;
  } else {
    r.rate = v;
    r.rate_v = 1.0;
    r.hysteretic_power = strength * phase.slip * v;
  }
  const LeadCoreHeating& heating = law.heating;
  if (!heating.heats()) return r;
  const double e2 = heating.e2;
  const double h = heating.ConductionRate(t);
  r.force_w = -e2 * strength * zf;
  r.w_rate = -h * w;
  r.w_rate_w = -h;
  if (phase.slip != 0) {
    const double heat = strength * phase.slip / heating.capacity;  // d T / d u_s
    r.w_rate += heat * v;
    r.w_rate_v = heat;
    r.w_rate_w -= e2 * heat * v;
  }
  // Work rate less the rate of the stored Qd(T) D_y z_f^2 / 2: its z_f part cancels the stick
  // work exactly; its temperature part, -E2 Qd dT/dt D_y z_f^2 / 2, is left.
  r.hysteretic_power += 0.5 * e2 * strength * r.w_rate * uy * zf * zf;
  return r;
}

void Roots(const LeadRubber& law, const LawPhase& phase, double u, double v, double z,
           double* roots) {
  roots[0] = StickSlipRoot(law.slider, phase, u, v, z);
}

PhaseSwitch Switch(const LeadRubber& law, const LawPhase& phase, int, double u, double v,
                   double z) {
  return StickSlipSwitch(law.slider, phase, u, v, z);
}

}  // namespace isolab::hysteresis
