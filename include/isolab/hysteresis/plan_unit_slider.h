// The normalised elastoplastic slider of the bearing laws (unit_slider.h) in two directions, the
// sliding interface of a friction pendulum or the lead core of a lead-rubber bearing:
//   z = (u - u_s) / u_y,   |z| <= 1,   du_s = lambda z, lambda >= 0,
// the circular elastoplastic (Bouc-Wen n -> inf) limit of the biaxial interface variable of
// Constantinou, Mokha & Reinhorn (1990, Teflon bearings in base isolation II: modeling). The map is
// closed form: the interface sticks while the trial z* = (u - u_s,n) / u_y lies in the unit circle;
// otherwise z = z* / |z*| and the slider moves to u_s = u - u_y z, a travel of u_y (|z*| - 1) along
// z. z depends on the path alone, never on the strength that multiplies it; along a line through
// the origin it is the 1-D slider.
#pragma once

#include <algorithm>

#include "isolab/hysteresis/plan_slip_decision.h"
#include "isolab/hysteresis/plan_vector.h"
#include "isolab/hysteresis/unit_slider.h"

namespace isolab::hysteresis {

struct PlanUnitSlider {
  UnitSlider slider;  // its yield displacement u_y

  struct Step {
    Vec2 z;               // |z| <= 1
    Mat2 dz_du;           // I / u_y sticking; (I - z z^T) / (u_y |z*|) slipping
    Vec2 slider;          // u_s after the increment
    double travel = 0.0;  // |u_s - u_s,n|
    // int z . du over the increment: u_y (|z|^2 - |z_n|^2) / 2 for the elastic part plus the
    // travel (|z| = 1 while slipping); exact when sticking and for a straight increment whose
    // slip keeps its direction, which is every increment along a line.
    double z_work = 0.0;
    bool slipping = false;
  };

  Vec2 Z(Vec2 u, Vec2 slider_position) const { return (u - slider_position) / slider.uy; }

  // The one stick test of the bearing laws (plan_slip_decision.h): z_n is the committed slider
  // force's direction.
  Step Update(bool committed_slipping, Vec2 u_n, Vec2 slider_n, Vec2 u) const {
    const double uy = slider.uy;
    const Vec2 z_n = Z(u_n, slider_n);
    const Vec2 trial = Z(u, slider_n);
    const double trial_norm = Norm(trial);
    Step step;
    if (!PlanSlips(committed_slipping, z_n, u - u_n, trial_norm)) {
      step.z = trial;
      step.dz_du = Identity(1.0 / uy);
      step.slider = slider_n;
    } else {
      step.z = trial / trial_norm;
      step.dz_du = (1.0 / (uy * trial_norm)) * NormalProjector(step.z);
      step.slider = u - uy * step.z;
      // Not below 0: a continuing slip decided by the phase may start a round-off inside.
      step.travel = std::max(0.0, uy * (trial_norm - 1.0));
      step.slipping = true;
    }
    step.z_work = 0.5 * uy * (Dot(step.z, step.z) - Dot(z_n, z_n)) + step.travel;
    return step;
  }
};

}  // namespace isolab::hysteresis
