// Constant-ductility inelastic response spectra (Chopra, Dynamics of Structures, 4th ed.,
// Sec. 7.3-7.5). The SDOF system, per unit mass (results do not depend on m):
//   u'' + 2 zeta w u' + f_s(u)/m = -a_g(t),   w = 2 pi / T the small-oscillation frequency,
// f_s elastoplastic (alpha = 0) or bilinear with post-yield stiffness alpha k, yield force f_y at
// yield deformation u_y = f_y / k (hysteresis library: elastoplastic, or BHM2 = an elastoplastic
// branch (1 - alpha) k in parallel with a spring alpha k). With u_o the peak deformation of the
// corresponding linear system and f_o = k u_o its peak force:
//   normalised yield strength   fy_bar = f_y / f_o = u_y / u_o,
//   ductility demand            mu(fy_bar) = u_m / u_y,  u_m = max |u(t)|.
// For each target mu this finds the yield strength whose demand is mu, and reports
//   D_y = u_y,   V_y = w u_y,   A_y = w^2 u_y (= f_y / m),   u_m = mu u_y.
// mu(fy_bar) is not monotonic: several strengths may give one ductility (Chopra Sec. 7.5, Fig.
// 7.5.1); as Chopra does, the largest is chosen. It is found by scanning fy_bar downward from 1
// on a geometric grid (ratio `scan_ratio`) until the demand first reaches mu, then bisecting that
// interval to a relative width `tolerance`. A crossing narrower than one scan interval can be
// missed; the returned strength is then still one giving mu, but not the largest.
//
// Time stepping: the project's Newmark integrator (average acceleration, full Newton) with step
// h = dt / n, n the smallest integer with h <= T / steps_per_period (default 50): at most the
// record's step and T/50, and a divisor of the record's step so every record sample is a step.
// u_o comes from the same integrator at the same h, so fy_bar = 1 is exactly the elastic limit and
// mu = 1 gives fy_bar = 1; u_o differs from the exact elastic D of elastic_spectrum.h by
// Newmark's period error and its sampling at h, under 0.5 % from T = 0.1 to 4 s on the bundled
// record (tests/spectra/constant_ductility_test.cpp), so A_y at mu = 1 is A to that accuracy.
#pragma once

#include <cmath>
#include <functional>
#include <span>
#include <vector>

#include "isolab/integrators/excitation.h"
#include "isolab/integrators/newmark.h"
#include "isolab/integrators/response.h"

namespace isolab::spectra {

struct ConstantDuctilityProgress {
  std::size_t done = 0, total = 0;  // oscillators (period x damping) finished, of all
  double period = 0.0;              // of the one just finished (time)
  double damping_ratio = 0.0;
  long newmark_runs = 0;  // so far
};

struct ConstantDuctilityOptions {
  double alpha = 0.0;                   // post-yield stiffness / initial stiffness; [0, 1)
  int steps_per_period = 50;            // least Newmark steps per natural period; >= 10
  double scan_ratio = 0.97;             // fy_bar scanned as 1, r, r^2, ...; (0.5, 1)
  double min_strength_ratio = 0.01;     // lowest fy_bar scanned; (0, 1)
  double tolerance = 1e-4;              // bisection stops at (hi - lo) <= tolerance * hi; (0, 0.01]
  integrators::NewmarkOptions newmark;  // average acceleration, full Newton
  std::function<void(const ConstantDuctilityProgress&)> progress;  // after each oscillator

  // Throws InvalidParameter naming the field out of range.
  void Validate() const;
};

struct ConstantDuctilityPoint {
  double strength_ratio = NAN;             // fy_bar = f_y / f_o (-); NaN where no fy_bar >=
                                           // min_strength_ratio gives the ductility
  double yield_deformation = NAN;          // D_y = u_y = fy_bar u_o (length)
  double yield_pseudo_velocity = NAN;      // V_y = w u_y (length/time)
  double yield_pseudo_acceleration = NAN;  // A_y = w^2 u_y (length/time^2)
  double peak_deformation = NAN;           // u_m of the run at fy_bar (length), = mu u_y
  double achieved_ductility = NAN;         // u_m / u_y of that run: mu to the tolerance
};

struct ConstantDuctilitySpectrum {
  std::vector<double> periods;         // (time)
  std::vector<double> damping_ratios;  // (-)
  std::vector<double> ductilities;     // targets mu >= 1
  double alpha = 0.0;
  std::vector<double> time_steps;              // Newmark h per period (time)
  std::vector<double> elastic_deformations;    // u_o, [d * periods + p] (length)
  std::vector<ConstantDuctilityPoint> points;  // [(d * ductilities + m) * periods + p]
  long newmark_runs = 0;

  const ConstantDuctilityPoint& at(std::size_t damping, std::size_t ductility,
                                   std::size_t period) const {
    return points[(damping * ductilities.size() + ductility) * periods.size() + period];
  }
};

// Newmark step for a period: the record's step divided by the smallest n that brings it to
// T / steps_per_period or below.
double InelasticTimeStep(double record_dt, double period, int steps_per_period);

// One oscillator (T, zeta, alpha) under one record: the ductility demand as a function of the
// normalised yield strength, one Newmark run per call, its working arrays reused across calls.
class DuctilityDemand {
 public:
  struct Result {
    double peak_deformation = 0.0;  // u_m (length)
    double ductility = 0.0;         // u_m / u_y
  };

  // Runs the linear system once for u_o. `excitation` must outlive this object.
  DuctilityDemand(const integrators::Excitation& excitation, double period, double zeta,
                  const ConstantDuctilityOptions& options);

  // Throws std::runtime_error (with Newmark's message) if a run fails to converge.
  Result operator()(double strength_ratio);

  double elastic_deformation() const { return elastic_deformation_; }  // u_o
  double time_step() const { return grid_.dt; }
  double omega() const { return omega_; }  // 2 pi / T
  long runs() const { return runs_; }

 private:
  // One Newmark run from rest; the peak |u|.
  double PeakOf(const structure::Structure& sdof);

  const integrators::Excitation& excitation_;
  double omega_, zeta_, alpha_;
  integrators::NewmarkOptions newmark_;
  integrators::TimeGrid grid_;
  integrators::ResponseHistory response_;
  double elastic_deformation_ = 0.0;
  long runs_ = 0;
};

// The largest strength ratio in [min_strength_ratio, 1] whose demand is each target ductility
// (scan shared by all targets, then one bisection per target). Targets must be >= 1.
std::vector<ConstantDuctilityPoint> SolveStrengthRatios(DuctilityDemand& demand,
                                                        std::span<const double> ductilities,
                                                        const ConstantDuctilityOptions& options);

// Every period x damping ratio x ductility. Throws InvalidParameter for bad input (as
// ValidateSpectrumInput, and ductilities[k] < 1) and std::runtime_error if Newmark fails.
ConstantDuctilitySpectrum ComputeConstantDuctilitySpectrum(
    const integrators::SampledHistory& ground_acceleration, std::span<const double> periods,
    std::span<const double> damping_ratios, std::span<const double> ductilities,
    const ConstantDuctilityOptions& options);

}  // namespace isolab::spectra
