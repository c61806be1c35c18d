#include "isolab/diagnosis/spectral.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <numeric>
#include <unsupported/Eigen/FFT>

namespace isolab::diagnosis {
namespace {

std::vector<double> Centred(const std::vector<double>& x) {
  const double mean =
      x.empty() ? 0.0 : std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(x.size());
  std::vector<double> centred(x.size());
  std::transform(x.begin(), x.end(), centred.begin(), [&](double v) { return v - mean; });
  return centred;
}

}  // namespace

std::size_t PaddedLength(std::size_t n) {
  std::size_t m = 1;
  while (m < n) m *= 2;
  return std::max<std::size_t>(m, 2);
}

std::vector<double> Periodogram(const std::vector<double>& x) {
  const std::size_t n = x.size(), m = PaddedLength(n);
  const std::vector<double> centred = Centred(x);
  std::vector<double> windowed(m, 0.0);
  double window_power = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const double w = n > 1 ? 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * static_cast<double>(k) /
                                                  static_cast<double>(n - 1))
                           : 1.0;
    windowed[k] = w * centred[k];
    window_power += w * w;
  }
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> spectrum;
  fft.fwd(spectrum, windowed);
  std::vector<double> power(m / 2 + 1);
  for (std::size_t k = 0; k < power.size(); ++k) {
    power[k] = window_power > 0.0 ? std::norm(spectrum[k]) / window_power : 0.0;
  }
  return power;
}

std::vector<double> Autocorrelation(const std::vector<double>& x, std::size_t max_lag) {
  const std::size_t n = x.size();
  std::vector<double> rho(max_lag + 1, 0.0);
  if (n < 2) return rho;
  // Zero padding to twice the length makes the circular correlation the linear one.
  const std::size_t m = PaddedLength(2 * n);
  std::vector<double> padded = Centred(x);
  padded.resize(m, 0.0);
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> spectrum;
  fft.fwd(spectrum, padded);
  for (auto& c : spectrum) c = std::norm(c);
  std::vector<double> correlation;
  fft.inv(correlation, spectrum);
  if (!(correlation[0] > 0.0)) return rho;
  for (std::size_t k = 0; k <= max_lag && k < n; ++k) rho[k] = correlation[k] / correlation[0];
  return rho;
}

double IntegratedCorrelationTime(const std::vector<double>& x) {
  const std::size_t n = x.size();
  if (n < 4) return 1.0;
  const std::vector<double> rho = Autocorrelation(x, n - 1);
  double tau = -1.0;  // -rho_0 + 2 sum over pairs, rho_0 = 1 counted once
  for (std::size_t k = 0; k + 1 < n; k += 2) {
    const double pair = rho[k] + rho[k + 1];
    if (!(pair > 0.0)) break;
    tau += 2.0 * pair;
  }
  return std::clamp(tau, 1.0, static_cast<double>(n));
}

}  // namespace isolab::diagnosis
