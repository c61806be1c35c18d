// A displacement-controlled cyclic test, u(t) = u_a sin(2 pi t / T), from rest, on an assembly:
// the protocol of the paper's Table 7 and of bearing qualification tests.
#pragma once

#include <span>
#include <vector>

#include "isolab/hysteresis/parallel_assembly.h"

namespace isolab::hysteresis {

struct CyclicProtocol {
  double amplitude = 0.0;     // u_a (length), > 0
  double period = 1.0;        // T (time), > 0; matters only for rate-dependent laws
  int cycles = 2;             // number of full cycles, >= 1
  int steps_per_cycle = 400;  // a multiple of 4, so u = +-u_a is sampled exactly

  // Throws InvalidParameter naming the first field out of range.
  void Validate() const;
};

struct ComponentCycle {
  double dissipated = 0.0;      // energy dissipated by the component over the cycle
  double slider_at_peak = 0.0;  // its slider displacement where u = +u_a in the cycle
};

struct CycleSummary {
  int index = 0;            // 1-based
  double dissipated = 0.0;  // W_d of the whole assembly over the cycle
  double peak_force = 0.0;  // max |F| over the cycle
  std::vector<ComponentCycle> components;
};

// The sampled loop: time, displacement, total force and, row by row, each component's force.
struct CyclicLoop {
  std::vector<double> time;
  std::vector<double> displacement;
  std::vector<double> force;
  std::vector<double> component_force;  // [sample * components + component]
};

struct CyclicResult {
  CyclicProtocol protocol;
  CyclicLoop loop;
  std::vector<CycleSummary> cycles;
};

CyclicResult RunCyclicTest(const ParallelAssembly& assembly, const CyclicProtocol& protocol);

// The same test on a specimen with a history: it starts from `state` (one LawState per
// component, e.g. what an earlier test left) and leaves in it the state after the last sample, so
// tests run one after another on one specimen. Energies per cycle count from the start state.
CyclicResult RunCyclicTest(const ParallelAssembly& assembly, const CyclicProtocol& protocol,
                           std::span<LawState> state);

}  // namespace isolab::hysteresis
