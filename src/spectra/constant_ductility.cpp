#include "isolab/spectra/constant_ductility.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "isolab/core/errors.h"
#include "isolab/hysteresis/law_parameters.h"
#include "isolab/spectra/elastic_spectrum.h"
#include "isolab/structure/shear_building.h"

namespace isolab::spectra {
namespace {

using hysteresis::LawType;

// One end of a bisection bracket: a strength ratio and the run there.
struct Probe {
  double strength = 0.0;
  DuctilityDemand::Result result;
};

ConstantDuctilityPoint PointFrom(const Probe& probe, double elastic_deformation, double omega) {
  ConstantDuctilityPoint point;
  point.strength_ratio = probe.strength;
  point.yield_deformation = probe.strength * elastic_deformation;
  point.yield_pseudo_velocity = omega * point.yield_deformation;
  point.yield_pseudo_acceleration = omega * omega * point.yield_deformation;
  point.peak_deformation = probe.result.peak_deformation;
  point.achieved_ductility = probe.result.ductility;
  return point;
}

void ValidateDuctilities(std::span<const double> ductilities) {
  for (std::size_t k = 0; k < ductilities.size(); ++k) {
    if (!(ductilities[k] >= 1.0) || !std::isfinite(ductilities[k])) {
      throw InvalidParameter(
          {fmt::format("ductilities[{}]", k), ductilities[k], "must be finite and >= 1"});
    }
  }
}

}  // namespace

void ConstantDuctilityOptions::Validate() const {
  if (!(alpha >= 0.0 && alpha < 1.0)) throw InvalidParameter({"alpha", alpha, "must be in [0, 1)"});
  if (steps_per_period < 10) {
    throw InvalidParameter({"steps_per_period", double(steps_per_period), "must be >= 10"});
  }
  if (!(scan_ratio > 0.5 && scan_ratio < 1.0)) {
    throw InvalidParameter({"scan_ratio", scan_ratio, "must be in (0.5, 1)"});
  }
  if (!(min_strength_ratio > 0.0 && min_strength_ratio < 1.0)) {
    throw InvalidParameter({"min_strength_ratio", min_strength_ratio, "must be in (0, 1)"});
  }
  if (!(tolerance > 0.0 && tolerance <= 0.01)) {
    throw InvalidParameter({"tolerance", tolerance, "must be in (0, 0.01]"});
  }
  newmark.Validate();
}

double InelasticTimeStep(double record_dt, double period, int steps_per_period) {
  // The allowance keeps T = 1 s at 50 steps on a 0.02 s record at n = 1 despite rounding.
  const int n =
      std::max(1, static_cast<int>(std::ceil(record_dt * steps_per_period / period - 1e-9)));
  return record_dt / n;
}

DuctilityDemand::DuctilityDemand(const integrators::Excitation& excitation, double period,
                                 double zeta, const ConstantDuctilityOptions& options)
    : excitation_(excitation),
      omega_(2.0 * std::numbers::pi / period),
      zeta_(zeta),
      alpha_(options.alpha),
      newmark_(options.newmark) {
  const auto& ground = excitation.ground.front().acceleration;
  grid_.dt = InelasticTimeStep(ground.dt, period, options.steps_per_period);
  // h divides the record's step, so the record's end is a whole number of steps.
  grid_.steps = static_cast<int>(std::lround(ground.duration() / grid_.dt));
  grid_.output_every = 1;  // the peak needs every step
  const double k = omega_ * omega_;
  elastic_deformation_ =
      PeakOf(structure::BuildSdof(1.0, 2.0 * zeta_ * omega_,
                                  hysteresis::SingleLaw(LawType::kLinearSpring, {k}))
                 .structure);
}

double DuctilityDemand::PeakOf(const structure::Structure& sdof) {
  const integrators::RunSummary summary =
      integrators::RunNewmark(sdof, excitation_, grid_, newmark_, &response_);
  ++runs_;
  if (!summary.ok()) {
    throw std::runtime_error(fmt::format("constant-ductility SDOF (T = {:g}, zeta = {:g}): {}",
                                         2.0 * std::numbers::pi / omega_, zeta_, summary.message));
  }
  return response_.displacement.col(0).head(response_.rows_written).cwiseAbs().maxCoeff();
}

DuctilityDemand::Result DuctilityDemand::operator()(double strength_ratio) {
  const double k = omega_ * omega_;
  const double u_y = strength_ratio * elastic_deformation_;
  // Elastoplastic is its own law; the bilinear one is BHM2: an elastoplastic branch (1 - alpha) k
  // yielding at u_y in parallel with alpha k, so the yield force is k u_y as for alpha = 0.
  hysteresis::ParallelAssembly law =
      alpha_ == 0.0 ? hysteresis::SingleLaw(LawType::kElastoplastic, {k, u_y})
                    : hysteresis::SingleLaw(LawType::kBhm2, {k, alpha_ * k, u_y});
  const double peak =
      PeakOf(structure::BuildSdof(1.0, 2.0 * zeta_ * omega_, std::move(law)).structure);
  return {peak, peak / u_y};
}

std::vector<ConstantDuctilityPoint> SolveStrengthRatios(DuctilityDemand& demand,
                                                        std::span<const double> ductilities,
                                                        const ConstantDuctilityOptions& options) {
  ValidateDuctilities(ductilities);
  const double u_o = demand.elastic_deformation();
  std::vector<ConstantDuctilityPoint> points(ductilities.size());
  if (!(u_o > 0.0)) return points;  // a record without motion: no strength is defined

  // Scan down from the elastic limit. A target is bracketed at the first interval whose lower
  // end reaches it: the demand is below it over every strength scanned above, so the crossing
  // found is the largest strength (to the scan's resolution).
  struct Bracket {
    Probe lo, hi;  // demand(lo) >= mu > demand(hi)
    bool found = false, exact = false;
  };
  std::vector<Bracket> brackets(ductilities.size());
  std::size_t pending = ductilities.size();
  Probe previous{1.0, demand(1.0)};
  for (std::size_t m = 0; m < ductilities.size(); ++m) {
    // At fy_bar = 1 the system just stays elastic: demand 1 (to round-off).
    if (std::abs(previous.result.ductility - ductilities[m]) <=
        options.tolerance * ductilities[m]) {
      brackets[m] = {previous, previous, true, true};
      --pending;
    }
  }
  for (double strength = options.scan_ratio; pending > 0 && strength >= options.min_strength_ratio;
       strength *= options.scan_ratio) {
    const Probe probe{strength, demand(strength)};
    for (std::size_t m = 0; m < ductilities.size(); ++m) {
      if (brackets[m].found || probe.result.ductility < ductilities[m]) continue;
      brackets[m] = {probe, previous, true, false};
      --pending;
    }
    previous = probe;
  }

  for (std::size_t m = 0; m < ductilities.size(); ++m) {
    Bracket& b = brackets[m];
    if (!b.found) continue;  // not reached above min_strength_ratio: NaN
    const double mu = ductilities[m];
    while (!b.exact && b.hi.strength - b.lo.strength > options.tolerance * b.hi.strength) {
      const double middle = 0.5 * (b.lo.strength + b.hi.strength);
      const Probe probe{middle, demand(middle)};
      (probe.result.ductility >= mu ? b.lo : b.hi) = probe;
    }
    // The end nearer the target, both being runs already made.
    const Probe& best =
        std::abs(b.lo.result.ductility - mu) <= std::abs(b.hi.result.ductility - mu) ? b.lo : b.hi;
    points[m] = PointFrom(best, u_o, demand.omega());
  }
  return points;
}

ConstantDuctilitySpectrum ComputeConstantDuctilitySpectrum(
    const integrators::SampledHistory& ground, std::span<const double> periods,
    std::span<const double> damping_ratios, std::span<const double> ductilities,
    const ConstantDuctilityOptions& options) {
  options.Validate();
  ValidateSpectrumInput(ground, periods, damping_ratios);
  ValidateDuctilities(ductilities);
  if (ductilities.empty()) throw InvalidParameter({"ductilities", 0.0, "at least one is needed"});
  ConstantDuctilitySpectrum spectrum;
  spectrum.periods.assign(periods.begin(), periods.end());
  spectrum.damping_ratios.assign(damping_ratios.begin(), damping_ratios.end());
  spectrum.ductilities.assign(ductilities.begin(), ductilities.end());
  spectrum.alpha = options.alpha;
  spectrum.elastic_deformations.assign(periods.size() * damping_ratios.size(), NAN);
  spectrum.points.resize(periods.size() * damping_ratios.size() * ductilities.size());
  for (const double period : periods) {
    spectrum.time_steps.push_back(InelasticTimeStep(ground.dt, period, options.steps_per_period));
  }

  integrators::Excitation excitation = integrators::Excitation::Uniform({});
  excitation.ground[0].acceleration = ground;
  const std::size_t total = periods.size() * damping_ratios.size();
  std::size_t done = 0;
  for (std::size_t d = 0; d < damping_ratios.size(); ++d) {
    for (std::size_t p = 0; p < periods.size(); ++p) {
      DuctilityDemand demand(excitation, periods[p], damping_ratios[d], options);
      const std::vector<ConstantDuctilityPoint> solved =
          SolveStrengthRatios(demand, ductilities, options);
      spectrum.elastic_deformations[d * periods.size() + p] = demand.elastic_deformation();
      for (std::size_t m = 0; m < ductilities.size(); ++m) {
        spectrum.points[(d * ductilities.size() + m) * periods.size() + p] = solved[m];
      }
      spectrum.newmark_runs += demand.runs();
      if (options.progress) {
        options.progress({++done, total, periods[p], damping_ratios[d], spectrum.newmark_runs});
      }
    }
  }
  return spectrum;
}

}  // namespace isolab::spectra
