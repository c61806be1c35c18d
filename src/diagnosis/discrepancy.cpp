#include "isolab/diagnosis/discrepancy.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace isolab::diagnosis {
namespace {

using identification::CycleSpan;
using identification::CyclicTestData;

// Mean displacement and force over the samples of a span within 3 % of its extreme displacement
// on one side (sign +1: the positive peak).
std::pair<double, double> PeakMean(const std::vector<double>& u, const std::vector<double>& f,
                                   CycleSpan span, double sign) {
  double extreme = 0.0;
  for (std::size_t k = span.begin; k < span.end; ++k) extreme = std::max(extreme, sign * u[k]);
  double u_sum = 0.0, f_sum = 0.0;
  int count = 0;
  for (std::size_t k = span.begin; k < span.end; ++k) {
    if (sign * u[k] >= 0.97 * extreme) {
      u_sum += u[k];
      f_sum += f[k];
      ++count;
    }
  }
  if (count == 0) return {NAN, NAN};  // an empty span: no peak to read
  return {u_sum / count, f_sum / count};
}

LoopMeasure Measure(const std::vector<double>& u, const std::vector<double>& f, CycleSpan span) {
  const auto [u_plus, f_plus] = PeakMean(u, f, span, 1.0);
  const auto [u_minus, f_minus] = PeakMean(u, f, span, -1.0);
  return {identification::LoopEnergy(u, f, span), (f_plus - f_minus) / (u_plus - u_minus)};
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

identification::FitData AllCycles(std::vector<CyclicTestData> tests) {
  identification::FitData data;
  for (const CyclicTestData& test : tests) {
    if (test.cycles.empty()) throw std::invalid_argument("test '" + test.name + "' has no cycle");
    for (const CycleSpan& span : test.cycles) {
      if (!(span.begin + 1 < span.end && span.end <= test.displacement.size())) {
        throw std::invalid_argument("test '" + test.name + "' has an empty or out-of-range cycle");
      }
    }
    data.fitted.push_back(test.cycles);
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
  for (std::size_t i = 0; i < data.tests.size(); ++i) {
    const CyclicTestData& test = data.tests[i];
    d.model_force.push_back(identification::SimulateForce(model, test));
    d.velocity.push_back(CentralVelocity(test));
    d.force_noise.push_back(ForceNoise(test));
    for (const CycleSpan& span : data.fitted[i]) {
      const auto where = std::find_if(test.cycles.begin(), test.cycles.end(),
                                      [&](const CycleSpan& c) { return c.begin == span.begin; });
      CycleRecord record;
      record.test = static_cast<int>(i);
      record.cycle = static_cast<int>(where - test.cycles.begin()) + 1;
      record.amplitude = identification::SpanAmplitude(test.displacement, span);
      record.period = test.time[span.end - 1] - test.time[span.begin];
      if (span.end < test.time.size()) record.period = test.time[span.end] - test.time[span.begin];
      record.measured = Measure(test.displacement, test.force, span);
      record.modelled = Measure(test.displacement, d.model_force[i], span);
      d.cycles.push_back(record);
    }
  }
  return d;
}

}  // namespace isolab::diagnosis
