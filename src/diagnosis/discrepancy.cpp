#include "isolab/diagnosis/discrepancy.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "isolab/diagnosis/spectral.h"

namespace isolab::diagnosis {
namespace {

using identification::CycleSpan;
using identification::CyclicTestData;

// Mean displacement and force over the samples of a half-cycle within 3 % of its range of the
// reversal sample `at`.
std::pair<double, double> ReversalMean(const std::vector<double>& u, const std::vector<double>& f,
                                       CycleSpan span, std::size_t at, double range) {
  double u_sum = 0.0, f_sum = 0.0;
  int count = 0;
  for (std::size_t k = span.begin; k < span.end; ++k) {
    if (std::abs(u[k] - u[at]) <= 0.03 * range) {
      u_sum += u[k];
      f_sum += f[k];
      ++count;
    }
  }
  return {u_sum / count, f_sum / count};  // count >= 1: `at` itself
}

// The half-cycle's energy (identification::HalfCycleEnergy) with the chord's end forces averaged
// near the reversals as the secant's are: single samples there would carry their noise into it.
LoopMeasure Measure(const std::vector<double>& u, const std::vector<double>& f, CycleSpan span) {
  const double range = 2.0 * identification::HalfRange(u, span);
  const auto [u_a, f_a] = ReversalMean(u, f, span, span.begin, range);
  const auto [u_b, f_b] = ReversalMean(u, f, span, span.end - 1, range);
  const std::size_t a = span.begin, b = span.end - 1;
  const double chord_correction = 0.5 * (f[a] + f[b] - f_a - f_b) * (u[b] - u[a]);
  return {identification::HalfCycleEnergy(u, f, span) + chord_correction, (f_b - f_a) / (u_b - u_a),
          f_a, f_b};
}

double Median(std::vector<double> values) {
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

// Samples at rest: the displacement within this share of its range of its first value, at least
// this many of them.
constexpr double kRestBand = 1e-3;
constexpr std::size_t kRestSamples = 64;

std::vector<double> CentralVelocity(const CyclicTestData& test) {
  const std::size_t n = test.time.size();
  std::vector<double> v(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t a = k > 0 ? k - 1 : k, b = k + 1 < n ? k + 1 : k;
    const double dt = test.time[b] - test.time[a];
    if (dt > 0.0) v[k] = (test.displacement[b] - test.displacement[a]) / dt;
  }
  return v;
}

}  // namespace

double SecondDifferenceNoise(const CyclicTestData& test) {
  const std::vector<double>& f = test.force;
  if (f.size() < 5) return 0.0;
  std::vector<double> second;
  second.reserve(f.size());
  for (std::size_t k = 1; k + 1 < f.size(); ++k) second.push_back(f[k + 1] - 2.0 * f[k] + f[k - 1]);
  const double center = Median(second);
  for (double& d : second) d = std::abs(d - center);
  // 1.4826 MAD is the standard deviation of a Gaussian.
  return 1.4826 * Median(second) / std::sqrt(6.0);
}

std::string NoiseEstimate::Describe() const {
  const std::string rest = fmt::format("rest, {} samples", rest_samples);
  const std::string band = fmt::format("band {:.3g}-{:.4g} per unit time", band_low, nyquist);
  if (uncertain) {
    return fmt::format("uncertain: {} read {:.4g}, {} read {:.4g}; the larger taken", rest,
                       rest_sigma, band, band_sigma);
  }
  switch (source) {
    case Source::kRest:
      return rest;
    case Source::kBand:
      return band;
    case Source::kNone:
      break;
  }
  return "second differences (no band above the response)";
}

NoiseEstimate EstimateForceNoise(const CyclicTestData& test) {
  return EstimateNoise(test, test.force);
}

namespace {

// The rest read (discrepancy.h): sets rest_samples and rest_sigma where there are enough samples
// at rest before the motion.
void ReadAtRest(const CyclicTestData& test, const std::vector<double>& f, NoiseEstimate& estimate) {
  const std::vector<double>& u = test.displacement;
  const std::size_t n = f.size();
  const auto [low, high] = std::minmax_element(u.begin(), u.end());
  const double range = *high - *low;
  std::size_t rest = 0;
  while (rest < n && std::abs(u[rest] - u[0]) <= kRestBand * range) ++rest;
  if (rest < kRestSamples) return;
  double sum = 0.0, square = 0.0;
  for (std::size_t k = 0; k < rest; ++k) sum += f[k], square += f[k] * f[k];
  const double mean = sum / double(rest);
  const double sigma = std::sqrt(std::max(square / double(rest) - mean * mean, 0.0) *
                                 double(rest) / double(rest - 1));
  // A channel that reads one value at rest (a quantised load cell whose noise is below its step)
  // shows no noise there: no read, not a floor of zero.
  if (!(sigma > 0.0)) return;
  estimate.rest_sigma = sigma;
  estimate.rest_samples = static_cast<long>(rest);
}

// The band read (discrepancy.h): sets band_sigma, band_low and nyquist where there is a band
// above the response to read.
void ReadAboveTheResponse(const CyclicTestData& test, const std::vector<double>& f,
                          NoiseEstimate& estimate) {
  const std::vector<double>& u = test.displacement;
  const std::size_t n = f.size();
  const double dt = (test.time.back() - test.time.front()) / double(n - 1);
  if (!(dt > 0.0)) return;
  const double nyquist = 0.5 / dt;
  const std::size_t m = PaddedLength(n);
  const double bin = 1.0 / (double(m) * dt);
  // The band of the device's response: ten times the frequency below which 99 % of the
  // displacement's power lies.
  const std::vector<double> motion = Periodogram(u);
  const double total = std::accumulate(motion.begin(), motion.end(), 0.0);
  double cumulative = 0.0, motion_band = 0.0;
  for (std::size_t k = 0; k < motion.size(); ++k) {
    cumulative += motion[k];
    if (cumulative >= 0.99 * total) {
      motion_band = (double(k) + 1.0) * bin;
      break;
    }
  }
  const double band_low = std::min(10.0 * motion_band, 0.5 * nyquist);
  const std::vector<double> power = Periodogram(f);
  // Octave by octave above the band: a low quantile over the periodogram's chi-squared (2
  // degrees of freedom, exponential) spread, which harmonic lines in a few bins do not move.
  constexpr double kQuantile = 0.25;
  const double quantile_of_mean = -std::log(1.0 - kQuantile);
  double integral = 0.0, first_level = -1.0;
  // Quarter octaves, so the integral follows a spectrum that rolls off, as a load cell's filter
  // makes it, and a quantile within a band does not read its low end; but at least 128 bins each:
  // neighbouring ordinates of a windowed, padded periodogram move together, and a quantile of a
  // few independent ones reads high (16 bins of a 601-sample test read white noise 16 % high).
  constexpr double kBandBins = 128.0;
  std::vector<double> first_octave;
  for (double lo = band_low; lo < nyquist;) {
    double hi = std::min(lo * std::pow(2.0, 0.25), nyquist);
    hi = std::min(std::max(hi, lo + kBandBins * bin), nyquist);
    if (nyquist - hi < 0.5 * (hi - lo)) hi = nyquist;  // no sliver of a band at the top
    std::vector<double> ordinates;
    for (std::size_t k = static_cast<std::size_t>(std::ceil(lo / bin));
         k < power.size() && double(k) * bin < hi; ++k) {
      ordinates.push_back(power[k]);
    }
    if (ordinates.size() >= 4) {
      const auto at =
          ordinates.begin() + static_cast<std::ptrdiff_t>(kQuantile * double(ordinates.size() - 1));
      std::nth_element(ordinates.begin(), at, ordinates.end());
      const double level = *at / quantile_of_mean;
      if (lo < 2.0 * band_low) first_octave.push_back(level);
      if (first_level < 0.0) first_level = level;
      integral += level * (hi - lo);
    } else if (first_level >= 0.0) {
      integral += first_level * (hi - lo);  // too few bins to read: as the first band
    }
    lo = hi;
  }
  if (first_level < 0.0) return;  // no band above the response to read
  // Below the band the noise is taken at the median level of the first octave above it: lines of
  // the loops' harmonics raise a few bands' levels, which the median passes over.
  if (!first_octave.empty()) first_level = Median(first_octave);
  estimate.band_sigma = std::sqrt((first_level * band_low + integral) / nyquist);
  estimate.band_low = band_low;
  estimate.nyquist = nyquist;
}

}  // namespace

NoiseEstimate EstimateNoise(const CyclicTestData& test, const std::vector<double>& f) {
  NoiseEstimate estimate;
  if (f.size() < 8) return estimate;
  ReadAtRest(test, f, estimate);
  ReadAboveTheResponse(test, f, estimate);
  const bool rest = estimate.rest_samples > 0, band = estimate.band_low > 0.0;
  if (rest && band) {
    const double larger = std::max(estimate.rest_sigma, estimate.band_sigma);
    estimate.uncertain =
        !(larger <= kNoiseReadsAgree * std::min(estimate.rest_sigma, estimate.band_sigma));
    const bool from_band = estimate.uncertain && estimate.band_sigma > estimate.rest_sigma;
    estimate.source = from_band ? NoiseEstimate::Source::kBand : NoiseEstimate::Source::kRest;
    estimate.sigma = from_band ? estimate.band_sigma : estimate.rest_sigma;
  } else if (rest || band) {
    estimate.source = rest ? NoiseEstimate::Source::kRest : NoiseEstimate::Source::kBand;
    estimate.sigma = rest ? estimate.rest_sigma : estimate.band_sigma;
  } else {
    CyclicTestData series = test;
    series.force = f;
    estimate.sigma = SecondDifferenceNoise(series);
  }
  return estimate;
}

double NoiseFloor(const identification::FitData& data, const std::vector<double>& force_noise) {
  double floor = 0.0;
  for (std::size_t i = 0; i < data.tests.size(); ++i) {
    double norm = 0.0;
    long samples = 0;
    for (const CycleSpan& span : data.fitted[i]) {
      for (std::size_t k = span.begin; k < span.end; ++k)
        norm += std::pow(data.tests[i].force[k], 2);
      samples += static_cast<long>(span.end - span.begin);
    }
    if (norm > 0.0) floor += samples * force_noise[i] * force_noise[i] / norm;
  }
  return floor;
}

identification::FitData AllCycles(std::vector<CyclicTestData> tests, bool one_specimen) {
  identification::FitData data;
  data.one_specimen = one_specimen;
  for (const CyclicTestData& test : tests) {
    if (test.half_cycles.empty()) {
      throw std::invalid_argument("test '" + test.name +
                                  "' has no half-cycle between two reversals");
    }
    data.fitted.push_back({{0, test.displacement.size()}});
  }
  data.tests = std::move(tests);
  return data;
}

std::vector<double> Discrepancy::Residual(std::size_t test) const {
  std::vector<double> residual;
  const auto& t = data->tests[test];
  for (const CycleSpan& span : data->fitted[test]) {
    for (std::size_t k = span.begin; k < span.end; ++k) {
      residual.push_back(t.force[k] - model_force[test][k]);
    }
  }
  return residual;
}

std::vector<double> CorrelationTimes(const Discrepancy& d) {
  std::vector<double> times;
  for (std::size_t i = 0; i < d.data->tests.size(); ++i) {
    times.push_back(IntegratedCorrelationTime(d.Residual(i)));
  }
  return times;
}

double EffectiveSamples(const Discrepancy& d) {
  const std::vector<double> times = CorrelationTimes(d);
  double effective = 0.0;
  for (std::size_t i = 0; i < d.data->tests.size(); ++i) {
    long samples = 0;
    for (const CycleSpan& span : d.data->fitted[i]) samples += long(span.end - span.begin);
    effective += double(samples) / times[i];
  }
  return std::max(effective, 1.0);
}

long SampleCount(const identification::FitData& data) {
  long samples = 0;
  for (const auto& spans : data.fitted) {
    for (const CycleSpan& span : spans) samples += static_cast<long>(span.end - span.begin);
  }
  return samples;
}

Discrepancy Discrepancy::Of(const hysteresis::ParallelAssembly& model,
                            const identification::FitData& data,
                            const std::vector<NoiseEstimate>* noise) {
  Discrepancy d;
  d.data = &data;
  d.model_force = identification::SimulateForces(model, data.tests, data.one_specimen);
  for (std::size_t i = 0; i < data.tests.size(); ++i) {
    const CyclicTestData& test = data.tests[i];
    d.velocity.push_back(CentralVelocity(test));
    // The residual's noise reads lower than the force's where the model has taken out the
    // loops' harmonics; neither can read below the noise itself, so the lower one is kept.
    std::vector<double> residual(test.force.size());
    for (std::size_t k = 0; k < residual.size(); ++k)
      residual[k] = test.force[k] - d.model_force[i][k];
    NoiseEstimate estimate = EstimateNoise(test, residual);
    const NoiseEstimate& force = noise ? (*noise)[i] : EstimateForceNoise(test);
    if (force.sigma < estimate.sigma) estimate = force;
    d.noise.push_back(estimate);
    d.force_noise.push_back(estimate.sigma);
    for (std::size_t h = 0; h < test.half_cycles.size(); ++h) {
      const CycleSpan half = test.half_cycles[h];
      const bool fitted = std::any_of(
          data.fitted[i].begin(), data.fitted[i].end(),
          [&](const CycleSpan& span) { return span.begin <= half.begin && half.end <= span.end; });
      if (!fitted) continue;
      CycleRecord record;
      record.test = static_cast<int>(i);
      record.cycle = static_cast<int>(h) + 1;
      record.amplitude = identification::HalfRange(test.displacement, half);
      record.period = 2.0 * (test.time[half.end - 1] - test.time[half.begin]);
      record.measured = Measure(test.displacement, test.force, half);
      record.modelled = Measure(test.displacement, d.model_force[i], half);
      d.cycles.push_back(record);
    }
  }
  return d;
}

}  // namespace isolab::diagnosis
