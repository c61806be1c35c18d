// A fitted model set against the measurements it was fitted to: the residual force, sample by
// sample, and what an engineer reads off each half-cycle between reversals (energy, secant
// stiffness between its reversal points), for the measured and the modelled force alike, so the
// statistics mean the same on a sinusoidal protocol and on a seismic history. The detectors of
// effects.h read only this, never a "truth".
#pragma once

#include <vector>

#include "isolab/hysteresis/parallel_assembly.h"
#include "isolab/identification/fit.h"

namespace isolab::diagnosis {

// One half-cycle of one test, read off its force path.
struct LoopMeasure {
  // Dissipated energy, the area between the path and the chord of its reversal points
  // (identification::HalfCycleEnergy; half a symmetric loop's area) (force*length).
  double energy = 0.0;
  // Secant stiffness between the reversal points, (F_B - F_A) / (u_B - u_A), with F and u
  // averaged over the samples within 3 % of the half-cycle's range of each reversal, so noise on
  // single samples averages out.
  double secant = 0.0;
};

struct CycleRecord {
  int test = 0;            // index into the data's tests
  int cycle = 0;           // 1-based half-cycle within the test
  double amplitude = 0.0;  // half the reversal-to-reversal range (length)
  double period = 0.0;     // twice the half-cycle's duration (time)
  LoopMeasure measured, modelled;
};

struct Discrepancy {
  const identification::FitData* data = nullptr;
  std::vector<std::vector<double>> model_force;  // per test, per sample
  std::vector<std::vector<double>> velocity;     // per test: central differences of u
  std::vector<double> force_noise;  // per test: standard deviation of the measurement noise
  std::vector<CycleRecord> cycles;  // every half-cycle within the fitted spans, in test order

  // The model driven through every test and its loops measured. `data` must outlive the result.
  static Discrepancy Of(const hysteresis::ParallelAssembly& model,
                        const identification::FitData& data);
};

// Standard deviation of a test's force noise, from its second differences: white noise of
// variance s^2 gives second differences of variance 6 s^2, while a smooth loop sampled finely
// gives almost none; the median absolute deviation ignores the few samples at the kinks.
double ForceNoise(const identification::CyclicTestData& test);

// The e^2 that noise alone leaves: sum over tests of (fitted samples x noise^2) / <F0, F0>.
double NoiseFloor(const identification::FitData& data, const std::vector<double>& force_noise);

// Every sample of every test fitted (diagnosis reads early half-cycles against later ones), the
// tests independent specimens or one specimen in order. Throws std::invalid_argument for a test
// without a half-cycle between reversals.
identification::FitData AllCycles(std::vector<identification::CyclicTestData> tests,
                                  bool one_specimen = false);

// Lag-1 autocorrelation of the residual within the fitted cycles, each test weighted as in e^2,
// clamped to [0, 0.99].
double ResidualCorrelation(const Discrepancy& discrepancy);

// Samples worth as many independent ones: n (1 - rho) / (1 + rho) for residuals correlated
// as AR(1) with lag-1 correlation rho (the variance inflation of a mean).
double EffectiveSamples(long samples, double rho);

// Fitted samples over all tests.
long SampleCount(const identification::FitData& data);

}  // namespace isolab::diagnosis
