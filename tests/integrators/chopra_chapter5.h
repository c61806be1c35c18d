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

// Chopra's Tables E5.3 (Newmark average acceleration), E5.4 (linear acceleration) and E5.5
// (elastoplastic, fy = 7.5 kip, Newton-Raphson) for the pulse above at dt = 0.1 s, recomputed to
// six decimals (the book prints four, from rounded constants, about 1e-4 lower).
struct ChopraChapter5Row {
  double t;                                  // s
  double u_average, v_average;               // in, in/s: linear system, average acceleration
  double u_linear;                           // in: linear system, linear acceleration
  double u_elastoplastic, fs_elastoplastic;  // in, kip
};
inline constexpr ChopraChapter5Row kChopraChapter5[] = {
    {0.0, 0.000000, 0.000000, 0.000000, 0.000000, 0.000000},
    {0.1, 0.043667, 0.873339, 0.029984, 0.043667, 0.436669},
    {0.2, 0.232619, 2.905701, 0.219334, 0.232619, 2.326189},
    {0.3, 0.612071, 4.683342, 0.616610, 0.612071, 6.120711},
    {0.4, 1.082543, 4.726091, 1.113016, 1.114364, 7.500000},
    {0.5, 1.430954, 2.242133, 1.478209, 1.621462, 7.500000},
    {0.6, 1.423078, -2.399646, 1.462486, 1.989157, 7.500000},
    {0.7, 0.962175, -6.818408, 0.951430, 2.095225, 7.500000},
    {0.8, 0.190776, -8.609582, 0.127306, 1.924131, 5.789060},
    {0.9, -0.604380, -7.293537, -0.695431, 1.560317, 2.150921},
    {1.0, -1.144195, -3.502769, -1.220830, 1.141591, -2.036338},
};

}  // namespace isolab::testing
