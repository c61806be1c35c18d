// Elastic response spectra of a ground motion (Chopra, Dynamics of Structures, 4th ed.,
// Sec. 6.6): for each natural period T and damping ratio zeta, the peak deformation D of the
// linear SDOF oscillator u'' + 2 zeta w u' + w^2 u = -a_g(t) from rest, and
//   V = (2 pi / T) D   (pseudo-velocity),   A = (2 pi / T)^2 D   (pseudo-acceleration).
// Each D is the exact piecewise-linear solution of exact_linear_sdof.h, its peak read at the
// record's samples and at sub-steps in between (options.points_per_period).
// Units: those of the record (length/time^2) and the periods (time).
#pragma once

#include <span>
#include <vector>

#include "isolab/integrators/excitation.h"

namespace isolab::spectra {

struct ElasticSpectrumOptions {
  // Least number of points per natural period at which the peak is sought; record steps are cut
  // into sub-steps to reach it (exact_linear_sdof.h): 100 finds the continuous peak to 0.05 %, 1
  // reads it at the record's samples as Chopra does. >= 1.
  int points_per_period = 100;

  // Throws InvalidParameter naming the field out of range.
  void Validate() const;
};

struct SpectralOrdinate {
  double deformation = 0.0;          // D (length)
  double pseudo_velocity = 0.0;      // V (length/time)
  double pseudo_acceleration = 0.0;  // A (length/time^2)
  double time_of_peak = 0.0;         // when |u| = D (time)
};

struct ElasticSpectrum {
  std::vector<double> periods;              // (time)
  std::vector<double> damping_ratios;       // (-)
  std::vector<SpectralOrdinate> ordinates;  // damping-major: [d * periods.size() + p]

  const SpectralOrdinate& at(std::size_t damping, std::size_t period) const {
    return ordinates[damping * periods.size() + period];
  }
};

// The longest period a spectrum takes (s). Structures' periods are seconds; far beyond them the
// exact SDOF step loses its accuracy to cancellation (D fell to 0 at 1e10 s, where it should tend
// to the peak ground displacement), so such a period is refused, not answered wrong.
inline constexpr double kMaxSpectrumPeriod = 1000.0;

// Throws InvalidParameter naming the first bad entry ("periods[3]", "damping_ratios[0]") of
// periods (finite, > 0, at most kMaxSpectrumPeriod), damping ratios ([0, 1)) or the record (>= 2
// finite samples, dt > 0).
void ValidateSpectrumInput(const integrators::SampledHistory& ground_acceleration,
                           std::span<const double> periods, std::span<const double> damping_ratios);

ElasticSpectrum ComputeElasticSpectrum(const integrators::SampledHistory& ground_acceleration,
                                       std::span<const double> periods,
                                       std::span<const double> damping_ratios,
                                       const ElasticSpectrumOptions& options = {});

// V and A of a deformation D at period T.
SpectralOrdinate OrdinateFromDeformation(double period, double deformation, double time_of_peak);

}  // namespace isolab::spectra
