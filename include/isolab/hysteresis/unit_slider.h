// The normalised elastoplastic slider of the bearing laws whose strength varies (friction
// pendulum, lead-rubber with heating): z = clamp((u - u_s) / u_y, -1, 1), the sliding
// interface's yield displacement u_y fixed, as in the hysteretic variable of Constantinou et al.
// (1990) and Kalpakidis & Constantinou (2009) taken to its elastoplastic (Bouc-Wen n -> inf)
// limit. z depends on the displacement path alone, never on the strength that multiplies it, so
// its update is exact for any increment: the slider sticks while |u - u_s,n| <= u_y, else it moves
// to u_s = u - s u_y; a slider that slipped into the committed state goes on slipping for
// s du >= 0 (slip_direction.h: the decision and the tangent at that corner).
#pragma once

#include <cmath>

#include "isolab/hysteresis/slip_direction.h"

namespace isolab::hysteresis {

struct UnitSlider {
  double uy = 0.0;  // yield displacement of the sliding interface (length), > 0

  struct Step {
    double z = 0.0;       // in [-1, 1]
    double dz_du = 0.0;   // 1/u_y sticking, 0 slipping
    double slider = 0.0;  // u_s after the increment
    double travel = 0.0;  // |u_s - u_s,n|, the slip of this increment
    // int z du over the increment from u_n: u_y (z^2 - z_n^2) / 2 for the elastic part plus the
    // travel (z = s while slipping), exact for a monotone increment, which is all an increment
    // of a law is.
    double z_work = 0.0;
    int slip = 0;  // +-1 slipping that way, 0 sticking (LawState::slip)
  };

  double Z(double u, double slider) const { return (u - slider) / uy; }

  // From the committed u_n, u_s,n and slip phase (LawState::u, slider, slip) to u.
  Step Update(double u_n, double slider_n, int slip_n, double u) const {
    Step step;
    const double z_n = Z(u_n, slider_n);
    const double trial = Z(u, slider_n);
    step.slip = SlipDirection(slip_n, u - u_n, trial, 1.0 / uy, 1.0);
    if (step.slip == 0) {
      step.z = trial;
      step.dz_du = 1.0 / uy;
      step.slider = slider_n;
    } else {
      step.z = step.slip;
      step.slider = u - step.z * uy;
      step.travel = std::abs(step.slider - slider_n);
    }
    step.z_work = 0.5 * uy * (step.z * step.z - z_n * z_n) + step.travel;
    return step;
  }
};

}  // namespace isolab::hysteresis
