// Exact response of a linear SDOF oscillator from rest to a ground acceleration that is linear
// between samples (the record as isolab reads it):
//   u'' + 2 zeta w u' + w^2 u = p(t),   p = -a_g,   w = 2 pi / T,
// u the deformation relative to the ground. Over a step h in which p is linear the state at the
// end is a linear map of the state and the loads at both ends (Nigam & Jennings 1969; Chopra,
// Dynamics of Structures, 4th ed., Sec. 5.2, Eq. 5.2.5 and Table 5.2.1, here per unit mass,
// k = w^2):
//   u_{i+1} = A  u_i + B  v_i + C  p_i + D  p_{i+1}
//   v_{i+1} = A' u_i + B' v_i + C' p_i + D' p_{i+1}
// with w_D = w sqrt(1 - zeta^2), e = exp(-zeta w h), s = sin(w_D h), c = cos(w_D h),
// r = zeta / sqrt(1 - zeta^2):
//   A  = e (r s + c)                      B  = e s / w_D
//   C  = [2 zeta/(w h) + e(((1 - 2 zeta^2)/(w_D h) - r) s - (1 + 2 zeta/(w h)) c)] / w^2
//   D  = [1 - 2 zeta/(w h) + e((2 zeta^2 - 1)/(w_D h) s + 2 zeta/(w h) c)] / w^2
//   A' = -e w s / sqrt(1 - zeta^2)        B' = e (c - r s)
//   C' = [-1/h + e((w/sqrt(1 - zeta^2) + r/h) s + c/h)] / w^2
//   D' = [1 - e (r s + c)] / (w^2 h)
// No approximation is made: the result is the exact response to the piecewise-linear record at
// every point the recurrence visits, whatever h. It shares no code with the Newmark integrator,
// so each checks the other (tests/spectra/exact_linear_sdof_test.cpp).
//
// Peaks are sought at the recurrence's points, not between them. The record's own samples are
// visited, and where a record step is long against the period it is cut into equal sub-steps
// (the load still interpolated linearly, so still exact) so that there are at least
// `points_per_period` points per natural period: with the default 100, the peak read at points is
// within 1 - cos(pi/100) = 0.05 % of the continuous peak in the worst case. With 1 there are no
// sub-steps (for periods above the record's step): the peak of the record's samples, the way
// Chopra reads his spectra; on El Centro at T = 0.5 s that is 0.5 % below the continuous peak
// (tests/spectra/elastic_spectrum_test.cpp).
#pragma once

#include <vector>

#include "isolab/integrators/excitation.h"

namespace isolab::spectra {

// The recurrence's coefficients for one step (names as in Chopra's Table 5.2.1; the primed ones
// with suffix _v). Units follow from per-unit-mass loads: C, D in time^2, C', D' in time.
struct ExactStepCoefficients {
  double a = 0, b = 0, c = 0, d = 0;
  double a_v = 0, b_v = 0, c_v = 0, d_v = 0;

  // w > 0 (rad/time), 0 <= zeta < 1, h > 0 (time). Underdamped only: response spectra are.
  static ExactStepCoefficients For(double omega, double zeta, double h);
};

// Peak |u| over the record's duration and the time it occurs. The oscillator is at rest at t = 0;
// free vibration after the record's last sample is not followed.
struct PeakDeformation {
  double value = 0.0;  // (length)
  double time = 0.0;   // (time)
};

// Sub-steps per record step so that a period holds at least `points_per_period` points.
int SubstepsPerSample(double record_dt, double period, int points_per_period);

// Throws InvalidParameter for period <= 0, zeta outside [0, 1) or points_per_period < 1.
// Allocates nothing.
PeakDeformation ExactPeakDeformation(const integrators::SampledHistory& ground_acceleration,
                                     double period, double zeta, int points_per_period = 100);

// u at every recurrence point (record samples, each step cut into `substeps`), for checks;
// element k is at time k dt / substeps.
std::vector<double> ExactDeformationHistory(const integrators::SampledHistory& ground_acceleration,
                                            double period, double zeta, int substeps = 1);

}  // namespace isolab::spectra
