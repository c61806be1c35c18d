// Friction pendulum (single concave sliding surface; Zayas, Low & Mahin 1990) with the velocity-
// dependent friction of Constantinou, Mokha & Reinhorn (1990):
//   f = (W / R) u + mu(v) W z,   mu(v) = mu_fast - (mu_fast - mu_slow) exp(-a |v|),
// W the supported weight, R the radius of the sliding surface (isolated period 2 pi sqrt(R/g)),
// z the sliding interface's elastoplastic variable of yield displacement u_y (unit_slider.h). With
// mu_fast = mu_slow the law is BHM2 exactly: kh = W/R, fs = mu W, k0 = W/R + mu W / u_y, and a
// cycle of amplitude D dissipates 4 mu W (D - u_y).
//
// Exact update: z is a closed form in the end displacement (the friction force never feeds back
// on it), and mu is read at the trial velocity, so for a given v the force is piecewise linear in
// u and a trial is a pure function of (committed state, u, v). Tangents: d f / d u = W/R + mu W
// dz/du, and d f / d v = W z mu'(v) (LawResponse::damping), with mu'(v) = a (mu_fast - mu_slow)
// sign(v) exp(-a |v|), taken as 0 at v = 0 exactly where |v| has no derivative.
//
// Energy: the recoverable energy is the pendulum's, W u^2 / (2R) (the rise of the weight on the
// spherical surface); the friction force's work, W int mu z du, is all booked as dissipated. It
// includes the pre-slide deformation of the interface, at most mu W u_y / 2, which a reversal gives
// back; at constant mu the work over an increment is exact, and with mu(v) it takes the mean of mu
// at the increment's two ends, so work = stored + dissipated holds to round-off either way.
#pragma once

#include <cmath>

#include "isolab/hysteresis/law_state.h"
#include "isolab/hysteresis/unit_slider.h"

namespace isolab::hysteresis {

struct FrictionPendulum {
  double weight = 0.0;     // W (force), > 0
  double stiffness = 0.0;  // W / R (force/length), >= 0
  double mu_slow = 0.0;    // friction coefficient at v -> 0, >= 0
  double mu_fast = 0.0;    // friction coefficient at large v, >= 0
  double rate = 0.0;       // a (time/length), >= 0; 0 with mu_fast = mu_slow for constant friction
  UnitSlider slider;       // the sliding interface, yield displacement u_y

  // Constant friction skips the exponentials (the update then costs what BHM2's does).
  bool constant() const { return rate * (mu_fast - mu_slow) == 0.0; }
  double Friction(double v) const {
    return constant() ? mu_fast : mu_fast - (mu_fast - mu_slow) * std::exp(-rate * std::abs(v));
  }
  double FrictionSlope(double v) const {
    if (constant() || v == 0.0) return 0.0;
    const double slope = rate * (mu_fast - mu_slow) * std::exp(-rate * std::abs(v));
    return v > 0.0 ? slope : -slope;
  }

  void Update(const LawState& committed, const LawInput& in, LawState* trial,
              LawResponse* response) const {
    const UnitSlider::Step step =
        slider.Update(committed.u, committed.slider, committed.slip, in.u);
    // mu and its slope share one exponential.
    const double mu_v = FrictionSlope(in.v);
    const double mu =
        constant() ? mu_fast
                   : mu_fast - std::abs(mu_v) / rate - (in.v == 0.0 ? mu_fast - mu_slow : 0.0);
    trial->u = in.u;
    trial->v = in.v;
    trial->t = in.t;
    trial->slider = step.slider;
    trial->slip = step.slip;
    trial->accumulated_slip = committed.accumulated_slip + step.travel;
    trial->dissipated =
        committed.dissipated + 0.5 * (Friction(committed.v) + mu) * weight * step.z_work;
    trial->force = response->force = stiffness * in.u + mu * weight * step.z;
    response->stiffness = stiffness + mu * weight * step.dz_du;
    response->damping = weight * step.z * mu_v;
  }

  double StoredEnergy(const LawState& state) const { return 0.5 * stiffness * state.u * state.u; }
};

}  // namespace isolab::hysteresis
