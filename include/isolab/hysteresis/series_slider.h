// THM1 kernel (Markou & Manolis 2016, Fig. 1 and 3; Oliveto et al. 2014): element 1, a spring
// ke, in series with [element 2, a rigid-plastic slider fs, in parallel with element 3, the
// trilinear spring g driven by the slider displacement u_h]:
//   u = u_e + u_h,   f = ke (u - u_h) = f_slider + g(u_h),   |f_slider| <= fs.
// BHM1 (kh1 = kh2), the elastoplastic element (kh1 = kh2 = 0) and, with fs = 0, a spring ke in
// series with g are the same kernel.
//
// Exact update: the slider sticks while |ke (u - u_h,n) - g(u_h,n)| <= fs; otherwise it slips in
// the direction s of that force until ke (u - u_h) - g(u_h) = s fs, i.e. ke u_h + g(u_h) =
// ke u - s fs, solved segment by segment (TrilinearSpring::SolveInSeries). A slider that slipped
// into the committed state goes on slipping for s du >= 0 (slip_direction.h: the decision and the
// tangent at that corner). Over a monotone increment the slider sticks, then slips one way, and
// the end state depends only on the end displacement, so one call equals any number of
// sub-increments.
#pragma once

#include <cmath>

#include "isolab/hysteresis/law_state.h"
#include "isolab/hysteresis/slip_direction.h"
#include "isolab/hysteresis/trilinear_spring.h"

namespace isolab::hysteresis {

struct SeriesSlider {
  double ke = 0.0;         // element 1 stiffness (force/length), > 0
  double fs = 0.0;         // slider characteristic force (force), >= 0; 0 means no stick phase
  TrilinearSpring spring;  // element 3; needs ke + kh1 > 0 and ke + kh2 > 0

  void Update(const LawState& committed, const LawInput& in, LawState* trial,
              LawResponse* response) const {
    const double uh = committed.slider;
    const double slider_force = ke * (in.u - uh) - spring.Force(uh);
    const int slip = SlipDirection(committed.slip, in.u - committed.u, slider_force, ke, fs);
    trial->u = in.u;
    trial->v = in.v;
    trial->slip = slip;
    response->damping = 0.0;
    if (slip == 0) {
      trial->slider = uh;
      trial->dissipated = committed.dissipated;
      trial->force = response->force = ke * (in.u - uh);
      response->stiffness = ke;
      return;
    }
    const double direction = slip;
    double kh = 0.0;
    const double uh_new = spring.SolveInSeries(ke, ke * in.u - direction * fs, &kh);
    trial->slider = uh_new;
    trial->dissipated = committed.dissipated + fs * std::abs(uh_new - uh);
    // Equal to ke (u - u_h) but free of its cancellation when ke >> kh (the paper's k0 >> k1
    // spring limit, where u - u_h is a small difference of large numbers).
    trial->force = response->force = direction * fs + spring.Force(uh_new);
    // d u_h / d u = ke / (ke + kh), so d f / d u = ke kh / (ke + kh).
    response->stiffness = ke * kh / (ke + kh);
  }

  // Recoverable energy: element 1 (f^2 / 2 ke, again free of cancellation) plus element 3.
  double StoredEnergy(const LawState& state) const {
    return 0.5 * state.force * state.force / ke + spring.Energy(state.slider);
  }
};

}  // namespace isolab::hysteresis
