#include "isolab/spectra/exact_linear_sdof.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "exact_walk.h"
#include "isolab/core/errors.h"

namespace isolab::spectra {
namespace {

void ValidateOscillator(double period, double zeta) {
  if (!(period > 0.0) || !std::isfinite(period)) {
    throw InvalidParameter({"period", period, "must be finite and > 0"});
  }
  if (!(zeta >= 0.0 && zeta < 1.0)) {
    throw InvalidParameter({"damping ratio", zeta, "must be in [0, 1)"});
  }
}

}  // namespace

ExactStepCoefficients ExactStepCoefficients::For(double omega, double zeta, double h) {
  const double root = std::sqrt(1.0 - zeta * zeta);
  const double omega_d = omega * root;
  const double e = std::exp(-zeta * omega * h);
  const double s = std::sin(omega_d * h), c = std::cos(omega_d * h);
  const double r = zeta / root;
  const double k = omega * omega;  // stiffness per unit mass
  const double wh = omega * h, wdh = omega_d * h;
  ExactStepCoefficients x;
  x.a = e * (r * s + c);
  x.b = e * s / omega_d;
  x.c = (2.0 * zeta / wh +
         e * (((1.0 - 2.0 * zeta * zeta) / wdh - r) * s - (1.0 + 2.0 * zeta / wh) * c)) /
        k;
  x.d =
      (1.0 - 2.0 * zeta / wh + e * ((2.0 * zeta * zeta - 1.0) / wdh * s + 2.0 * zeta / wh * c)) / k;
  x.a_v = -e * omega * s / root;
  x.b_v = e * (c - r * s);
  x.c_v = (-1.0 / h + e * ((omega / root + r / h) * s + c / h)) / k;
  x.d_v = (1.0 - e * (r * s + c)) / (k * h);
  return x;
}

int SubstepsPerSample(double record_dt, double period, int points_per_period) {
  // The small allowance keeps T = 0.4 s at 20 points on a 0.02 s record from tipping to 2.
  const double substeps = std::ceil(record_dt * points_per_period / period - 1e-9);
  if (!(substeps <= std::numeric_limits<int>::max())) {
    throw InvalidParameter({"points_per_period", double(points_per_period),
                            "gives more sub-steps a sample than an int counts at this period"});
  }
  return std::max(1, static_cast<int>(substeps));
}

PeakDeformation ExactPeakDeformation(const integrators::SampledHistory& ground, double period,
                                     double zeta, int points_per_period) {
  ValidateOscillator(period, zeta);
  if (points_per_period < 1) {
    throw InvalidParameter({"points_per_period", double(points_per_period), "must be >= 1"});
  }
  const int substeps = SubstepsPerSample(ground.dt, period, points_per_period);
  const double h = ground.dt / substeps;
  PeakDeformation peak;
  long at = 0;
  WalkExact<1>({&ground}, period, zeta, substeps, [&](long k, const std::array<double, 1>& u) {
    if (std::abs(u[0]) > peak.value) {
      peak.value = std::abs(u[0]);
      at = k;
    }
  });
  peak.time = at * h;
  return peak;
}

std::vector<double> ExactDeformationHistory(const integrators::SampledHistory& ground,
                                            double period, double zeta, int substeps) {
  ValidateOscillator(period, zeta);
  if (substeps < 1) throw InvalidParameter({"substeps", double(substeps), "must be >= 1"});
  std::vector<double> history;
  history.reserve(ground.values.empty() ? 1 : (ground.values.size() - 1) * substeps + 1);
  WalkExact<1>({&ground}, period, zeta, substeps,
               [&](long, const std::array<double, 1>& u) { history.push_back(u[0]); });
  return history;
}

}  // namespace isolab::spectra
