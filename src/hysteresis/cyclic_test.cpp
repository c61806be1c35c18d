#include "isolab/hysteresis/cyclic_test.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "isolab/core/errors.h"

namespace isolab::hysteresis {

void CyclicProtocol::Validate() const {
  if (!(amplitude > 0.0 && std::isfinite(amplitude))) {
    throw InvalidParameter({"amplitude", amplitude, "must be > 0 and finite"});
  }
  if (!(period > 0.0 && std::isfinite(period))) {
    throw InvalidParameter({"period", period, "must be > 0 and finite"});
  }
  if (cycles < 1) throw InvalidParameter({"cycles", double(cycles), "must be >= 1"});
  if (steps_per_cycle < 4 || steps_per_cycle % 4 != 0) {
    throw InvalidParameter(
        {"steps_per_cycle", double(steps_per_cycle), "must be a multiple of 4, at least 4"});
  }
  if (double(cycles) * steps_per_cycle > 1e8) {
    throw InvalidParameter(
        {"steps_per_cycle", double(steps_per_cycle), "times cycles must be <= 1e8 samples"});
  }
}

CyclicResult RunCyclicTest(const ParallelAssembly& assembly, const CyclicProtocol& protocol) {
  std::vector<LawState> rest(assembly.state_size());
  return RunCyclicTest(assembly, protocol, rest);
}

CyclicResult RunCyclicTest(const ParallelAssembly& assembly, const CyclicProtocol& protocol,
                           std::span<LawState> state) {
  protocol.Validate();
  const std::size_t n_components = assembly.size();
  const int per_cycle = protocol.steps_per_cycle;
  const int samples = protocol.cycles * per_cycle + 1;
  const double omega = 2.0 * std::numbers::pi / protocol.period;

  CyclicResult result;
  result.protocol = protocol;
  CyclicLoop& loop = result.loop;
  loop.time.resize(samples);
  loop.displacement.resize(samples);
  loop.force.resize(samples);
  loop.component_force.resize(samples * n_components);

  std::vector<LawState> committed(state.begin(), state.end()), trial(assembly.state_size());
  std::vector<LawResponse> responses(n_components);
  std::vector<double> dissipated_at_cycle_start(n_components);
  for (std::size_t c = 0; c < n_components; ++c) dissipated_at_cycle_start[c] = state[c].dissipated;
  CycleSummary cycle;

  for (int k = 0; k < samples; ++k) {
    // The phase restarts every cycle so u = +-u_a lands on exact quarter-cycle samples.
    const int in_cycle = k % per_cycle;
    const double phase = 2.0 * std::numbers::pi * in_cycle / per_cycle;
    const LawInput in{protocol.amplitude * std::sin(phase),
                      protocol.amplitude * omega * std::cos(phase),
                      k * protocol.period / per_cycle};
    const AssemblyResponse total = assembly.Update(committed, in, trial, responses);
    std::swap(committed, trial);

    loop.time[k] = in.t;
    loop.displacement[k] = in.u;
    loop.force[k] = total.force;
    for (std::size_t c = 0; c < n_components; ++c) {
      loop.component_force[k * n_components + c] = responses[c].force;
    }

    if (k == 0) continue;  // the state at rest opens the first cycle
    cycle.peak_force = std::max(cycle.peak_force, std::abs(total.force));
    if (in_cycle == per_cycle / 4) {
      cycle.components.resize(n_components);
      for (std::size_t c = 0; c < n_components; ++c) {
        cycle.components[c].slider_at_peak = committed[c].slider;
      }
    }
    if (in_cycle == 0) {  // a cycle closes
      cycle.index = static_cast<int>(result.cycles.size()) + 1;
      cycle.dissipated = 0.0;
      for (std::size_t c = 0; c < n_components; ++c) {
        cycle.components[c].dissipated = committed[c].dissipated - dissipated_at_cycle_start[c];
        cycle.dissipated += cycle.components[c].dissipated;
        dissipated_at_cycle_start[c] = committed[c].dissipated;
      }
      result.cycles.push_back(std::move(cycle));
      cycle = CycleSummary{};
    }
  }
  std::copy(committed.begin(), committed.end(), state.begin());
  return result;
}

}  // namespace isolab::hysteresis
