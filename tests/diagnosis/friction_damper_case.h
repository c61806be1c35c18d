// A synthetic laboratory friction damper with hidden truth, in kip and in, shaped after the
// characterisation campaign of a real one: ten sinusoidal tests at 0.25 to 2 Hz and 0.5 to
// 1.5 in, seven cycles each, sampled at 1024 Hz (150,528 samples), from rest. The device is two
// sliding interfaces beside a light spring: one behind a clearance of 0.15 in (backlash: its
// 2 kip of friction drops out for 0.15 in after every reversal) and one whose friction is
// 1.3 kip one way and 2.6 kip the other, so the device slips at +3.3 and -4.6 kip. The force
// channel carries Gaussian noise through a load cell's anti-alias filter (a 4th-order
// Butterworth low-pass), as a laboratory's does; `Decimate` keeps every k-th sample, as a
// lower-rate acquisition of the same tests would. Optionally the device makes noise of its own
// while it slides (stick-slip chatter: band-limited Gaussian noise, on while the speed is above a
// fifth of the test's peak), which samples at rest before the motion cannot see.
#pragma once

#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "isolab/hysteresis/parallel_assembly.h"
#include "isolab/identification/cyclic_data.h"

namespace isolab::diagnosis::testing {

inline hysteresis::ParallelAssembly FrictionDamperTruth() {
  using hysteresis::LawParameters;
  using hysteresis::LawType;
  using hysteresis::ParameterForm;
  const auto law = [](LawType type, std::vector<double> values) {
    return LawParameters::Make(type, ParameterForm::kMathematical, values);
  };
  return hysteresis::ParallelAssembly(
      {{"spring", law(LawType::kLinearSpring, {0.5})},
       {"play", law(LawType::kBacklashElastoplastic, {40.0, 0.05, 0.15})},
       {"asymmetric", law(LawType::kAsymmetricElastoplastic, {60.0, 1.3 / 60, 2.6 / 60})}});
}

struct DamperNoise {
  double sigma = 0.02;           // kip, after the filter
  double cutoff = 50.0;          // Hz; <= 0: white
  double quantum = 0.0;          // kip; > 0 rounds the force to it (an ADC's step)
  double rest_seconds = 0.0;     // samples at rest before each test's motion
  double chatter = 0.0;          // kip, RMS of the chatter while it is on
  double chatter_cutoff = 40.0;  // Hz, its 4th-order Butterworth low-pass
  unsigned seed = 1;
};

// Gaussian noise through a 4th-order Butterworth low-pass (two bilinear-transform biquads),
// scaled to standard deviation `sigma` after the filter.
inline std::vector<double> FilteredNoise(std::size_t n, double rate, const DamperNoise& noise,
                                         std::mt19937_64* random) {
  std::normal_distribution<double> gaussian(0.0, 1.0);
  const std::size_t settle = 4096;
  std::vector<double> x(n + settle);
  for (double& v : x) v = gaussian(*random);
  if (noise.cutoff > 0.0) {
    const double k = std::tan(std::numbers::pi * noise.cutoff / rate);
    for (const double q : {0.54119610, 1.30656296}) {  // 1 / (2 cos) of the Butterworth poles
      const double norm = 1.0 / (1.0 + k / q + k * k);
      const double b0 = k * k * norm, b1 = 2 * b0, b2 = b0;
      const double a1 = 2 * (k * k - 1) * norm, a2 = (1 - k / q + k * k) * norm;
      double x1 = 0, x2 = 0, y1 = 0, y2 = 0;
      for (double& v : x) {
        const double y = b0 * v + b1 * x1 + b2 * x2 - a1 * y1 - a2 * y2;
        x2 = x1, x1 = v, y2 = y1, y1 = y, v = y;
      }
    }
  }
  x.erase(x.begin(), x.begin() + settle);
  double square = 0.0;
  for (const double v : x) square += v * v;
  const double scale = noise.sigma / std::sqrt(square / double(n));
  for (double& v : x) v *= scale;
  return x;
}

inline std::vector<identification::CyclicTestData> FrictionDamperTests(
    double rate = 1024.0, const DamperNoise& noise = {}, int cycles = 7) {
  const hysteresis::ParallelAssembly truth = FrictionDamperTruth();
  const std::vector<std::pair<double, double>> protocol = {
      {4.0, 0.5}, {4.0, 1.0}, {4.0, 1.5}, {2.0, 0.5}, {2.0, 1.0},
      {2.0, 1.5}, {1.0, 0.5}, {1.0, 1.0}, {0.5, 0.5}, {0.5, 1.0}};
  std::mt19937_64 random(noise.seed);
  std::vector<identification::CyclicTestData> tests;
  for (const auto& [period, amplitude] : protocol) {
    identification::CyclicTestData test;
    char name[64];
    std::snprintf(name, sizeof name, "f=%g_u=%g", 1.0 / period, amplitude);
    test.name = name;
    const auto rest = static_cast<std::size_t>(noise.rest_seconds * rate);
    const auto moving = static_cast<std::size_t>(std::lround(cycles * period * rate));
    for (std::size_t k = 0; k <= rest + moving; ++k) {
      const double t = double(k) / rate;
      const double phase =
          k < rest ? 0.0 : 2 * std::numbers::pi * double(k - rest) / (period * rate);
      test.time.push_back(t);
      test.displacement.push_back(amplitude * std::sin(phase));
    }
    test.force = identification::SimulateForce(truth, test);
    const std::vector<double> e = FilteredNoise(test.force.size(), rate, noise, &random);
    DamperNoise chatter = noise;
    chatter.sigma = noise.chatter, chatter.cutoff = noise.chatter_cutoff;
    const std::vector<double> c = noise.chatter > 0.0
                                      ? FilteredNoise(test.force.size(), rate, chatter, &random)
                                      : std::vector<double>(test.force.size(), 0.0);
    for (std::size_t k = 0; k < test.force.size(); ++k) {
      const double phase =
          k < rest ? 0.0 : 2 * std::numbers::pi * double(k - rest) / (period * rate);
      const bool sliding = k >= rest && std::abs(std::cos(phase)) > 0.2;
      test.force[k] += e[k] + (sliding ? c[k] : 0.0);
      if (noise.quantum > 0.0)
        test.force[k] = noise.quantum * std::round(test.force[k] / noise.quantum);
    }
    identification::Segment(&test);
    tests.push_back(std::move(test));
  }
  return tests;
}

// Every `factor`-th sample of each test, from the first: the same tests at a lower rate.
inline std::vector<identification::CyclicTestData> Decimate(
    const std::vector<identification::CyclicTestData>& tests, std::size_t factor) {
  std::vector<identification::CyclicTestData> result;
  for (const auto& test : tests) {
    identification::CyclicTestData kept;
    kept.name = test.name;
    for (std::size_t k = 0; k < test.time.size(); k += factor) {
      kept.time.push_back(test.time[k]);
      kept.displacement.push_back(test.displacement[k]);
      kept.force.push_back(test.force[k]);
    }
    identification::Segment(&kept);
    result.push_back(std::move(kept));
  }
  return result;
}

}  // namespace isolab::diagnosis::testing
