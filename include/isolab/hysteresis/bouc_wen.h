// Bouc-Wen smooth hysteresis (Bouc 1967, Wen 1976), the law peer tools use for isolators and the
// one of the Noel & Schoukens (2016) hysteretic benchmark. The force is the hysteretic variable,
//   f = z,   dz/dt = alpha du/dt - beta (gamma |du/dt| |z|^(nu-1) z + delta du/dt |z|^nu),
// which is rate-independent: over an increment du of sign s,
//   dz/du = g(z) = alpha - beta (gamma s |z|^(nu-1) z + delta |z|^nu).
// Integrated implicitly with the trapezoidal rule, z1 = z0 + du (g(z0) + g(z1)) / 2, solved by
// scalar Newton to round-off, so it is second order in the increment; the tangent is the exact
// derivative of that discrete update. Stored energy z^2 / (2 alpha); dissipated energy is the
// trapezoidal work (z0 + z1) du / 2 less the change in stored energy. If the local Newton
// iteration fails (an increment so large that 1 - du g'(z)/2 vanishes), the force is NaN: the
// global Newton iteration then fails and the integrator cuts the step.
#pragma once

#include <cmath>

#include "isolab/hysteresis/law_state.h"

namespace isolab::hysteresis {

struct BoucWen {
  double alpha = 0.0;  // initial stiffness (force/length), > 0
  double beta = 0.0;   // (force^(1-nu)/length), >= 0
  double gamma = 0.0;  // shape
  double delta = 0.0;  // shape (written A or beta' elsewhere)
  double nu = 1.0;     // smoothness, >= 1

  double Slope(double z, double s) const {
    const double magnitude = std::abs(z);
    const double power = nu == 1.0 ? magnitude : std::pow(magnitude, nu);
    const double sign = z > 0.0 ? 1.0 : (z < 0.0 ? -1.0 : 0.0);
    return alpha - beta * (gamma * s * sign + delta) * power;
  }
  double SlopeDerivative(double z, double s) const {
    const double magnitude = std::abs(z);
    const double sign = z > 0.0 ? 1.0 : (z < 0.0 ? -1.0 : 0.0);
    const double power = nu == 1.0 ? 1.0 : nu * std::pow(magnitude, nu - 1.0);
    return -beta * power * (gamma * s + delta * sign);
  }

  void Update(const LawState& committed, const LawInput& in, LawState* trial,
              LawResponse* response) const {
    const double du = in.u - committed.u;
    // Direction of the increment; with no increment (a step from rest), the trial velocity's.
    const double s = du > 0.0 ? 1.0 : (du < 0.0 ? -1.0 : (in.v < 0.0 ? -1.0 : 1.0));
    const double z0 = committed.force;
    const double g0 = Slope(z0, s);
    double z = z0 + du * g0;  // explicit predictor
    double derivative = 1.0;
    bool converged = false;
    for (int iteration = 0; iteration < 50 && !converged; ++iteration) {
      const double residual = z - z0 - 0.5 * du * (g0 + Slope(z, s));
      derivative = 1.0 - 0.5 * du * SlopeDerivative(z, s);
      const double correction = residual / derivative;
      z -= correction;
      converged = std::abs(correction) <= 1e-14 * (std::abs(z) + alpha * std::abs(du)) + 1e-300;
    }
    if (!converged || !std::isfinite(z)) z = NAN;
    derivative = 1.0 - 0.5 * du * SlopeDerivative(z, s);
    trial->u = in.u;
    trial->v = in.v;
    trial->slider = 0.0;
    trial->force = response->force = z;
    const double stored_change = (z * z - z0 * z0) / (2.0 * alpha);
    trial->dissipated = committed.dissipated + 0.5 * (z0 + z) * du - stored_change;
    // dz/du of the discrete update: (g0 + g(z)) / 2 + du/2 g'(z) dz/du.
    response->stiffness = 0.5 * (g0 + Slope(z, s)) / derivative;
    response->damping = 0.0;
  }

  double StoredEnergy(const LawState& state) const {
    return state.force * state.force / (2.0 * alpha);
  }
};

}  // namespace isolab::hysteresis
