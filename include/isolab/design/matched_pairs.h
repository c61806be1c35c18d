// Spectrum-compatible pairs of horizontal ground motion components, made by isolab itself: a fresh
// clone cannot redistribute the PEER database, so a design example needs records matched to its
// design spectrum. Each pair's RotD100 (the maximum-direction spectrum of ASCE 7-16 Sec. 21.2,
// rotd_spectrum.h) is brought within a tolerance of a target over a period range.
//
// Method: iterative frequency-domain spectral matching in the style of SIMQKE (Gasparini &
// Vanmarcke, "Simulated earthquake motions compatible with prescribed response spectra", MIT
// Dept. of Civil Engineering R76-4, 1976), applied to the pair's RotD100:
//  1. Two independent filtered-noise components (synthetic_motion.h, the spec's shape, seeds
//     below) start the pair.
//  2. At every iteration the pair's RotD100 is computed (ComputePairSpectrum, peaks sought at 30
//     points per period) at the check periods, log-spaced at most 2.5 % apart (48 to 400
//     intervals) over [period_min, period_max], ends included, and at the same spacing over the
//     margins [0.8 period_min, period_min) and (period_max, 1.25 period_max]. In the margins the
//     target is extended log-log linearly from the last 25 % of the range at each end (it is called
//     only in range).
//  3. The Fourier amplitudes of BOTH components (zero-padded to a power of two of at least twice
//     the samples, so that the circular convolution does not wrap) at f = 1/T are multiplied by
//     r(T) = (target(T) / RotD100(T))^g(T), log r interpolated linearly in log-frequency between
//     check periods; phases are kept, and so is the envelope of the starting records, and the
//     inverse transform is cut back to the record's samples. Across the margins log r tapers
//     by a half cosine in log-period to the geometric mean of the in-range ratios, which scales
//     every frequency beyond the widened range (after the first iteration it is close to 1: the
//     starting records' level is arbitrary). The gain g starts at 1 at every check period; it
//     grows by 1.5, up to 2, while that period's misfit keeps its sign and shrinks by less than
//     30 % an iteration, and halves, down to 1, when the misfit changes sign (a per-period step
//     adaptation like Rprop's, Riedmiller & Braun 1993): a long period, whose RotD100 answers
//     a change of a 30-s record's Fourier amplitudes weakly, converges in fewer iterations.
//  4. The baseline is corrected (below), and the loop repeats from 2.
// When the misfit, max |RotD100/target - 1| over the check periods in [period_min, period_max],
// is within the tolerance, it is measured again as reported: exactly (peaks sought at 100 points
// per period, 0.05 %), with the dips and peaks of RotD100/target between check periods sought
// by bisection (RotD100 can dip in a V a few percent below two check periods). If that is within
// the tolerance the pair is done; otherwise the loop goes on, corrected by that measurement. After
// max_iterations corrections, the records of least misfit seen are kept, measured as reported.
// The baseline correction is applied inside the loop, so the matching compensates for what it
// takes away, and the misfit reported is that of the records returned.
//
// Baseline correction: a polynomial fitted to the displacement (Boore & Bommer, "Processing of
// strong-motion accelerograms: needs, options and consequences", Soil Dyn. Earthq. Eng. 25(2),
// 2005). Velocity and displacement are integrated from rest by the trapezoidal rule; an
// acceleration correction c(t) = sum_{j=0..4} x_j (t / t_end)^j is integrated by the same rule,
// and x is the least-squares fit of c's displacement to the record's displacement, constrained so
// that the corrected velocity and displacement at the record's end are zero (to rounding). A
// base-isolated building's periods are 2-4 s: a displacement left to drift would act on it as a
// fake long-period pulse.
//
// Restarts: fixed phases can trap a pair (its misfit stops falling, or climbs). A pair whose
// misfit has not fallen for 8 iterations, or that used max_iterations, without converging starts
// again from new seeds (attempt r = 1, 2, 3); the attempt of least misfit is returned, its
// iterations counted from its own start.
//
// Seeds: component c (0 for H1, 1 for H2) of pair k (0, 1, ...) in attempt r (0, 1, ...) starts
// from the filtered noise of seed s(k, c, r), the (2k + c + 1 + 2^32 r)-th output of SplitMix64
// (Steele, Lea & Flood, OOPSLA 2014) started from `seed`. Pair k is thus the same whatever the
// count, and its components are independent draws.
//
// Units: records and target in g, periods in s.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "isolab/analysis/synthetic_motion.h"
#include "isolab/io/record.h"

namespace isolab::design {

struct MatchedPairSpec {
  // Pair k of a suite starts from seeds s(k, 0), s(k, 1) derived from this one (header), so pair
  // k is the same whatever the count.
  std::uint64_t seed = 1;
  int count = 1;  // pairs, >= 1
  // The starting records' shape (duration, dt, envelope, site filter); its seed and pga are
  // ignored. duration >= 4 period_max, so that a record holds several cycles of every period.
  analysis::FilteredNoiseSpec motion;
  double period_min = 0.1;      // s, >= 5 motion.dt (the margin below it stays under Nyquist)
  double period_max = 5.0;      // s, > period_min: the range over which RotD100 must match
  double damping_ratio = 0.05;  // of the spectra, [0, 1)
  double tolerance = 0.10;      // the largest |RotD100/target - 1| accepted over the range, > 0
  int max_iterations = 30;      // corrections at most, >= 0
  // What the target is, for the records' descriptions ("design.csv"); empty: "the given target".
  std::string target_name;

  // Throws InvalidParameter naming the field out of range.
  void Validate() const;
};

struct MatchedPair {
  io::Record h1, h2;  // in g; description says how made (seeds, method, target, misfit)
  // max over [period_min, period_max] of |RotD100/target - 1| of h1, h2 as returned (after
  // matching and baseline correction): at the check periods and the extremes between them.
  double misfit = 0;
  int iterations = 0;      // corrections made
  bool converged = false;  // misfit <= tolerance
};

// s(k, c, r) of the header: the seed of component c (0: H1, 1: H2) of pair k in attempt r.
std::uint64_t MatchedPairComponentSeed(std::uint64_t seed, int pair, int component,
                                       int attempt = 0);

// The check periods (s), log-spaced over [0.8 period_min, 1.25 period_max], period_min and
// period_max among them; those in [period_min, period_max] give the misfit.
std::vector<double> MatchedPairCheckPeriods(const MatchedPairSpec& spec);

// target(T): pseudo-acceleration in g at period T (s), > 0 over [period_min, period_max]; it is
// called only there. Throws InvalidParameter for a spec that fails Validate, and for a target
// that is not finite and > 0 at a check period ("target(0.5 s)").
std::vector<MatchedPair> MatchPairs(const MatchedPairSpec& spec,
                                    const std::function<double(double)>& target);

}  // namespace isolab::design
