#include "isolab/spectra/rotd_spectrum.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "exact_walk.h"
#include "isolab/core/errors.h"

namespace isolab::spectra {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// ValidateSpectrumInput on one component, its violations named after it ("h2 record sample 7").
void ValidateComponent(const char* name, const integrators::SampledHistory& ground,
                       std::span<const double> periods, std::span<const double> damping_ratios) {
  try {
    ValidateSpectrumInput(ground, periods, damping_ratios);
  } catch (const InvalidParameter& error) {
    ParameterViolation violation = error.violation();
    violation.key = fmt::format("{} {}", name, violation.key);
    throw InvalidParameter(violation);
  }
}

// The unit vector of each angle 0, 1, ..., 179 degrees; 90 exactly (0, 1), so that D(90) is
// H2's own peak.
struct Directions {
  std::array<double, kRotDAngles> cos{}, sin{};
  Directions() {
    for (int a = 0; a < kRotDAngles; ++a) {
      const double radians = a * std::numbers::pi / 180.0;
      cos[a] = a == 90 ? 0.0 : std::cos(radians);
      sin[a] = a == 90 ? 1.0 : std::sin(radians);
    }
  }
};

ElasticSpectrum EmptyLike(std::span<const double> periods, std::span<const double> damping) {
  ElasticSpectrum spectrum;
  spectrum.periods.assign(periods.begin(), periods.end());
  spectrum.damping_ratios.assign(damping.begin(), damping.end());
  spectrum.ordinates.reserve(periods.size() * damping.size());
  return spectrum;
}

}  // namespace

void ValidatePairInput(const integrators::SampledHistory& h1, const integrators::SampledHistory& h2,
                       std::span<const double> periods, std::span<const double> damping_ratios) {
  ValidateComponent("h1", h1, periods, damping_ratios);
  ValidateComponent("h2", h2, periods, damping_ratios);
  if (std::abs(h2.dt - h1.dt) > 1e-9 * h1.dt) {
    throw InvalidParameter(
        {"h2 dt", h2.dt, fmt::format("must be h1's {:g}: a pair shares one step", h1.dt)});
  }
  if (h2.values.size() != h1.values.size()) {
    throw InvalidParameter(
        {"h2 samples", double(h2.values.size()),
         fmt::format("must be h1's {}: a pair has one length", h1.values.size())});
  }
}

PairSpectrum ComputePairSpectrum(const integrators::SampledHistory& h1,
                                 const integrators::SampledHistory& h2,
                                 std::span<const double> periods,
                                 std::span<const double> damping_ratios,
                                 const ElasticSpectrumOptions& options) {
  options.Validate();
  ValidatePairInput(h1, h2, periods, damping_ratios);
  static const Directions directions;
  PairSpectrum pair{EmptyLike(periods, damping_ratios), EmptyLike(periods, damping_ratios),
                    EmptyLike(periods, damping_ratios), EmptyLike(periods, damping_ratios),
                    EmptyLike(periods, damping_ratios), {}};
  std::array<double, kRotDAngles> peaks, sorted;
  for (const double zeta : damping_ratios) {
    for (const double period : periods) {
      const int substeps = SubstepsPerSample(h1.dt, period, options.points_per_period);
      PeakDeformation d1, d2;
      double largest_squared = 0.0, floor_squared = -1.0;
      std::array<double, 2> at_largest{};
      long k1 = 0, k2 = 0, k_largest = 0;
      peaks.fill(0.0);
      WalkExact<2>({&h1, &h2}, period, zeta, substeps, [&](long k, const std::array<double, 2>& u) {
        if (std::abs(u[0]) > d1.value) d1.value = std::abs(u[0]), k1 = k;
        if (std::abs(u[1]) > d2.value) d2.value = std::abs(u[1]), k2 = k;
        const double squared = u[0] * u[0] + u[1] * u[1];
        if (squared > largest_squared) {
          largest_squared = squared, at_largest = u, k_largest = k;
        }
        // |u . n| <= |u|: a point no longer than the smallest peak so far raises none, and
        // after the strong motion most points are such.
        if (squared <= floor_squared) return;
        double floor = std::numeric_limits<double>::infinity();
        for (int a = 0; a < kRotDAngles; ++a) {
          peaks[a] =
              std::max(peaks[a], std::abs(u[0] * directions.cos[a] + u[1] * directions.sin[a]));
          floor = std::min(floor, peaks[a]);
        }
        floor_squared = floor * floor;
      });
      const double h = h1.dt / substeps;
      sorted = peaks;
      std::sort(sorted.begin(), sorted.end());
      const double median = 0.5 * (sorted[kRotDAngles / 2 - 1] + sorted[kRotDAngles / 2]);
      pair.h1.ordinates.push_back(OrdinateFromDeformation(period, d1.value, k1 * h));
      pair.h2.ordinates.push_back(OrdinateFromDeformation(period, d2.value, k2 * h));
      pair.geometric_mean.ordinates.push_back(
          OrdinateFromDeformation(period, std::sqrt(d1.value * d2.value), kNaN));
      pair.rotd50.ordinates.push_back(OrdinateFromDeformation(period, median, kNaN));
      pair.rotd100.ordinates.push_back(
          OrdinateFromDeformation(period, std::sqrt(largest_squared), k_largest * h));
      double angle = std::atan2(at_largest[1], at_largest[0]) * 180.0 / std::numbers::pi;
      if (angle < 0.0) angle += 180.0;
      if (angle >= 180.0) angle -= 180.0;
      pair.rotd100_angle.push_back(angle);
    }
  }
  return pair;
}

}  // namespace isolab::spectra
