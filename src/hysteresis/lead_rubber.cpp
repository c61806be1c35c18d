#include "isolab/hysteresis/lead_rubber.h"

#include <algorithm>
#include <numbers>

namespace isolab::hysteresis {
namespace {

// Kalpakidis & Constantinou (2009)'s F(tau), the conduction through the end plates.
double EndPlateFunction(double tau) {
  constexpr double pi = std::numbers::pi;
  if (tau < 0.6) {
    const double q = tau / 4.0;
    return 2.0 * std::sqrt(tau / pi) - (tau / pi) * (2.0 - q - q * q - 3.75 * q * q * q);
  }
  const double x = 4.0 * tau;
  return 8.0 / (3.0 * pi) -
         (1.0 - 1.0 / (12.0 * tau) + 1.0 / (6.0 * x * x) - 1.0 / (12.0 * x * x * x)) /
             (2.0 * std::sqrt(pi * tau));
}

}  // namespace

double LeadCoreHeating::ConductionRate(double t) const {
  // h grows as t^(-1/2) towards the start, where T = 0: h T -> 0, so the start contributes 0.
  if (!(t > 0.0) || !conducts()) return 0.0;
  const double tau = diffusion * t;
  return conduction * (1.0 / EndPlateFunction(tau) + shim_ratio / std::cbrt(tau));
}

double LeadCoreHeating::HalfStepDecay(double t_n, double dt) const {
  if (!conducts() || !(dt > 0.0)) return 1.0;
  return std::exp(-0.5 * dt * ConductionRate(t_n + 0.5 * dt));
}

LeadCoreHeating::Step LeadCoreHeating::Advance(double qd, double temperature_n, double t_n,
                                               double t, double travel) const {
  Step step;
  const double dt = t - t_n;
  const double h = conducts() && dt > 0.0 ? ConductionRate(t_n + 0.5 * dt) : 0.0;
  if (h * dt > 1.0) {
    // Implicit: C k T - C T_n - Qd0 exp(-E2 T) travel = 0 with k = 1 + h dt, increasing and
    // concave in T, so Newton from the left of the root (T_n / k) climbs to it monotonically.
    const double k = 1.0 + h * dt;
    double temperature = temperature_n / k;
    for (int iteration = 0; iteration < 100; ++iteration) {
      const double strength = qd * std::exp(-e2 * temperature);
      const double g = capacity * (k * temperature - temperature_n) - strength * travel;
      const double slope = capacity * k + e2 * strength * travel;
      const double change = -g / slope;
      temperature += change;
      if (!(std::abs(change) > 1e-13 * (1.0 + temperature))) break;
    }
    step.temperature = temperature;
    step.strength = qd * std::exp(-e2 * temperature);
    step.strength_n = qd * std::exp(-e2 * temperature_n);
    step.strength_a = step.strength;
    step.heat = step.strength * travel;
    step.softening =
        e2 * step.strength * step.strength / (capacity * k + e2 * step.strength * travel);
    return step;
  }
  const double decay = HalfStepDecay(t_n, dt);
  const double t_a = temperature_n * decay;  // after the first half step's conduction
  const double w_a = std::exp(e2 * t_a);
  // After the increment's slip heats the core: w_b = w_a + E2 Qd0 travel / C, the rise taken as
  // log1p so that many small increments add up to one large one to round-off.
  const double growth = e2 * qd * travel / capacity;
  const double w_b = w_a + growth;
  const double rise = std::log1p(growth / w_a) / e2;
  step.temperature = (t_a + rise) * decay;
  step.strength_a = qd / w_a;
  step.strength = decay == 1.0 ? qd / w_b : qd * std::exp(-e2 * step.temperature);
  step.strength_n = decay == 1.0 ? step.strength_a : qd * std::exp(-e2 * temperature_n);
  step.heat = capacity * rise;
  // d T_1 / d travel = decay Qd0 / (C w_b), so the strength falls as E2 Qd(T_1) times that.
  step.softening = e2 * step.strength * decay * qd / (capacity * w_b);
  return step;
}

void LeadRubber::Update(const LawState& committed, const LawInput& in, LawState* trial,
                        LawResponse* response) const {
  const UnitSlider::Step step = slider.Update(committed.u, committed.slider, committed.slip, in.u);
  const double z_n = slider.Z(committed.u, committed.slider);
  trial->u = in.u;
  trial->v = in.v;
  trial->t = in.t;
  trial->slider = step.slider;
  trial->slip = step.slip;
  trial->accumulated_slip = committed.accumulated_slip + step.travel;
  response->damping = 0.0;
  if (!heating.heats()) {
    trial->temperature = 0.0;
    trial->dissipated = committed.dissipated + qd * step.travel;
    trial->force = response->force = kd * in.u + qd * step.z;
    response->stiffness = kd + qd * step.dz_du;
    return;
  }
  const LeadCoreHeating::Step core =
      heating.Advance(qd, committed.temperature, committed.t, in.t, step.travel);
  trial->temperature = core.temperature;

  const double uy = slider.uy;
  const double work = 0.5 * core.strength_a * uy * (step.z * step.z - z_n * z_n) + core.heat;
  const double stored_change =
      0.5 * uy * (core.strength * step.z * step.z - core.strength_n * z_n * z_n);
  trial->dissipated = committed.dissipated + work - stored_change;
  trial->force = response->force = kd * in.u + core.strength * step.z;
  // Slipping, d travel / d u = z = s, so the strength falls as d Qd / d u = -softening s; z s =
  // 1. Decided by the phase, not the travel, so that a slip going on from no increment has its
  // slip-side tangent.
  const double softening = step.slip != 0 ? core.softening : 0.0;
  response->stiffness = kd + core.strength * step.dz_du - softening;
}

}  // namespace isolab::hysteresis
