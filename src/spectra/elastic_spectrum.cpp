#include "isolab/spectra/elastic_spectrum.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "isolab/core/errors.h"
#include "isolab/spectra/exact_linear_sdof.h"

namespace isolab::spectra {

void ElasticSpectrumOptions::Validate() const {
  if (points_per_period < 1) {
    throw InvalidParameter({"points_per_period", double(points_per_period), "must be >= 1"});
  }
}

void ValidateSpectrumInput(const integrators::SampledHistory& ground,
                           std::span<const double> periods,
                           std::span<const double> damping_ratios) {
  if (!(ground.dt > 0.0) || !std::isfinite(ground.dt)) {
    throw InvalidParameter({"record dt", ground.dt, "must be finite and > 0"});
  }
  if (ground.values.size() < 2) {
    throw InvalidParameter(
        {"record samples", double(ground.values.size()), "a spectrum needs at least 2"});
  }
  for (std::size_t k = 0; k < ground.values.size(); ++k) {
    if (!std::isfinite(ground.values[k])) {
      throw InvalidParameter(
          {fmt::format("record sample {}", k), ground.values[k], "must be finite"});
    }
  }
  if (periods.empty()) throw InvalidParameter({"periods", 0.0, "at least one is needed"});
  for (std::size_t k = 0; k < periods.size(); ++k) {
    if (!(periods[k] > 0.0 && periods[k] <= kMaxSpectrumPeriod)) {
      throw InvalidParameter({fmt::format("periods[{}]", k), periods[k],
                              fmt::format("must be > 0 and at most {:g} s", kMaxSpectrumPeriod)});
    }
  }
  if (damping_ratios.empty()) {
    throw InvalidParameter({"damping_ratios", 0.0, "at least one is needed"});
  }
  for (std::size_t k = 0; k < damping_ratios.size(); ++k) {
    if (!(damping_ratios[k] >= 0.0 && damping_ratios[k] < 1.0)) {
      throw InvalidParameter(
          {fmt::format("damping_ratios[{}]", k), damping_ratios[k], "must be in [0, 1)"});
    }
  }
}

SpectralOrdinate OrdinateFromDeformation(double period, double deformation, double time_of_peak) {
  const double omega = 2.0 * std::numbers::pi / period;
  return {deformation, omega * deformation, omega * omega * deformation, time_of_peak};
}

ElasticSpectrum ComputeElasticSpectrum(const integrators::SampledHistory& ground,
                                       std::span<const double> periods,
                                       std::span<const double> damping_ratios,
                                       const ElasticSpectrumOptions& options) {
  options.Validate();
  ValidateSpectrumInput(ground, periods, damping_ratios);
  ElasticSpectrum spectrum;
  spectrum.periods.assign(periods.begin(), periods.end());
  spectrum.damping_ratios.assign(damping_ratios.begin(), damping_ratios.end());
  spectrum.ordinates.reserve(periods.size() * damping_ratios.size());
  for (const double zeta : damping_ratios) {
    for (const double period : periods) {
      const PeakDeformation peak =
          ExactPeakDeformation(ground, period, zeta, options.points_per_period);
      spectrum.ordinates.push_back(OrdinateFromDeformation(period, peak.value, peak.time));
    }
  }
  return spectrum;
}

}  // namespace isolab::spectra
