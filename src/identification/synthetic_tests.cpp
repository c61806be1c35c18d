#include "isolab/identification/synthetic_tests.h"

#include <fmt/format.h>

#include <cmath>
#include <random>

namespace isolab::identification {

std::vector<CyclicTestData> SyntheticTests(const hysteresis::ParallelAssembly& assembly,
                                           const SyntheticTestOptions& options) {
  std::mt19937_64 random(options.seed);
  std::normal_distribution<double> gaussian(0.0, 1.0);
  std::vector<CyclicTestData> tests;
  for (const double amplitude : options.amplitudes) {
    const hysteresis::CyclicResult result = hysteresis::RunCyclicTest(
        assembly, {amplitude, options.period, options.cycles, options.steps_per_cycle});
    CyclicTestData test;
    test.name = fmt::format("u={:g}", amplitude);
    test.time = result.loop.time;
    test.displacement = result.loop.displacement;
    test.force = result.loop.force;
    if (options.noise > 0.0) {
      double square = 0.0;
      for (const double f : test.force) square += f * f;
      const double sigma = options.noise * std::sqrt(square / test.force.size());
      for (double& f : test.force) f += sigma * gaussian(random);
    }
    test.cycles = SplitCycles(test.displacement);
    tests.push_back(std::move(test));
  }
  return tests;
}

}  // namespace isolab::identification
