// THM2 kernel in two directions (parallel form; parallel_slider.h for one): [a spring kp = ke -
// kh1 in series with a slider of circular strength fs] in parallel with the spring g driven by
// the total deformation u (radial_spring.h):
//   f = b + g(u),   b = kp (u - u_s),   |b| <= fs,   du_s = lambda b / fs, lambda >= 0.
// BHM2 (kh1 = kh2), the HDR bearing from design data (hdr_bearing.h) and the lead-rubber bearing
// without heating are this kernel.
//
// Return map: the elastoplastic branch sticks while the trial b* = kp (u - u_s,n) lies in the
// circle; otherwise its force is returned radially, b = fs n with n = b* / |b*|, and the slider
// moves to u_s = u - fs n / kp, a travel of (|b*| - fs) / kp along n. This is the exact backward-
// Euler (closest-point) projection in closed form, and along a line through the origin it is the
// 1-D kernel. Tangent: stick kp I + Dg(u); slip (fs kp / |b*|) (I - n n^T) + Dg(u): across n the
// branch still stiffens by the rotation of b, along n it adds nothing. The dissipation is fs
// times the travel.
#pragma once

#include <algorithm>

#include "isolab/hysteresis/parallel_slider.h"
#include "isolab/hysteresis/plan_law_state.h"
#include "isolab/hysteresis/plan_slip_decision.h"
#include "isolab/hysteresis/radial_spring.h"

namespace isolab::hysteresis {

struct PlanParallelSlider {
  ParallelSlider law;  // kp, fs and g, as the 1-D kernel of the same law has them

  // The one stick test of the family (plan_slip_decision.h): the branch force if it stuck is
  // kp (u - u_s,n); committed on the circle, it was kp (u_n - u_s,n).
  bool Sticks(PlanLawStateView committed, Vec2 u, Vec2 trial_branch_force) const {
    if (!(law.fs > 0.0)) return false;
    const Vec2 u_n = Displacement(committed);
    return !PlanSlips(Slipping(committed), u_n - Slider(committed), u - u_n,
                      Norm(trial_branch_force) / law.fs);
  }

  void Update(PlanLawStateView committed, const PlanLawInput& in, PlanLawStateSlot trial,
              PlanLawResponse* response) const {
    const Vec2 us = Slider(committed);
    const Vec2 branch = law.kp * (in.u - us);
    const Vec2 g = RadialForce(law.spring, in.u);
    const Mat2 dg = RadialStiffness(law.spring, in.u);
    CoupledState next = Carried(committed);
    response->damping = {};
    if (Sticks(committed, in.u, branch)) {
      next.force = branch + g;
      response->stiffness = Identity(law.kp) + dg;
    } else {
      const double trial_norm = Norm(branch);
      // fs = 0 with b* = 0: no branch force and no direction; the slider follows u.
      const Vec2 n = trial_norm > 0.0 ? branch / trial_norm : Vec2{};
      // Not below 0: a continuing slip decided by the phase may start a round-off inside.
      const double travel = std::max(0.0, (trial_norm - law.fs) / law.kp);
      next.slipping = true;
      next.slider = in.u - (law.fs / law.kp) * n;
      next.dissipated += law.fs * travel;
      next.accumulated_slip += travel;
      next.force = law.fs * n + g;
      response->stiffness =
          trial_norm > 0.0 ? (law.fs * law.kp / trial_norm) * NormalProjector(n) + dg : dg;
    }
    response->force = next.force;
    Store(in, next, trial);
  }

  double StoredEnergy(PlanLawStateView state) const {
    const Vec2 ue = Displacement(state) - Slider(state);
    return 0.5 * law.kp * Dot(ue, ue) + RadialEnergy(law.spring, Displacement(state));
  }
};

}  // namespace isolab::hysteresis
