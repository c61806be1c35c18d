// The normalised elastoplastic slider of the bearing laws whose strength varies (friction
// pendulum, lead-rubber with heating): z = clamp((u - u_s) / u_y, -1, 1), the sliding
// interface's yield displacement u_y fixed, as in the hysteretic variable of Constantinou et al.
// (1990) and Kalpakidis & Constantinou (2009) taken to its elastoplastic (Bouc-Wen n -> inf)
// limit. z depends on the displacement path alone, never on the strength that multiplies it, so
// its update is exact for any increment: the slider sticks while |u - u_s,n| <= u_y, else it moves
// to u_s = u - s u_y.
#pragma once

#include <cmath>

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
  };

  double Z(double u, double slider) const { return (u - slider) / uy; }

  Step Update(double u_n, double slider_n, double u) const {
    Step step;
    const double z_n = Z(u_n, slider_n);
    const double trial = Z(u, slider_n);
    if (std::abs(trial) <= 1.0) {
      step.z = trial;
      step.dz_du = 1.0 / uy;
      step.slider = slider_n;
    } else {
      step.z = trial > 0.0 ? 1.0 : -1.0;
      step.slider = u - step.z * uy;
      step.travel = std::abs(step.slider - slider_n);
    }
    step.z_work = 0.5 * uy * (step.z * step.z - z_n * z_n) + step.travel;
    return step;
  }
};

}  // namespace isolab::hysteresis
