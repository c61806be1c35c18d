// Amplitude scaling of a suite of horizontal record pairs to a target spectrum, as ASCE 7-16
// Sec. 17.3.3 asks of the response-history analysis of an isolated structure: each pair gets one
// factor (both components alike), and the mean over the pairs of their scaled maximum-direction
// (RotD100, rotd_spectrum.h) spectra must not fall below the target anywhere over the period
// range from 0.75 T_M (upper-bound isolator properties) to 1.25 T_M (lower-bound properties).
//
// The code fixes the criterion, not the factors; here, in two steps:
//  1. shape: each pair alone is brought to the target's level in the least-squares-in-log sense,
//       s_i = exp(mean_p ln(target_p / RotD100_i,p)),
//     so that no one pair is scaled far above the others to carry the mean;
//  2. common: the smallest factor that lifts the mean onto the target,
//       c = max_p target_p / mean_i(s_i RotD100_i,p),
//     so the scaled mean touches the target at one period (the governing one) and lies above it
//     at every other.
// Pair i is scaled by f_i = c s_i. The mean is checked at grid points only: ScalingPeriods puts
// the target's corners on the grid (where a code spectrum has its kinks), and a grid as fine as
// a record's spectrum is smooth leaves the mean above the target in between to the spectra's
// own interpolation error.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "isolab/spectra/design_spectrum.h"

namespace isolab::spectra {

// Periods (s) from lo to hi inclusive, log-spaced with `count` points, plus every corner period of
// the target (CornerPeriods) strictly inside: sorted, none repeated (a corner within 1e-12 relative
// of a grid point is that point). Throws InvalidParameter naming "lo" (<= 0 or not finite), "hi"
// (<= lo, not finite, or where the target is not defined: beyond a table or 4 s for Eurocode 8),
// "count" (< 2), and as Validate(target).
std::vector<double> ScalingPeriods(const TargetSpectrum& target, double lo, double hi,
                                   int count = 100);

struct SuiteScaling {
  std::vector<double> periods;             // the grid (s)
  std::vector<double> target;              // Sa of the target at the periods (g)
  std::vector<double> pair_shape_factors;  // s_i, step 1, per pair
  double common_factor = 1.0;              // c, step 2
  std::vector<double> factors;             // f_i = c s_i: what pair i is scaled by
  std::vector<double> scaled_mean;         // mean_i f_i RotD100_i at the periods (g)
  // The period index where scaled_mean / target is least: 1 there, to round-off, and >= 1 (to
  // round-off) at every other.
  std::size_t governing = 0;
};

// rotd100[i][p]: pair i's unscaled RotD100 pseudo-acceleration (g, as target_sa) at periods[p].
// Throws InvalidParameter naming "periods" (none), "periods[p]" (<= 0 or not finite), "target_sa"
// or "rotd100[i]" (a size other than the periods'), "target_sa[p]" or "rotd100[i][p]" (<= 0 or
// not finite), "rotd100" (no pairs).
SuiteScaling ScaleSuite(std::span<const double> periods, std::span<const double> target_sa,
                        const std::vector<std::vector<double>>& rotd100);

}  // namespace isolab::spectra
