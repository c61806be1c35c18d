// Chopra, Dynamics of Structures, Ex. 5.1-5.6, shared by the Newmark and IDA tests:
// m = 0.2533 kip s^2/in, k = 10 kip/in, zeta = 0.05, p = 10 sin(pi t/0.6) kip.
#pragma once

#include <cmath>
#include <numbers>

#include "isolab/integrators/excitation.h"

namespace isolab::testing {

inline constexpr double kChopraMass = 0.2533, kChopraStiffness = 10.0;
inline const double kChopraDamping = 2.0 * 0.05 * std::sqrt(kChopraStiffness * kChopraMass);

// Sampled at `dt` (0.6 s a whole number of steps), so every analysis step sees the exact load.
inline integrators::Excitation HalfSinePulse(double dt = 0.1) {
  integrators::Excitation excitation;
  integrators::AppliedForce pulse{0, {dt, {}}};
  const int samples = static_cast<int>(std::round(0.6 / dt));
  for (int k = 0; k <= samples; ++k) {
    pulse.force.values.push_back(10.0 * std::sin(std::numbers::pi * k / samples));
  }
  excitation.forces.push_back(pulse);
  return excitation;
}

}  // namespace isolab::testing
