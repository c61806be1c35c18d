// Response spectra by brute force, written apart from src/spectra, for the tests that check work
// built on the library's spectra (record scaling, suite scaling, matched pairs): a number those
// tests compare with must not come from the code under test.
//
// Each period's linear SDOF (per unit mass: u'' + 2 zeta w u' + w^2 u = -a_g) is stepped through
// the record by the classical fourth-order Runge-Kutta method at a step no longer than T / 1000,
// the ground acceleration linear between the record's samples, from rest, over the record's
// duration (no free vibration after it, as the library's). The peak is read at every step. At
// w h <= 2 pi / 1000 the method's error per step is of order (w h)^5 / 120, 1e-13, so over
// thousands of cycles the response is exact to about 1e-9, and a peak read 1000 times a period is
// at most 1 - cos(pi / 1000) = 4.9e-6 below the continuous one. The library solves each sample
// interval exactly and reads the peak 100 times a period (up to 4.9e-4 low), so the two agree to
// about 5e-4, this one never lower by more than about 5e-6.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

namespace isolab::testing {

// Steps the SDOF of `period` and `damping` through `ground` (sampled every `dt`) and calls
// observe(u) after every step, u the relative displacement.
template <typename Observe>
void StepSdof(const std::vector<double>& ground, double dt, double period, double damping,
              const Observe& observe) {
  const double w = 2.0 * std::numbers::pi / period;
  const double c = 2.0 * damping * w, k = w * w;
  const int substeps = std::max(1, int(std::ceil(dt * 1000.0 / period)));
  const double h = dt / substeps;
  // The state's rate (u', v') at ground acceleration g.
  const auto rate = [&](double u, double v, double g) { return std::pair{v, -g - c * v - k * u}; };
  double u = 0.0, v = 0.0;
  for (std::size_t i = 0; i + 1 < ground.size(); ++i) {
    const double slope = (ground[i + 1] - ground[i]) / substeps;
    for (int j = 0; j < substeps; ++j) {
      const double g0 = ground[i] + slope * j, g1 = g0 + 0.5 * slope, g2 = g0 + slope;
      const auto [du1, dv1] = rate(u, v, g0);
      const auto [du2, dv2] = rate(u + 0.5 * h * du1, v + 0.5 * h * dv1, g1);
      const auto [du3, dv3] = rate(u + 0.5 * h * du2, v + 0.5 * h * dv2, g1);
      const auto [du4, dv4] = rate(u + h * du3, v + h * dv3, g2);
      u += h / 6.0 * (du1 + 2.0 * du2 + 2.0 * du3 + du4);
      v += h / 6.0 * (dv1 + 2.0 * dv2 + 2.0 * dv3 + dv4);
      observe(u);
    }
  }
}

// Pseudo-acceleration w^2 max |u| (units of `ground`).
inline double BruteForceSa(const std::vector<double>& ground, double dt, double period,
                           double damping) {
  double peak = 0.0;
  StepSdof(ground, dt, period, damping, [&](double u) { peak = std::max(peak, std::abs(u)); });
  const double w = 2.0 * std::numbers::pi / period;
  return w * w * peak;
}

// RotD100 of a pair: w^2 max over time of |(u1, u2)|, the largest response in any direction.
inline double BruteForceRotD100(const std::vector<double>& h1, const std::vector<double>& h2,
                                double dt, double period, double damping) {
  std::vector<double> u1;
  u1.reserve(h1.size() * 8);
  StepSdof(h1, dt, period, damping, [&](double u) { u1.push_back(u); });
  double peak = 0.0;
  std::size_t k = 0;
  StepSdof(h2, dt, period, damping, [&](double u) {
    if (k < u1.size()) peak = std::max(peak, std::hypot(u1[k], u));
    ++k;
  });
  const double w = 2.0 * std::numbers::pi / period;
  return w * w * peak;
}

}  // namespace isolab::testing
