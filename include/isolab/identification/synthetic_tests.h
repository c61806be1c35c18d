// Synthetic cyclic tests of a known assembly, for identification tests and benchmarks: the
// sinusoidal protocol of hysteresis/cyclic_test.h at several amplitudes, with optional Gaussian
// measurement noise on the force (seeded, so a data set is reproducible).
#pragma once

#include <vector>

#include "isolab/hysteresis/cyclic_test.h"
#include "isolab/identification/cyclic_data.h"

namespace isolab::identification {

struct SyntheticTestOptions {
  std::vector<double> amplitudes;    // one test per amplitude and period (length)
  std::vector<double> periods{2.0};  // (time); 0.5 Hz as in HDRB qualification tests
  int cycles = 3;
  int steps_per_cycle = 200;
  double noise = 0.0;  // standard deviation of the force noise, relative to the test's RMS force
  unsigned seed = 1;
  // One specimen: the tests run in order on one specimen, each from the state the previous one
  // left (a campaign whose damage accumulates); else each on a fresh specimen.
  bool one_specimen = false;
};

// Gaussian noise on every force sample, of standard deviation `noise` times the test's RMS force,
// from a generator seeded with `seed` (the same seed, the same noise).
void AddForceNoise(std::vector<CyclicTestData>* tests, double noise, unsigned seed);

// A test from a computed loop, named "u=<amplitude>" ("u=<amplitude>_T=<period>" when
// `name_period`) and split into cycles and half-cycles.
CyclicTestData TestFromLoop(const hysteresis::CyclicResult& result, bool name_period = false);

// Tests at every amplitude for each period in turn, named as TestFromLoop names them (with the
// period when there are several), split into cycles and half-cycles.
std::vector<CyclicTestData> SyntheticTests(const hysteresis::ParallelAssembly& assembly,
                                           const SyntheticTestOptions& options);

}  // namespace isolab::identification
