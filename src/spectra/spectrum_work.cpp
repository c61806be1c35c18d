#include "isolab/spectra/spectrum_work.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "isolab/core/errors.h"

namespace isolab::spectra {

double SpectrumSteps(const integrators::SampledHistory& ground, std::span<const double> periods,
                     std::size_t damping_ratios, int points_per_period, std::size_t ductilities,
                     const ConstantDuctilityOptions& options) {
  const double samples = static_cast<double>(ground.values.size());
  // Strength ratios scanned from 1 down to min_strength_ratio, and bisection halvings to the
  // tolerance, as SolveStrengthRatios takes them at most.
  const double scans =
      1.0 + std::ceil(std::log(options.min_strength_ratio) / std::log(options.scan_ratio));
  const double halvings = std::ceil(std::log2(1.0 / options.tolerance));
  const double runs = ductilities > 0 ? 1.0 + scans + halvings * ductilities : 0.0;
  double steps = 0.0;
  for (const double period : periods) {
    // The substep counts of SubstepsPerSample and InelasticTimeStep, before their rounding.
    const double elastic = std::max(1.0, std::ceil(ground.dt * points_per_period / period));
    const double inelastic =
        std::max(1.0, std::ceil(ground.dt * options.steps_per_period / period));
    steps += samples * (elastic + runs * inelastic);
  }
  return steps * static_cast<double>(damping_ratios);
}

double PairSpectrumSteps(const integrators::SampledHistory& ground, std::span<const double> periods,
                         std::size_t damping_ratios, int points_per_period) {
  return kPairStepsPerPoint *
         SpectrumSteps(ground, periods, damping_ratios, points_per_period, 0, {});
}

void CheckSpectrumWork(double steps, double max_steps, const std::string& limit_name) {
  if (steps <= max_steps) return;
  throw InputError({limit_name},
                   fmt::format("the spectrum would take about {:.3g} SDOF steps, more than the "
                               "{:.3g} allowed: ask for fewer or longer periods, fewer points per "
                               "period or fewer damping ratios, or raise {}",
                               steps, max_steps, limit_name));
}

}  // namespace isolab::spectra
