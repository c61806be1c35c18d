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

std::vector<CycleSpan> SplitHalfCycles(const std::vector<double>& u) {
  std::vector<CycleSpan> halves;
  if (u.size() < 3) return halves;
  const auto [low, high] = std::minmax_element(u.begin(), u.end());
  const double band = kReversalBand * (*high - *low);
  if (!(band > 0.0)) return halves;
  // Before the first move by more than the band the direction is unknown: track both extremes.
  std::size_t extreme = 0, low_at = 0, high_at = 0;
  int direction = 0;  // +1 rising, -1 falling
  std::vector<std::size_t> reversals;
  for (std::size_t k = 1; k < u.size(); ++k) {
    if (direction == 0) {
      if (u[k] > u[high_at]) high_at = k;
      if (u[k] < u[low_at]) low_at = k;
      if (u[high_at] - u[low_at] > band) {
        // The later of the two extremes is where the motion now heads from.
        direction = high_at > low_at ? 1 : -1;
        extreme = direction > 0 ? high_at : low_at;
      }
      continue;
    }
    if (direction * (u[k] - u[extreme]) > 0.0) {
      extreme = k;  // still going the same way
    } else if (direction * (u[extreme] - u[k]) > band) {
      reversals.push_back(extreme);  // came back by more than the band: a reversal
      direction = -direction;
      extreme = k;
    }
  }
  for (std::size_t r = 0; r + 1 < reversals.size(); ++r) {
    halves.push_back({reversals[r], reversals[r + 1] + 1});
  }
  return halves;
}

void Segment(CyclicTestData* test) {
  test->cycles = SplitCycles(test->displacement);
  test->half_cycles = SplitHalfCycles(test->displacement);
}

void SimulateForceFrom(const hysteresis::ParallelAssembly& assembly, const CyclicTestData& test,
                       std::span<hysteresis::LawState> state, std::span<double> force) {
  std::vector<hysteresis::LawState> committed(state.begin(), state.end()),
      trial(assembly.state_size());
  std::vector<hysteresis::LawResponse> responses(assembly.size());
  for (std::size_t k = 0; k < force.size(); ++k) {
    const double dt = k > 0 ? test.time[k] - test.time[k - 1] : 0.0;
    const double v = dt > 0.0 ? (test.displacement[k] - test.displacement[k - 1]) / dt : 0.0;
    // The test's own clock drives the laws that read time (the lead core's heat conduction).
    force[k] =
        assembly.Update(committed, {test.displacement[k], v, test.time[k]}, trial, responses).force;
    std::swap(committed, trial);
  }
  std::copy(committed.begin(), committed.end(), state.begin());
}

std::vector<double> SimulateForce(const hysteresis::ParallelAssembly& assembly,
                                  const CyclicTestData& test) {
  std::vector<hysteresis::LawState> state(assembly.state_size());
  std::vector<double> force(test.displacement.size());
  SimulateForceFrom(assembly, test, state, force);
  return force;
}

std::vector<std::vector<double>> SimulateForces(const hysteresis::ParallelAssembly& assembly,
                                                std::span<const CyclicTestData> tests,
                                                bool one_specimen) {
  std::vector<std::vector<double>> forces;
  std::vector<hysteresis::LawState> state(assembly.state_size());
  for (const CyclicTestData& test : tests) {
    if (!one_specimen) std::fill(state.begin(), state.end(), hysteresis::LawState{});
    forces.emplace_back(test.displacement.size());
    SimulateForceFrom(assembly, test, state, forces.back());
  }
  return forces;
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

double HalfCycleEnergy(const std::vector<double>& u, const std::vector<double>& f, CycleSpan span) {
  double work = 0.0;
  for (std::size_t k = span.begin + 1; k < span.end; ++k) {
    work += 0.5 * (f[k] + f[k - 1]) * (u[k] - u[k - 1]);
  }
  const std::size_t a = span.begin, b = span.end - 1;
  return work - 0.5 * (f[a] + f[b]) * (u[b] - u[a]);
}

double SpanAmplitude(const std::vector<double>& u, CycleSpan span) {
  double amplitude = 0.0;
  for (std::size_t k = span.begin; k < span.end; ++k)
    amplitude = std::max(amplitude, std::abs(u[k]));
  return amplitude;
}

double HalfRange(const std::vector<double>& u, CycleSpan span) {
  const auto [low, high] = std::minmax_element(u.begin() + span.begin, u.begin() + span.end);
  return 0.5 * (*high - *low);
}

}  // namespace isolab::identification
