// Scaling a suite of record pairs to a target spectrum (suite_scaling.h, ASCE 7-16 Sec. 17.3.3).
#include "isolab/spectra/suite_scaling.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "isolab/core/errors.h"

namespace isolab::spectra {
namespace {

void RequirePositive(const std::string& key, double value) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw InvalidParameter({key, value, "must be finite and > 0"});
  }
}

// The target must be defined at an end of the range: its own refusal, under the end's name.
void RequireDefinedAt(const TargetSpectrum& target, const char* key, double period) {
  try {
    SpectralAcceleration(target, period);
  } catch (const InvalidParameter& error) {
    if (error.violation().key != "period") throw;
    throw InvalidParameter({key, period, error.violation().rule});
  }
}

}  // namespace

std::vector<double> ScalingPeriods(const TargetSpectrum& target, double lo, double hi, int count) {
  Validate(target);
  RequirePositive("lo", lo);
  if (!(hi > lo) || !std::isfinite(hi)) {
    throw InvalidParameter({"hi", hi, fmt::format("must be finite and > lo = {:g}", lo)});
  }
  if (count < 2) throw InvalidParameter({"count", double(count), "must be >= 2"});
  RequireDefinedAt(target, "lo", lo);
  RequireDefinedAt(target, "hi", hi);

  std::vector<double> periods;
  const double ratio = std::log(hi / lo);
  for (int k = 0; k < count; ++k) periods.push_back(lo * std::exp(ratio * k / (count - 1)));
  periods.front() = lo;
  periods.back() = hi;
  for (const double corner : CornerPeriods(target)) {
    if (corner > lo && corner < hi) periods.push_back(corner);
  }
  std::sort(periods.begin(), periods.end());
  const auto same = [](double a, double b) { return std::abs(b - a) <= 1e-12 * std::abs(b); };
  periods.erase(std::unique(periods.begin(), periods.end(), same), periods.end());
  return periods;
}

SuiteScaling ScaleSuite(std::span<const double> periods, std::span<const double> target_sa,
                        const std::vector<std::vector<double>>& rotd100) {
  const std::size_t n = periods.size();
  if (n == 0) throw InvalidParameter({"periods", 0.0, "at least one is needed"});
  if (target_sa.size() != n) {
    throw InvalidParameter({"target_sa", double(target_sa.size()),
                            fmt::format("must have one value per period ({})", n)});
  }
  if (rotd100.empty()) throw InvalidParameter({"rotd100", 0.0, "at least one pair is needed"});
  for (std::size_t p = 0; p < n; ++p) {
    RequirePositive(fmt::format("periods[{}]", p), periods[p]);
    RequirePositive(fmt::format("target_sa[{}]", p), target_sa[p]);
  }
  for (std::size_t i = 0; i < rotd100.size(); ++i) {
    if (rotd100[i].size() != n) {
      throw InvalidParameter({fmt::format("rotd100[{}]", i), double(rotd100[i].size()),
                              fmt::format("must have one value per period ({})", n)});
    }
    for (std::size_t p = 0; p < n; ++p) {
      RequirePositive(fmt::format("rotd100[{}][{}]", i, p), rotd100[i][p]);
    }
  }

  SuiteScaling scaling;
  scaling.periods.assign(periods.begin(), periods.end());
  scaling.target.assign(target_sa.begin(), target_sa.end());
  const double pairs = static_cast<double>(rotd100.size());

  // Step 1: each pair's geometric-mean misfit to the target over the grid.
  for (const std::vector<double>& spectrum : rotd100) {
    double log_sum = 0.0;
    for (std::size_t p = 0; p < n; ++p) log_sum += std::log(target_sa[p] / spectrum[p]);
    scaling.pair_shape_factors.push_back(std::exp(log_sum / static_cast<double>(n)));
  }

  // Step 2: the shaped mean's largest shortfall (a factor below 1 when it is above the target
  // everywhere).
  scaling.common_factor = 0.0;
  for (std::size_t p = 0; p < n; ++p) {
    double shaped_mean = 0.0;
    for (std::size_t i = 0; i < rotd100.size(); ++i) {
      shaped_mean += scaling.pair_shape_factors[i] * rotd100[i][p];
    }
    shaped_mean /= pairs;
    scaling.common_factor = std::max(scaling.common_factor, target_sa[p] / shaped_mean);
  }

  for (const double shape : scaling.pair_shape_factors) {
    scaling.factors.push_back(scaling.common_factor * shape);
  }
  for (std::size_t p = 0; p < n; ++p) {
    double mean = 0.0;
    for (std::size_t i = 0; i < rotd100.size(); ++i) mean += scaling.factors[i] * rotd100[i][p];
    scaling.scaled_mean.push_back(mean / pairs);
    const std::size_t g = scaling.governing;
    if (scaling.scaled_mean[p] / target_sa[p] < scaling.scaled_mean[g] / target_sa[g]) {
      scaling.governing = p;
    }
  }
  return scaling;
}

}  // namespace isolab::spectra
