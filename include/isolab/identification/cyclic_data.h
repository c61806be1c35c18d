// Measured tests of a bearing (displacement and force sampled in time): any displacement history,
// sinusoidal or not, split into half-cycles between reversals (and, where the history has them,
// whole cycles), and the model driven through them: what identification fits and diagnosis reads.
//
// Reversals. A measured displacement wiggles: a sign change of its differences is not a
// reversal. A reversal is the running extreme of the displacement once the displacement has come
// back from it by more than a band of kReversalBand times the test's whole range (max - min):
// a hysteresis band on the displacement, so noise and small ripples inside a half-cycle do not
// split it. A half-cycle runs from one reversal to the next; its amplitude is half the
// reversal-to-reversal range. The stretch before the first reversal and after the last are not
// half-cycles (they do not start and end at a reversal).
//
// Specimens. Tests are independent specimens (each driven from rest, the model's state zero at
// its first sample) or one specimen tested in the given order: each test then starts from the
// element state the previous test left (slider positions, the accumulated slip of a degrading
// law, a Bouc-Wen hysteretic variable), and may start away from zero displacement.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "isolab/hysteresis/parallel_assembly.h"

namespace isolab::identification {

struct CycleSpan {
  std::size_t begin = 0, end = 0;  // samples [begin, end)
};

// A half-cycle's reversal band, as a share of the test's displacement range.
inline constexpr double kReversalBand = 0.02;

struct CyclicTestData {
  std::string name;
  std::vector<double> time, displacement, force;
  // Whole cycles, each from one upward zero crossing of the displacement to the next (the first
  // from the start); a trailing part that does not swing both ways is not a cycle. Sinusoidal
  // protocols have them; a seismic history may have none.
  std::vector<CycleSpan> cycles;
  // Half-cycles between reversals; each span holds both of its reversal samples.
  std::vector<CycleSpan> half_cycles;
};

// The range of the data a fit saw, so that a run of the fitted model can say when it goes beyond
// it (a law identified on one amplitude extrapolates at another). Displacement and velocity are
// the deformation's, so for a layer of equal bearings in one direction the same for the layer and
// for each bearing.
struct IdentifiedRange {
  double displacement = 0.0;      // peak |u| over the fitted samples (length)
  double velocity = 0.0;          // peak |v| there, v by backward differences as the fit drives the
                                  // model (length/time)
  double cycles = 0.0;            // reversals within the fitted samples / 2 (two a cycle)
  std::vector<std::string> data;  // the tests' names
};

// Splits a displacement history into whole cycles (CyclicTestData::cycles).
std::vector<CycleSpan> SplitCycles(const std::vector<double>& displacement);

// Splits a displacement history into half-cycles between reversals (the band rule above).
std::vector<CycleSpan> SplitHalfCycles(const std::vector<double>& displacement);

// Fills a test's cycles and half_cycles from its displacement.
void Segment(CyclicTestData* test);

// Force of `assembly` driven through the test's displacement history (velocity by backward
// differences, for rate-dependent laws; zero at the first sample), starting from `state` (one
// LawState per component) and leaving in it the state after the last sample.
void SimulateForceFrom(const hysteresis::ParallelAssembly& assembly, const CyclicTestData& test,
                       std::span<hysteresis::LawState> state, std::span<double> force);

// Force of `assembly` driven from rest through one test, one value per sample.
std::vector<double> SimulateForce(const hysteresis::ParallelAssembly& assembly,
                                  const CyclicTestData& test);

// Force of `assembly` through every test: each from rest, or, for one specimen, each from the
// state the previous test left.
std::vector<std::vector<double>> SimulateForces(const hysteresis::ParallelAssembly& assembly,
                                                std::span<const CyclicTestData> tests,
                                                bool one_specimen);

// Energy of a loop over samples [begin, end): the trapezoidal integral of force d(displacement).
double LoopEnergy(const std::vector<double>& displacement, const std::vector<double>& force,
                  CycleSpan span);

// Energy a half-cycle dissipates: the area between its force path and the chord joining its two
// reversal points, integral of F du - (F_A + F_B)(u_B - u_A) / 2. The chord takes out the change
// of stored (elastic) energy, so the value is the same for a loop's rising and falling branch and
// sums to the loop's area over a symmetric cycle; a linear spring gives zero.
double HalfCycleEnergy(const std::vector<double>& displacement, const std::vector<double>& force,
                       CycleSpan span);

// Largest |displacement| over a span.
double SpanAmplitude(const std::vector<double>& displacement, CycleSpan span);

// Half the range of displacement over a span: a half-cycle's amplitude.
double HalfRange(const std::vector<double>& displacement, CycleSpan span);

}  // namespace isolab::identification
