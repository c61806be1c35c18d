#include "isolab/identification/testing_factors.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace isolab::identification {
namespace {

PropertyFactors FactorsOf(const std::vector<double>& values) {
  PropertyFactors f;
  for (const double v : values) f.nominal += v / static_cast<double>(values.size());
  const auto [low, high] = std::minmax_element(values.begin(), values.end());
  f.min = *low / f.nominal;
  f.max = *high / f.nominal;
  return f;
}

}  // namespace

CycleProperties PropertiesOfCycle(const CyclicTestData& test, CycleSpan cycle) {
  std::size_t top = cycle.begin, bottom = cycle.begin;
  for (std::size_t i = cycle.begin; i < cycle.end; ++i) {
    if (test.displacement[i] > test.displacement[top]) top = i;
    if (test.displacement[i] < test.displacement[bottom]) bottom = i;
  }
  CycleProperties p;
  const double travel = std::abs(test.displacement[top]) + std::abs(test.displacement[bottom]);
  p.amplitude = 0.5 * travel;
  p.effective_stiffness = (std::abs(test.force[top]) + std::abs(test.force[bottom])) / travel;
  // The loop from zero crossing to zero crossing: the cycle's samples with the crossing before
  // its first and after its last interpolated (where the data have them), by trapezoids, closed
  // by the chord back to its start (a loop that stops short of its crossing).
  const std::vector<double>& u = test.displacement;
  const std::vector<double>& f = test.force;
  std::vector<std::pair<double, double>> path;  // (u, F)
  const auto crossing = [&](std::size_t a) {    // on the step from a to a + 1
    const double t = u[a] / (u[a] - u[a + 1]);
    return std::pair{0.0, f[a] + t * (f[a + 1] - f[a])};
  };
  if (cycle.begin > 0 && u[cycle.begin - 1] < 0.0 && u[cycle.begin] >= 0.0) {
    path.push_back(crossing(cycle.begin - 1));
  }
  for (std::size_t k = cycle.begin; k < cycle.end; ++k) path.push_back({u[k], f[k]});
  if (cycle.end < u.size() && u[cycle.end - 1] < 0.0 && u[cycle.end] >= 0.0) {
    path.push_back(crossing(cycle.end - 1));
  }
  path.push_back(path.front());
  for (std::size_t k = 1; k < path.size(); ++k) {
    p.dissipated +=
        0.5 * (path[k].second + path[k - 1].second) * (path[k].first - path[k - 1].first);
  }
  p.qd = p.dissipated / (4.0 * p.amplitude);
  p.kd = p.effective_stiffness - p.qd / p.amplitude;
  return p;
}

TestingFactors TestingFactorsOf(std::span<const CyclicTestData> tests) {
  TestingFactors factors;
  std::vector<double> qd_min, qd_max, kd_min, kd_max, qd, kd;
  for (const CyclicTestData& test : tests) {
    if (test.cycles.size() < static_cast<std::size_t>(kTestCycles)) {
      factors.skipped.push_back(test.name);
      continue;
    }
    TestProperties t;
    t.test = test.name;
    std::vector<double> q, k;
    for (int c = 0; c < kTestCycles; ++c) {
      t.cycles.push_back(PropertiesOfCycle(test, test.cycles[c]));
      q.push_back(t.cycles.back().qd);
      k.push_back(t.cycles.back().kd);
    }
    t.qd = FactorsOf(q);
    t.kd = FactorsOf(k);
    qd.push_back(t.qd.nominal);
    kd.push_back(t.kd.nominal);
    factors.tests.push_back(std::move(t));
  }
  if (factors.tests.empty()) return factors;
  factors.qd = FactorsOf(qd);
  factors.kd = FactorsOf(kd);
  factors.qd.min = factors.kd.min = 1.0;
  factors.qd.max = factors.kd.max = 1.0;
  for (const TestProperties& t : factors.tests) {
    factors.qd.min = std::min(factors.qd.min, t.qd.min);
    factors.qd.max = std::max(factors.qd.max, t.qd.max);
    factors.kd.min = std::min(factors.kd.min, t.kd.min);
    factors.kd.max = std::max(factors.kd.max, t.kd.max);
  }
  return factors;
}

}  // namespace isolab::identification
