// A spectrum's work counted before it starts, so that a request of days (a period of 1e-9 s, two
// billion points per period) is refused in a moment instead of running without end.
#pragma once

#include <cstddef>
#include <span>
#include <string>

#include "isolab/integrators/excitation.h"
#include "isolab/spectra/constant_ductility.h"

namespace isolab::spectra {

// The most SDOF steps a spectrum would take unless told otherwise (isolab spectrum
// --max-steps). On a 2-core AMD EPYC VM: about 20 s of elastic spectra (the default spectrum of
// a 60 s record counts 4.8e5 steps and takes 0.01 s), and under two minutes with ductilities,
// whose count is an upper bound (two ductilities on that record: 6.8e7 counted, 6.6 s).
inline constexpr double kDefaultMaxSpectrumSteps = 1e9;

// SDOF steps over the record: the elastic spectrum's (each period's substeps at
// `points_per_period`, per damping ratio) and, with `ductilities` > 0, the constant-ductility
// search's at its most (a Newmark run for every strength ratio of its scan, and a bisection to
// `options.tolerance` per ductility, at each period's inelastic step). Computed in floating
// point: it never overflows, whatever the inputs.
double SpectrumSteps(const integrators::SampledHistory& ground, std::span<const double> periods,
                     std::size_t damping_ratios, int points_per_period, std::size_t ductilities,
                     const ConstantDuctilityOptions& options);

// A point of a pair's walk (rotd_spectrum.h) in elastic SDOF steps, at its most: both
// oscillators and every direction's peak updated. Measured with spectra_benchmark on a 2-core AMD
// EPYC VM: the pair's 100 periods of a 30 s record cost 48 to 54 times the elastic spectrum of
// one component with every point updating every direction, 14 times with the points that can
// raise no direction skipped (as the spectra are computed); 60 bounds both.
inline constexpr double kPairStepsPerPoint = 60.0;

// A pair's spectra (either component's `ground`: they share step and length), counted as
// SpectrumSteps counts one record's elastic spectrum, each point at kPairStepsPerPoint.
double PairSpectrumSteps(const integrators::SampledHistory& ground, std::span<const double> periods,
                         std::size_t damping_ratios, int points_per_period);

// Throws InputError({limit_name}, ...) when `steps` (SpectrumSteps) exceed `max_steps`, saying
// what to ask for instead and how to raise the limit.
void CheckSpectrumWork(double steps, double max_steps, const std::string& limit_name);

}  // namespace isolab::spectra
