// Lead-rubber bearing with the lead-core heating of Kalpakidis & Constantinou (2009, "Effects of
// heating on the behavior of lead-rubber bearings. I: Theory", J. Struct. Eng. 135(12)), in the
// form OpenSees' LeadRubberX implements (Kumar, Whittaker & Constantinou 2014):
//   f = Kd u + Qd(T) z,   Qd(T) = Qd0 exp(-E2 T),   E2 = 0.0069 /degC by default,
//   rho_L c_L h_L dT/dt = Qd(T) |du_s/dt| / A_L - (k_s T / a) (1/F(tau) + 1.274 (t_s / a)
//   tau^(-1/3)),
// T the lead core's temperature rise, z the lead's elastoplastic variable of yield displacement
// D_y = Qd0 / (Ku - Kd) (unit_slider.h, the elastoplastic limit of the paper's Bouc-Wen z, whose
// yield displacement Y it keeps fixed as the paper does), a and h_L the core's radius and height,
// A_L = pi a^2, t_s the total thickness of the steel shims, k_s and alpha_s the steel's
// conductivity and diffusivity, tau = alpha_s t / a^2 (t from the start of the run) and
//   F(tau) = 2 sqrt(tau/pi) - (tau/pi) [2 - tau/4 - (tau/4)^2 - (15/4)(tau/4)^3]      tau < 0.6
//   F(tau) = 8/(3 pi) - [1 - 1/(12 tau) + 1/(6 (4 tau)^2) - 1/(12 (4 tau)^3)] / (2 sqrt(pi tau)).
// The heat source is the lead's plastic work Qd |du_s/dt| (the paper writes sigma_YL Z dU/dt, which
// adds the recoverable elastic work of the pre-yield branch; both agree while the lead yields).
// Without conduction (k_s = 0) this is the paper's simplified adiabatic theory, whose exact
// solution is T(kappa) = ln(1 + E2 Qd0 kappa / C) / E2 with kappa the lead's accumulated slip and
// C = rho_L c_L A_L h_L the core's heat capacity. Without heating it is BHM2 (Kd = kh, Qd = fs,
// Ku = k0).
//
// Update over an increment from (u_n, t_n) to (u, t): z is exact (it never depends on T); the
// temperature is split (Strang) into conduction over the first half of the time step, the
// increment's slip heating the core adiabatically (exact: e^(E2 T) grows by E2 Qd0 travel / C),
// and conduction over the second half, each conduction half exact for the linear decay at the
// midpoint rate, exp(-h(t_mid) dt / 2). So the update is exact in the adiabatic limit (one call
// equals any number of sub-increments) and second order in dt with conduction. Energy: stored =
// Kd u^2 / 2 + Qd(T) D_y z^2 / 2; the slider's work over the increment is Qd(T_a) D_y (z^2 -
// z_n^2) / 2 + C (T_b - T_a) (its stick part at the temperature of the motion, its slip part the
// heat put in), and dissipated = work - change of stored energy, so work = stored + dissipated
// holds to round-off; conduction changing Qd at fixed z moves energy between the pre-yield
// branch and the dissipated account (at most Qd D_y / 2 a cycle).
//
// Conduction faster than the step (h dt > 1; a heat capacity far below lead's, which the model
// reader refuses, reaches it) defeats the split: the core cooled to the start temperature in each
// half step, so the force kept the cold strength while the adiabatic heating between took almost
// none of the slip's work (Newmark's energy balance was off by 68 % of the input, the loop's area
// 70 times the dissipation reported). There the heat balance is taken implicitly over the step,
// C (T_1 - T_n) = Qd(T_1) travel - C h dt T_1 (L-stable: T_1 goes to the quasi-steady
// temperature the slip rate holds), and the slip's work is the heat Qd(T_1) travel the force
// does, so force, temperature and dissipation agree for any heat capacity.
#pragma once

#include <cmath>

#include "isolab/hysteresis/law_state.h"
#include "isolab/hysteresis/unit_slider.h"

namespace isolab::hysteresis {

// The core's heat balance in model units (force, length, time, degC).
struct LeadCoreHeating {
  double capacity = 0.0;  // C = rho_L c_L A_L h_L (force*length/degC); 0: the law does not heat
  double e2 = 0.0069;     // E2 (1/degC), > 0
  // Conduction h(t) T with h(t) = conduction (1/F(tau) + shim_ratio tau^(-1/3)), tau =
  // diffusion t; conduction = 0 for the adiabatic theory.
  double conduction = 0.0;  // k_s / (a rho_L c_L h_L) (1/time)
  double shim_ratio = 0.0;  // 1.274 t_s / a
  double diffusion = 0.0;   // alpha_s / a^2 (1/time)

  bool heats() const { return capacity > 0.0; }
  bool conducts() const { return conduction > 0.0; }
  // h(t) (1/time); it grows as t^(-1/2) after the start, and is 0 at t <= 0 (where T = 0).
  double ConductionRate(double t) const;
  // exp(-h dt / 2), the decay of T over half of the step from t_n to t_n + dt.
  double HalfStepDecay(double t_n, double dt) const;

  // The core over an increment from temperature T_n at t_n to t, the lead slipping `travel`
  // (the update above; qd is Qd0).
  struct Step {
    double temperature = 0.0;  // T_1
    double strength = 0.0;     // Qd(T_1)
    double strength_n = 0.0;   // Qd(T_n)
    double strength_a = 0.0;   // Qd at which the increment's stick part is valued
    double heat = 0.0;         // the slip's work, put into the core (force*length)
    double softening = 0.0;    // -d Qd(T_1) / d travel while slipping (force/length)
  };
  Step Advance(double qd, double temperature_n, double t_n, double t, double travel) const;
};

struct LeadRubber {
  double kd = 0.0;    // post-yield (rubber) stiffness Kd (force/length), >= 0
  double qd = 0.0;    // characteristic strength Qd0 at the start temperature (force), > 0
  UnitSlider slider;  // the lead core, yield displacement D_y = Qd0 / (Ku - Kd)
  LeadCoreHeating heating;

  double Strength(double temperature) const {
    return heating.heats() ? qd * std::exp(-heating.e2 * temperature) : qd;
  }

  void Update(const LawState& committed, const LawInput& in, LawState* trial,
              LawResponse* response) const;

  double StoredEnergy(const LawState& state) const {
    const double z = slider.Z(state.u, state.slider);
    return 0.5 * kd * state.u * state.u + 0.5 * Strength(state.temperature) * slider.uy * z * z;
  }
};

}  // namespace isolab::hysteresis
