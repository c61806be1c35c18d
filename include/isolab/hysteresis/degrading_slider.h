// Degrading BHM2 kernel: the BHM2 element (parallel_slider.h with a linear spring) whose force is
// scaled by a damage factor that falls with the slider's accumulated slip kappa, the scragging /
// Mullins softening of filled rubber (strength and stiffness of a virgin bearing drop over its
// first cycles and settle; Cardone & Gesualdi 2012, Grant et al. 2004 model it with damage
// driven by accumulated deformation):
//   f = phi(kappa) [kp (u - u_s) + kh u],   |kp (u - u_s)| <= fs,   kappa = int |du_s|,
//   phi(kappa) = 1 - loss (1 - exp(-kappa / slip_scale)),            0 <= loss < 1.
// The undamaged part is BHM2 exactly (so loss = 0 is BHM2), yielding at uy = fs / kp whatever
// the damage; both strength and stiffness scale by phi, which never recovers.
//
// Exact update: the slider moves as in BHM2 (closed form in the end displacement, the stick or
// slip decision of slip_direction.h) and kappa grows by its travel, so phi follows exactly. Energy
// dissipated = work - stored energy, with the work over the slip integrated in closed form (phi is
// an exponential in kappa, and u moves with u_s), so work = stored + dissipated holds to round-off
// for any increment. The tangent in slip, phi kh + phi' (s fs + kh u) s, may be negative: the
// element softens while it slips.
#pragma once

#include <cmath>

#include "isolab/hysteresis/law_state.h"
#include "isolab/hysteresis/slip_direction.h"

namespace isolab::hysteresis {

struct DegradingSlider {
  double kp = 0.0;          // elastoplastic branch stiffness k0 - k1 (force/length), > 0
  double fs = 0.0;          // its characteristic force kp uy (force), > 0
  double kh = 0.0;          // linear spring k1 (force/length)
  double loss = 0.0;        // share of force lost after long slip, [0, 1)
  double slip_scale = 1.0;  // accumulated slip over which 63 % of `loss` is lost (length), > 0

  double Factor(double kappa) const { return 1.0 - loss * (1.0 - std::exp(-kappa / slip_scale)); }

  void Update(const LawState& committed, const LawInput& in, LawState* trial,
              LawResponse* response) const {
    const double us = committed.slider;
    const double kappa0 = committed.accumulated_slip;
    const double branch_force = kp * (in.u - us);
    const int slip = SlipDirection(committed.slip, in.u - committed.u, branch_force, kp, fs);
    trial->u = in.u;
    trial->v = in.v;
    trial->slip = slip;
    response->damping = 0.0;
    if (slip == 0) {
      const double phi = Factor(kappa0);
      trial->slider = us;
      trial->accumulated_slip = kappa0;
      trial->dissipated = committed.dissipated;  // phi is constant: stored energy takes the work
      trial->force = response->force = phi * (branch_force + kh * in.u);
      response->stiffness = phi * (kp + kh);
      return;
    }
    const double s = slip;
    const double us_new = in.u - s * fs / kp;
    const double kappa1 = kappa0 + std::abs(us_new - us);
    const double phi = Factor(kappa1);
    const double virgin = s * fs + kh * in.u;
    trial->slider = us_new;
    trial->accumulated_slip = kappa1;
    trial->force = response->force = phi * virgin;
    // d kappa / d u = s while slipping.
    const double phi_slope = -loss / slip_scale * std::exp(-kappa1 / slip_scale);
    response->stiffness = phi * kh + phi_slope * virgin * s;
    // Stick up to the yield point u_y (no dissipation), then slip with u = u_y + s (kappa -
    // kappa0): work = int phi(kappa) (fs + s kh u_y + kh (kappa - kappa0)) dkappa.
    const double u_yield = us + s * fs / kp;
    const double work = (fs + s * kh * u_yield - kh * kappa0) * PhiIntegral(kappa0, kappa1) +
                        kh * PhiKappaIntegral(kappa0, kappa1);
    const double branch_energy = 0.5 * fs * fs / kp;
    const double stored_at_yield = Factor(kappa0) * (branch_energy + 0.5 * kh * u_yield * u_yield);
    const double stored_now = phi * (branch_energy + 0.5 * kh * in.u * in.u);
    trial->dissipated = committed.dissipated + work - (stored_now - stored_at_yield);
  }

  double StoredEnergy(const LawState& state) const {
    const double ue = state.u - state.slider;
    return Factor(state.accumulated_slip) * (0.5 * kp * ue * ue + 0.5 * kh * state.u * state.u);
  }

 private:
  // int_a^b phi dkappa and int_a^b phi kappa dkappa.
  double PhiIntegral(double a, double b) const {
    const double c = slip_scale;
    return (1.0 - loss) * (b - a) + loss * c * (std::exp(-a / c) - std::exp(-b / c));
  }
  double PhiKappaIntegral(double a, double b) const {
    const double c = slip_scale;
    const auto primitive = [c](double k) { return -c * std::exp(-k / c) * (k + c); };
    return (1.0 - loss) * 0.5 * (b - a) * (b + a) + loss * (primitive(b) - primitive(a));
  }
};

}  // namespace isolab::hysteresis
