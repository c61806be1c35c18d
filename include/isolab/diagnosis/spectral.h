// Spectral tools of the discrepancy, also used by the building-level fit (its residual's
// correlation time): the Hann-windowed periodogram of a uniformly
// sampled series and its autocorrelation, through Eigen's FFT on a power-of-two length.
#pragma once

#include <vector>

namespace isolab::diagnosis {

// One-sided Hann-windowed periodogram of `x` (its mean removed), normalised so that white noise
// of variance s^2 has E[P_k] = s^2 at every bin k = 0 .. M / 2 (M: the length padded to a power
// of two, bin k at frequency k / (M dt)). Zero padding interpolates between bins; it does not
// change the level.
std::vector<double> Periodogram(const std::vector<double>& x);

// The padded length Periodogram uses for n samples.
std::size_t PaddedLength(std::size_t n);

// Autocorrelation of `x` (mean removed) at lags 0 .. max_lag, divided by lag 0's (so rho_0 = 1);
// all zeros for a constant series.
std::vector<double> Autocorrelation(const std::vector<double>& x, std::size_t max_lag);

// Integrated autocorrelation time 1 + 2 sum rho_k, the sum cut by Geyer's (1992) initial positive
// sequence: pairs rho_2m + rho_2m+1 are added while positive. n samples of a series correlated
// over tau are worth n / tau independent ones; white noise has tau = 1.
double IntegratedCorrelationTime(const std::vector<double>& x);

}  // namespace isolab::diagnosis
