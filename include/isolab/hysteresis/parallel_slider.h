// THM2 kernel (Markou & Manolis 2016, Fig. 2 and 4; Tsopelas et al. 1994): [element 1, a spring
// kp = ke - kh1, in series with element 2, a slider fs] in parallel with element 3, the
// trilinear spring g driven by the TOTAL displacement u:
//   f = kp (u - u_s) + g(u),   |kp (u - u_s)| <= fs.
// BHM2 (kh1 = kh2) is the same kernel.
//
// Exact update: the elastoplastic branch sticks while |kp (u - u_s,n)| <= fs, else the slider
// moves to u_s = u - s fs / kp; a slider that slipped into the committed state goes on slipping
// for s du >= 0 (slip_direction.h). The spring g depends on u alone. Both are closed forms in the
// end displacement, so one call equals any number of sub-increments.
#pragma once

#include <cmath>

#include "isolab/hysteresis/law_state.h"
#include "isolab/hysteresis/slip_direction.h"
#include "isolab/hysteresis/trilinear_spring.h"

namespace isolab::hysteresis {

struct ParallelSlider {
  double kp = 0.0;         // element 1 stiffness ke - kh1 (force/length), > 0
  double fs = 0.0;         // slider characteristic force (force), >= 0; 0 means no stick phase
  TrilinearSpring spring;  // element 3 on the total displacement

  void Update(const LawState& committed, const LawInput& in, LawState* trial,
              LawResponse* response) const {
    const double us = committed.slider;
    const double branch_force = kp * (in.u - us);
    const int slip = SlipDirection(committed.slip, in.u - committed.u, branch_force, kp, fs);
    trial->u = in.u;
    trial->v = in.v;
    trial->slip = slip;
    response->damping = 0.0;
    if (slip == 0) {
      trial->slider = us;
      trial->dissipated = committed.dissipated;
      trial->force = response->force = branch_force + spring.Force(in.u);
      response->stiffness = kp + spring.Stiffness(in.u);
      return;
    }
    const double direction = slip;
    const double us_new = in.u - direction * fs / kp;
    trial->slider = us_new;
    trial->dissipated = committed.dissipated + fs * std::abs(us_new - us);
    trial->force = response->force = direction * fs + spring.Force(in.u);
    response->stiffness = spring.Stiffness(in.u);
  }

  double StoredEnergy(const LawState& state) const {
    const double ue = state.u - state.slider;
    return 0.5 * kp * ue * ue + spring.Energy(state.u);
  }
};

}  // namespace isolab::hysteresis
