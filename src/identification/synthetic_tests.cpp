#include "isolab/identification/synthetic_tests.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace isolab::identification {

void AddForceNoise(std::vector<CyclicTestData>* tests, double noise, unsigned seed) {
  if (!(noise > 0.0)) return;
  std::mt19937_64 random(seed);
  std::normal_distribution<double> gaussian(0.0, 1.0);
  for (CyclicTestData& test : *tests) {
    double square = 0.0;
    for (const double f : test.force) square += f * f;
    const double sigma = noise * std::sqrt(square / static_cast<double>(test.force.size()));
    for (double& f : test.force) f += sigma * gaussian(random);
  }
}

CyclicTestData TestFromLoop(const hysteresis::CyclicResult& result, bool name_period) {
  CyclicTestData test;
  test.name = name_period
                  ? fmt::format("u={:g}_T={:g}", result.protocol.amplitude, result.protocol.period)
                  : fmt::format("u={:g}", result.protocol.amplitude);
  test.time = result.loop.time;
  test.displacement = result.loop.displacement;
  test.force = result.loop.force;
  Segment(&test);
  return test;
}

std::vector<CyclicTestData> SyntheticTests(const hysteresis::ParallelAssembly& assembly,
                                           const SyntheticTestOptions& options) {
  std::vector<CyclicTestData> tests;
  std::vector<hysteresis::LawState> state(assembly.state_size());
  for (const double period : options.periods) {
    for (const double amplitude : options.amplitudes) {
      if (!options.one_specimen) std::fill(state.begin(), state.end(), hysteresis::LawState{});
      tests.push_back(TestFromLoop(
          hysteresis::RunCyclicTest(
              assembly, {amplitude, period, options.cycles, options.steps_per_cycle}, state),
          options.periods.size() > 1));
    }
  }
  AddForceNoise(&tests, options.noise, options.seed);
  return tests;
}

}  // namespace isolab::identification
