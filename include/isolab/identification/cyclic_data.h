// Measured cyclic tests of a bearing (displacement and force sampled in time), split into cycles,
// and the model driven through them: what identification fits and diagnosis reads.
#pragma once

#include <string>
#include <vector>

#include "isolab/hysteresis/parallel_assembly.h"

namespace isolab::identification {

struct CycleSpan {
  std::size_t begin = 0, end = 0;  // samples [begin, end)
};

struct CyclicTestData {
  std::string name;
  std::vector<double> time, displacement, force;
  // Whole cycles, each from one upward zero crossing of the displacement to the next (the first
  // from the start); a trailing part that does not swing both ways is not a cycle.
  std::vector<CycleSpan> cycles;
};

// Splits a displacement history into whole cycles (CyclicTestData::cycles).
std::vector<CycleSpan> SplitCycles(const std::vector<double>& displacement);

// Force of `assembly` driven from rest through the test's displacement history (velocity by
// backward differences, for rate-dependent laws), one value per sample.
std::vector<double> SimulateForce(const hysteresis::ParallelAssembly& assembly,
                                  const CyclicTestData& test);

// Energy of a loop over samples [begin, end): the trapezoidal integral of force d(displacement).
double LoopEnergy(const std::vector<double>& displacement, const std::vector<double>& force,
                  CycleSpan span);

// Largest |displacement| over a span.
double SpanAmplitude(const std::vector<double>& displacement, CycleSpan span);

}  // namespace isolab::identification
