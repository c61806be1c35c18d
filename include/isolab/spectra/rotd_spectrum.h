// Elastic spectra of a pair of horizontal record components, orientation-independent (Boore,
// "Orientation-independent, nongeometric-mean measures of seismic intensity from two horizontal
// components of motion", BSSA 100(4), 2010). A linear oscillator's response to the pair turned by
// an angle theta (H1 towards H2) is, by linearity,
//   u(theta, t) = u1(t) cos theta + u2(t) sin theta,
// u1, u2 its responses to the components (exact_linear_sdof.h), so one walk of both in lockstep
// gives every angle. Per period and damping ratio, with D(theta) = max_t |u(theta, t)|:
//   RotD50   the median of D(theta) over the non-redundant angles 0, 1, ..., 179 degrees
//            (Boore's 1-degree steps; the mean of the 90th and 91st of the 180 sorted values)
//   RotD100  the largest D in any direction, max_t |(u1, u2)|: the "maximum direction" response
//            of ASCE 7-16 Sec. 21.2 (Boore's largest over the 1-degree angles is at most
//            1 - cos(0.5 degrees) = 3.8e-5 below it)
//   geometric mean  sqrt(D1 D2) of the as-recorded components' D1 = D(0), D2 = D(90 degrees)
// and V = w D, A = w^2 D of each (elastic_spectrum.h). Units: the records' and the periods'.
//
// Constant-ductility spectra of a pair do not follow this way (an inelastic oscillator is not
// linear): there is none here.
#pragma once

#include <span>
#include <vector>

#include "isolab/integrators/excitation.h"
#include "isolab/spectra/elastic_spectrum.h"

namespace isolab::spectra {

inline constexpr int kRotDAngles = 180;  // 0, 1, ..., 179 degrees

struct PairSpectrum {
  // Each on the same grid (periods, damping ratios), damping-major as ElasticSpectrum. The
  // components' are what ComputeElasticSpectrum gives for each record alone, to the bit; the
  // geometric mean's and RotD50's time_of_peak are NaN, RotD100's when |(u1, u2)| peaks.
  ElasticSpectrum h1, h2, geometric_mean, rotd50, rotd100;
  // Per ordinate: the direction of RotD100, degrees from H1 towards H2 in [0, 180).
  std::vector<double> rotd100_angle;
};

// Throws InvalidParameter as ValidateSpectrumInput does (naming "h1 ..." or "h2 ..."), and for
// components of different steps or lengths ("h2 dt", "h2 samples").
void ValidatePairInput(const integrators::SampledHistory& h1, const integrators::SampledHistory& h2,
                       std::span<const double> periods, std::span<const double> damping_ratios);

// Throws InvalidParameter as ValidatePairInput and ElasticSpectrumOptions::Validate do.
PairSpectrum ComputePairSpectrum(const integrators::SampledHistory& h1,
                                 const integrators::SampledHistory& h2,
                                 std::span<const double> periods,
                                 std::span<const double> damping_ratios,
                                 const ElasticSpectrumOptions& options = {});

}  // namespace isolab::spectra
