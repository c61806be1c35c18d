// Play slider kernel: an elastoplastic slider engaged through a clearance (backlash), with a
// strength that may differ in the two directions. Two laws compile to it:
//   asymmetric_elastoplastic  k0, uy_pos, uy_neg   (ke, fs_pos, fs_neg): no clearance, slips at
//                             +fs_pos = k0 uy_pos one way and -fs_neg = -k0 uy_neg the other (a
//                             friction device whose friction differs by direction);
//   backlash_elastoplastic    k0, uy, gap          (ke, fs, gap): equal strengths fs = k0 uy,
//                             engaged only once the clearance of total width `gap` is crossed
//                             (a friction damper with play in its connection).
//
// Equations. With the slider at u_s and half the clearance h = gap / 2, the contact deformation
// is the dead zone of u - u_s,
//   e = u - u_s - h  (u - u_s > h),   0  (|u - u_s| <= h),   u - u_s + h  (u - u_s < -h),
// and the force f = k e with -fs_neg <= f <= fs_pos. While f is inside those limits the slider
// sticks; where it would leave them the slider moves so that f sits on the limit:
//   slipping +: u_s = u - h - fs_pos / k,   slipping -: u_s = u + h + fs_neg / k.
// So after every reversal the force unloads elastically, stays at zero across a band of width
// `gap` (the plateau of a device with play), reloads elastically and slips again: the dead zone
// sits around the last reversal. Every catalogue law before it is odd-symmetric (f(-u) = -f(u)
// along a mirrored path); these two are not (asymmetric strength) or are but with a zero-force
// band the others cannot make (backlash).
//
// Exact update: for a monotone increment the contact deformation is monotone, so the phase at
// the end of the increment is decided by the end displacement alone (stick inside the limits,
// slip onto the limit beyond them), and one call gives the same state as any subdivision. As in
// slip_direction.h the committed phase decides at no increment: a slider that slipped in
// direction s goes on slipping for s du >= 0 whatever the round-off; for s du < 0 it can only
// stick or slip the other way. Tangent: k where engaged and sticking, 0 in the clearance and
// while slipping. Energy: stored k e^2 / 2; dissipated fs_pos or fs_neg times the slider's
// travel in that direction, so work = stored + dissipated to round-off.
//
// The clearance is the backlash model of mechanical play (Tao & Kokotovic 1996, the "dead-zone"
// and "backlash" nonlinearities); in series with a Coulomb slider it is the friction damper with
// slack of Pall & Marsh (1982)-type devices tested with loose bolts.
#pragma once

#include <cmath>

#include "isolab/hysteresis/law_state.h"

namespace isolab::hysteresis {

struct PlaySlider {
  double k = 0.0;       // stiffness once engaged (force/length), > 0
  double fs_pos = 0.0;  // strength slipping in +u (force), > 0
  double fs_neg = 0.0;  // strength slipping in -u (force), > 0
  double gap = 0.0;     // total width of the clearance (length), >= 0

  // The contact deformation e of the clearance at u with the slider at u_s.
  double Contact(double u, double slider) const {
    const double h = 0.5 * gap, x = u - slider;
    return x > h ? x - h : (x < -h ? x + h : 0.0);
  }

  void Update(const LawState& committed, const LawInput& in, LawState* trial,
              LawResponse* response) const {
    const double du = in.u - committed.u;
    const double stick = k * Contact(in.u, committed.slider);
    int slip = 0;
    if (committed.slip != 0 && committed.slip * du >= 0.0) {
      slip = committed.slip;  // the slip goes on (slip_direction.h)
    } else if (stick > fs_pos && committed.slip <= 0) {
      slip = 1;
    } else if (stick < -fs_neg && committed.slip >= 0) {
      slip = -1;
    }
    trial->u = in.u;
    trial->v = in.v;
    trial->t = committed.t;
    trial->temperature = committed.temperature;
    trial->slip = slip;
    response->damping = 0.0;
    if (slip == 0) {
      trial->slider = committed.slider;
      trial->accumulated_slip = committed.accumulated_slip;
      trial->dissipated = committed.dissipated;
      trial->force = response->force = stick;
      // In the clearance the contact is slack; without one (gap 0) it is engaged everywhere,
      // the point u = u_s included.
      const bool slack = gap > 0.0 && std::abs(in.u - committed.slider) <= 0.5 * gap;
      response->stiffness = slack ? 0.0 : k;
      return;
    }
    const double strength = slip > 0 ? fs_pos : fs_neg;
    const double slider = in.u - slip * (0.5 * gap + strength / k);
    // Not below 0: a slip that goes on at a round-off reversal moves the slider by nothing.
    const double travel = std::max(0.0, slip * (slider - committed.slider));
    trial->slider = committed.slider + slip * travel;
    trial->accumulated_slip = committed.accumulated_slip + travel;
    trial->dissipated = committed.dissipated + strength * travel;
    trial->force = response->force = slip * strength;
    response->stiffness = 0.0;
  }

  double StoredEnergy(const LawState& state) const {
    const double e = Contact(state.u, state.slider);
    return 0.5 * k * e * e;
  }
};

}  // namespace isolab::hysteresis
