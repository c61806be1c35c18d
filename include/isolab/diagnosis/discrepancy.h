// A fitted model set against the measurements it was fitted to: the residual force, sample by
// sample, and what an engineer reads off each half-cycle between reversals (energy, secant
// stiffness between its reversal points), for the measured and the modelled force alike, so the
// statistics mean the same on a sinusoidal protocol and on a seismic history. The detectors of
// effects.h read only this, never a "truth".
#pragma once

#include <string>
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
  // The force at the half-cycle's first and last reversal, averaged as the secant's are (force).
  double start_force = 0.0, end_force = 0.0;
};

struct CycleRecord {
  int test = 0;            // index into the data's tests
  int cycle = 0;           // 1-based half-cycle within the test
  double amplitude = 0.0;  // half the reversal-to-reversal range (length)
  double period = 0.0;     // twice the half-cycle's duration (time)
  LoopMeasure measured, modelled;
};

// The noise of a test's force channel, estimated where the signal has no content, so that the
// estimate does not depend on the sampling rate or on how many samples sit at rest. Two reads:
//  * rest: the force's variance over the samples at the start of the test before the
//    displacement moves (by more than 0.1 % of its range), when there are at least 64 and they
//    are not all one value: what the channel reads with nothing to measure, whatever its
//    spectrum;
//  * band: from the Hann-windowed periodogram of the force above the band of the device's
//    response, f_c = 10 f_u, where f_u bounds 99 % of the displacement's power (its loops'
//    harmonics decay past that), and at most half the Nyquist frequency. Above f_c the noise
//    level is read quarter octave by quarter octave as a low quantile of the periodogram (the
//    25th percentile, over the chi-squared spread of periodogram ordinates: harmonic lines of the
//    loops occupy few bins and do not move it); below f_c the noise is taken as flat at the first
//    octave's median level. The variance is that spectrum's mean over the whole band
//    [0, Nyquist]. For white noise this is its variance at any rate; for noise band-limited by a
//    load cell's filter above f_c it is the filtered noise's variance; decimation folds noise
//    into the kept band without changing its variance, and the estimate follows.
// The two read different things where the device makes noise of its own only while it moves
// (stick-slip chatter): the rest read sees the channel alone, the band read the channel and the
// chatter. Which of them a test gets must not depend on the rate (a lower rate leaves fewer
// samples at rest), so both are read wherever they can be: within a factor of two of each other
// the rest read is taken (it needs no assumption about the spectrum); further apart the estimate
// is `uncertain` and the larger is taken, since a floor read too low makes the diagnosis name
// components that fit the chatter, and the report says so.
// What neither can see: noise confined below f_c, inside the device's own band (a moving
// average much longer than a sample, for instance), is indistinguishable there from model error.
struct NoiseEstimate {
  enum class Source { kRest, kBand, kNone };
  double sigma = 0.0;  // standard deviation of the force noise (force)
  Source source = Source::kNone;
  long rest_samples = 0;    // samples read at rest (0: too few to read)
  double rest_sigma = 0.0;  // the rest read (force); 0 where not read
  double band_sigma = 0.0;  // the band read (force); 0 where not read
  double band_low = 0.0;    // f_c, the band's lower edge (1/time); 0 where not read
  double nyquist = 0.0;     // the band's upper edge (1/time)
  bool uncertain = false;   // both read, more than kNoiseReadsAgree apart: sigma the larger

  // "rest, 5120 samples", "band 2.5-512 per unit time", or both reads when uncertain.
  std::string Describe() const;
};

// Two reads of one test's noise within this factor of each other agree.
inline constexpr double kNoiseReadsAgree = 2.0;

NoiseEstimate EstimateForceNoise(const identification::CyclicTestData& test);

// The same read from another series of the test's samples, such as a model's residual
// (measured less modelled force): the model takes out the loops' harmonic lines, so the band
// above the response holds less of the signal. Lines can only raise a level, so of two estimates
// of one test's noise the lower is the better.
NoiseEstimate EstimateNoise(const identification::CyclicTestData& test,
                            const std::vector<double>& series);

// The noise from the force's second differences (white noise of variance s^2 gives second
// differences of variance 6 s^2; the median absolute deviation ignores the few samples at
// kinks). It assumes the signal's second differences are negligible, which depends on the
// sampling rate, and that the noise is white from sample to sample: oversampled, filtered or
// quantised data read far too low, and a coarsely sampled signal's curvature reads as noise. The
// diagnosis uses EstimateForceNoise; this stays for comparison.
double SecondDifferenceNoise(const identification::CyclicTestData& test);

struct Discrepancy {
  const identification::FitData* data = nullptr;
  std::vector<std::vector<double>> model_force;  // per test, per sample
  std::vector<std::vector<double>> velocity;     // per test: central differences of u
  std::vector<NoiseEstimate> noise;              // per test (EstimateForceNoise)
  std::vector<double> force_noise;  // per test: standard deviation of the measurement noise
  std::vector<CycleRecord> cycles;  // every half-cycle within the fitted spans, in test order

  // The model driven through every test and its loops measured. `data` must outlive the result.
  // Each test's noise is the lower of the estimates from its residual and from its force (or
  // `noise`, when given: an earlier estimate to improve on).
  static Discrepancy Of(const hysteresis::ParallelAssembly& model,
                        const identification::FitData& data,
                        const std::vector<NoiseEstimate>* noise = nullptr);

  // The residual (measured less modelled force) of test i at its fitted samples, in order.
  std::vector<double> Residual(std::size_t test) const;
};

// The e^2 that noise alone leaves: sum over tests of (fitted samples x noise^2) / <F0, F0>.
double NoiseFloor(const identification::FitData& data, const std::vector<double>& force_noise);

// Every sample of every test fitted (diagnosis reads early half-cycles against later ones), the
// tests independent specimens or one specimen in order. Throws std::invalid_argument for a test
// without a half-cycle between reversals.
identification::FitData AllCycles(std::vector<identification::CyclicTestData> tests,
                                  bool one_specimen = false);

// Each test's residual correlation time, in samples: the integrated autocorrelation time
// 1 + 2 sum rho_k (Geyer's initial positive sequence). White noise has 1; a residual of model
// error correlated over a tenth of a cycle has about a tenth of a cycle's samples, so the time in
// seconds (samples x dt) is what does not depend on the sampling rate.
std::vector<double> CorrelationTimes(const Discrepancy& discrepancy);

// Samples worth as many independent ones: the sum over tests of fitted samples / correlation
// time. Oversampling adds samples and correlation time alike, so the count stays.
double EffectiveSamples(const Discrepancy& discrepancy);

// Fitted samples over all tests.
long SampleCount(const identification::FitData& data);

}  // namespace isolab::diagnosis
