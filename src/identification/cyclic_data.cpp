#include "isolab/identification/cyclic_data.h"

#include <algorithm>
#include <cmath>

namespace isolab::identification {

std::vector<CycleSpan> SplitCycles(const std::vector<double>& u) {
  std::vector<std::size_t> starts{0};
  for (std::size_t i = 1; i < u.size(); ++i) {
    // An upward crossing; one at the very start (from u = 0 at rest) opens the first cycle.
    if (u[i - 1] <= 0.0 && u[i] > 0.0 && i > 1) starts.push_back(i);
  }
  starts.push_back(u.size());
  std::vector<CycleSpan> cycles;
  for (std::size_t k = 0; k + 1 < starts.size(); ++k) {
    const CycleSpan span{starts[k], starts[k + 1]};
    const auto [low, high] = std::minmax_element(u.begin() + span.begin, u.begin() + span.end);
    // A whole cycle swings both ways by comparable amounts.
    const double swing = std::max(std::abs(*low), std::abs(*high));
    if (swing > 0.0 && *high >= 0.5 * swing && *low <= -0.5 * swing) cycles.push_back(span);
  }
  return cycles;
}

std::vector<double> SimulateForce(const hysteresis::ParallelAssembly& assembly,
                                  const CyclicTestData& test) {
  std::vector<hysteresis::LawState> committed(assembly.size()), trial(assembly.size());
  std::vector<hysteresis::LawResponse> responses(assembly.size());
  std::vector<double> force(test.displacement.size());
  for (std::size_t k = 0; k < force.size(); ++k) {
    const double dt = k > 0 ? test.time[k] - test.time[k - 1] : 0.0;
    const double v = dt > 0.0 ? (test.displacement[k] - test.displacement[k - 1]) / dt : 0.0;
    force[k] = assembly.Update(committed, {test.displacement[k], v}, trial, responses).force;
    std::swap(committed, trial);
  }
  return force;
}

double LoopEnergy(const std::vector<double>& u, const std::vector<double>& f, CycleSpan span) {
  double energy = 0.0;
  for (std::size_t k = span.begin + 1; k < span.end; ++k) {
    energy += 0.5 * (f[k] + f[k - 1]) * (u[k] - u[k - 1]);
  }
  // Close the loop with the step into the next cycle's first sample, when there is one.
  if (span.end < u.size()) {
    energy += 0.5 * (f[span.end] + f[span.end - 1]) * (u[span.end] - u[span.end - 1]);
  }
  return energy;
}

double SpanAmplitude(const std::vector<double>& u, CycleSpan span) {
  double amplitude = 0.0;
  for (std::size_t k = span.begin; k < span.end; ++k) amplitude = std::max(amplitude, std::abs(u[k]));
  return amplitude;
}

}  // namespace isolab::identification
