// The testing property modification factors of ASCE 7-16 17.2.8.4 (lambda_test), from a bearing's
// prototype tests themselves: the codes take a bearing's nominal properties as the mean over the
// three fully reversed cycles of a test at one amplitude, and lambda_test as the spread of the
// cycles about that mean (the first cycle's heating, scragging and rate effects, the third's
// loss). Per whole cycle of a measured test (cyclic_data.h):
//   D = (|D+| + |D-|) / 2,  k_eff = (|F+| + |F-|) / (|D+| + |D-|)   (ASCE 7-16 Eq. 17.8-1)
//   E  the loop's area from zero crossing to zero crossing (trapezoidal, the crossings
//      interpolated; the first cycle of a test from rest starts on the virgin branch),
//   Qd = E / (4 D),  Kd = k_eff - Qd / D
// F+- the forces at the cycle's extreme displacements. Qd = E / (4 D) is the characteristic
// strength of the rigid-plastic-hardening loop of the same energy: exact for one, (1 - Dy / D)
// of Qd for a bilinear loop of yield displacement Dy (Kd then Qd Dy / D^2 high), a bias the
// ratios between cycles of one amplitude cancel. Per test of at least three cycles, over cycles
// 1 to 3: nominal = the mean, lambda_max = the largest over the mean, lambda_min = the least over
// the mean; over the tests, the largest lambda_max and the least lambda_min.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "isolab/identification/cyclic_data.h"

namespace isolab::identification {

inline constexpr int kTestCycles = 3;

struct CycleProperties {
  double amplitude = 0.0;            // D (length)
  double effective_stiffness = 0.0;  // k_eff (force/length)
  double dissipated = 0.0;           // E (force*length)
  double qd = 0.0, kd = 0.0;         // (force), (force/length)
};

struct PropertyFactors {
  double nominal = 0.0;  // mean over the cycles
  double min = 1.0, max = 1.0;
};

struct TestProperties {
  std::string test;
  std::vector<CycleProperties> cycles;  // the first kTestCycles whole cycles
  PropertyFactors qd, kd;
};

struct TestingFactors {
  std::vector<TestProperties> tests;  // those with kTestCycles cycles or more
  std::vector<std::string> skipped;   // tests with fewer whole cycles
  PropertyFactors qd, kd;             // the envelope over the tests (nominal: the tests' mean)
  bool empty() const { return tests.empty(); }
};

CycleProperties PropertiesOfCycle(const CyclicTestData& test, CycleSpan cycle);

TestingFactors TestingFactorsOf(std::span<const CyclicTestData> tests);

}  // namespace isolab::identification
