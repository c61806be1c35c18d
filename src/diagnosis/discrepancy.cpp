#include "isolab/diagnosis/discrepancy.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

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
  return {identification::HalfCycleEnergy(u, f, span) + chord_correction,
          (f_b - f_a) / (u_b - u_a)};
}

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

double ForceNoise(const CyclicTestData& test) {
  const std::vector<double>& f = test.force;
  if (f.size() < 5) return 0.0;
  std::vector<double> second;
  second.reserve(f.size());
  for (std::size_t k = 1; k + 1 < f.size(); ++k) second.push_back(f[k + 1] - 2.0 * f[k] + f[k - 1]);
  const auto median = [](std::vector<double> values) {
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
  };
  const double center = median(second);
  for (double& d : second) d = std::abs(d - center);
  // 1.4826 MAD is the standard deviation of a Gaussian.
  return 1.4826 * median(second) / std::sqrt(6.0);
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

double ResidualCorrelation(const Discrepancy& d) {
  double lagged = 0.0, square = 0.0;
  for (std::size_t i = 0; i < d.data->tests.size(); ++i) {
    const auto& test = d.data->tests[i];
    double norm = 0.0, test_lagged = 0.0, test_square = 0.0;
    for (const CycleSpan& span : d.data->fitted[i]) {
      for (std::size_t k = span.begin; k < span.end; ++k) {
        const double r = test.force[k] - d.model_force[i][k];
        norm += test.force[k] * test.force[k];
        test_square += r * r;
        if (k > span.begin) test_lagged += r * (test.force[k - 1] - d.model_force[i][k - 1]);
      }
    }
    const double w = norm > 0.0 ? 1.0 / norm : 0.0;
    lagged += w * test_lagged;
    square += w * test_square;
  }
  return square > 0.0 ? std::clamp(lagged / square, 0.0, 0.99) : 0.0;
}

double EffectiveSamples(long samples, double rho) {
  return static_cast<double>(samples) * (1.0 - rho) / (1.0 + rho);
}

long SampleCount(const identification::FitData& data) {
  long samples = 0;
  for (const auto& spans : data.fitted) {
    for (const CycleSpan& span : spans) samples += static_cast<long>(span.end - span.begin);
  }
  return samples;
}

Discrepancy Discrepancy::Of(const hysteresis::ParallelAssembly& model,
                            const identification::FitData& data) {
  Discrepancy d;
  d.data = &data;
  d.model_force = identification::SimulateForces(model, data.tests, data.one_specimen);
  for (std::size_t i = 0; i < data.tests.size(); ++i) {
    const CyclicTestData& test = data.tests[i];
    d.velocity.push_back(CentralVelocity(test));
    d.force_noise.push_back(ForceNoise(test));
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
