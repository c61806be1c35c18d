#include "isolab/design/matched_pairs.h"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <unsupported/Eigen/FFT>

#include "isolab/core/errors.h"
#include "isolab/spectra/rotd_spectrum.h"

namespace isolab::design {
namespace {

// The margins around [period_min, period_max] over which the correction tapers off, and the
// spacing of the check periods (a 5 %-damped oscillator's half-power band is 10 % wide: 2.5 %
// steps follow the spectrum's smooth peaks; its V-shaped dips are sought between them).
constexpr double kLowMargin = 0.8, kHighMargin = 1.25;
constexpr double kSpacing = 1.025;
// Points per natural period at which the peaks are sought (ElasticSpectrumOptions): while
// matching, 30 (peaks found to 1 - cos(pi / 30) = 0.55 %, about a third of the work at short
// periods); for the misfit reported, the default 100 (0.05 %).
constexpr int kMatchingPoints = 30, kReportedPoints = 100;
// The gain on a check period's correction (header): raised by kGainUp, up to kMaxGain, while its
// misfit keeps its sign and shrinks by less than a factor kSlow per iteration; cut by kGainDown,
// down to 1, when the misfit changes sign.
constexpr double kSlow = 0.7, kGainUp = 1.5, kMaxGain = 2.0, kGainDown = 0.5;
constexpr int kMinIntervals = 48, kMaxIntervals = 400;
// A pair whose misfit has not fallen for kPatience iterations (the correction no longer moves
// it: fixed phases can trap it) starts again from the next attempt's seeds, up to kAttempts in
// all; the best attempt is returned.
constexpr int kPatience = 8, kAttempts = 4;
// Powers (t / t_end)^0..4 of the acceleration's baseline correction: displacements of degree 2
// to 6, as Boore & Bommer (2005) fit.
constexpr int kBaselineTerms = 5;

void RequireField(bool ok, const char* key, double value, const std::string& rule) {
  if (!ok) throw InvalidParameter({key, value, rule});
}

// Velocity and displacement from rest by the trapezoidal rule.
void IntegrateTrapezoidal(const std::vector<double>& a, double dt, std::vector<double>* v,
                          std::vector<double>* d) {
  v->assign(a.size(), 0.0);
  d->assign(a.size(), 0.0);
  for (std::size_t k = 1; k < a.size(); ++k) {
    (*v)[k] = (*v)[k - 1] + 0.5 * dt * (a[k - 1] + a[k]);
    (*d)[k] = (*d)[k - 1] + 0.5 * dt * ((*v)[k - 1] + (*v)[k]);
  }
}

// The constrained least-squares baseline correction of the header, set up once for a length and
// step: the basis' displacements (by the record's own integration rule, so the constraints hold
// for it to rounding) and the factorised KKT matrix.
class BaselineCorrection {
 public:
  BaselineCorrection(std::size_t samples, double dt)
      : dt_(dt),
        basis_(Eigen::Index(samples), kBaselineTerms),
        basis_displacement_(Eigen::Index(samples), kBaselineTerms) {
    const double t_end = dt * static_cast<double>(samples - 1);
    Eigen::Matrix<double, 2, kBaselineTerms> ends;
    std::vector<double> phi(samples), v, d;
    for (int j = 0; j < kBaselineTerms; ++j) {
      for (std::size_t k = 0; k < samples; ++k) {
        phi[k] = std::pow(static_cast<double>(k) * dt / t_end, j);
        basis_(static_cast<Eigen::Index>(k), j) = phi[k];
      }
      IntegrateTrapezoidal(phi, dt, &v, &d);
      for (std::size_t k = 0; k < samples; ++k) basis_displacement_(Eigen::Index(k), j) = d[k];
      ends(0, j) = v.back();
      ends(1, j) = d.back();
    }
    // minimise |D x - d|^2 subject to E x = (v_end, d_end):
    //   [D'D E'; E 0] [x; lambda] = [D'd; (v_end, d_end)]
    Eigen::Matrix<double, kBaselineTerms + 2, kBaselineTerms + 2> kkt;
    kkt.setZero();
    kkt.topLeftCorner<kBaselineTerms, kBaselineTerms>() =
        basis_displacement_.transpose() * basis_displacement_;
    kkt.topRightCorner<kBaselineTerms, 2>() = ends.transpose();
    kkt.bottomLeftCorner<2, kBaselineTerms>() = ends;
    solver_.compute(kkt);
  }

  // Removes the fitted polynomial from `a` (in place).
  void Apply(std::vector<double>* a) const {
    std::vector<double> v, d;
    IntegrateTrapezoidal(*a, dt_, &v, &d);
    Eigen::Matrix<double, kBaselineTerms + 2, 1> rhs;
    const Eigen::Map<const Eigen::VectorXd> displacement(d.data(), Eigen::Index(d.size()));
    rhs.head<kBaselineTerms>() = basis_displacement_.transpose() * displacement;
    rhs(kBaselineTerms) = v.back();
    rhs(kBaselineTerms + 1) = d.back();
    const Eigen::Matrix<double, kBaselineTerms + 2, 1> x = solver_.solve(rhs);
    const Eigen::VectorXd correction = basis_ * x.head<kBaselineTerms>();
    for (std::size_t k = 0; k < a->size(); ++k) {
      (*a)[k] -= correction(Eigen::Index(k));
      (*a)[k] += 0.0;  // no "-0" samples
    }
  }

 private:
  double dt_;
  Eigen::MatrixXd basis_, basis_displacement_;
  Eigen::FullPivLU<Eigen::Matrix<double, kBaselineTerms + 2, kBaselineTerms + 2>> solver_;
};

// The check periods with the target at each and the weight of its correction: 1 in
// [period_min, period_max], a half cosine in log-period down to 0 across the margins.
struct CheckGrid {
  std::vector<double> periods, target, weight;
  std::vector<bool> in_range;
};

double Taper(double log_distance, double log_margin) {
  if (log_distance >= log_margin) return 0.0;
  return 0.5 * (1.0 + std::cos(std::numbers::pi * log_distance / log_margin));
}

// target(period), refused unless finite and > 0.
double TargetAt(const MatchedPairSpec& spec, const std::function<double(double)>& target,
                double period) {
  const double value = target(period);
  if (!(std::isfinite(value) && value > 0.0)) {
    throw InvalidParameter({fmt::format("target({:g} s)", period), value,
                            fmt::format("must be finite and > 0 over [period_min, period_max] "
                                        "= [{:g}, {:g}] s",
                                        spec.period_min, spec.period_max)});
  }
  return value;
}

CheckGrid MakeGrid(const MatchedPairSpec& spec, const std::function<double(double)>& target) {
  CheckGrid grid;
  grid.periods = MatchedPairCheckPeriods(spec);
  const auto at = [&](double period) { return TargetAt(spec, target, period); };
  // The margins extend log target linearly in log T from each end's last 25 %.
  const double low_inner = std::min(spec.period_min * kHighMargin, spec.period_max);
  const double high_inner = std::max(spec.period_max / kHighMargin, spec.period_min);
  const double s_low = at(spec.period_min), s_high = at(spec.period_max);
  const double slope_low = std::log(at(low_inner) / s_low) / std::log(low_inner / spec.period_min);
  const double slope_high =
      std::log(s_high / at(high_inner)) / std::log(spec.period_max / high_inner);
  for (const double period : grid.periods) {
    if (period < spec.period_min) {
      const double log_distance = std::log(spec.period_min / period);
      grid.target.push_back(s_low * std::exp(-slope_low * log_distance));
      grid.weight.push_back(Taper(log_distance, std::log(1.0 / kLowMargin)));
      grid.in_range.push_back(false);
    } else if (period > spec.period_max) {
      const double log_distance = std::log(period / spec.period_max);
      grid.target.push_back(s_high * std::exp(slope_high * log_distance));
      grid.weight.push_back(Taper(log_distance, std::log(kHighMargin)));
      grid.in_range.push_back(false);
    } else {
      grid.target.push_back(at(period));
      grid.weight.push_back(1.0);
      grid.in_range.push_back(true);
    }
  }
  return grid;
}

// The pair's RotD100 (g) at a set of periods: the grid's, and those added where a dip was sought
// (RefineDips), kept in increasing period with their target and weight.
struct Measured {
  std::vector<double> periods, target, weight, rotd;
  std::vector<bool> in_range;
};

std::vector<double> RotD100(const std::vector<double>& a1, const std::vector<double>& a2, double dt,
                            const std::vector<double>& periods, double damping_ratio,
                            int points_per_period) {
  const integrators::SampledHistory h1{dt, a1}, h2{dt, a2};
  const double zeta[] = {damping_ratio};
  spectra::ElasticSpectrumOptions options;
  options.points_per_period = points_per_period;
  const spectra::PairSpectrum pair = spectra::ComputePairSpectrum(h1, h2, periods, zeta, options);
  std::vector<double> rotd(periods.size());
  for (std::size_t p = 0; p < rotd.size(); ++p) {
    rotd[p] = pair.rotd100.at(0, p).pseudo_acceleration;
  }
  return rotd;
}

Measured Measure(const std::vector<double>& a1, const std::vector<double>& a2, double dt,
                 const CheckGrid& grid, double damping_ratio, int points_per_period) {
  return {grid.periods, grid.target, grid.weight,
          RotD100(a1, a2, dt, grid.periods, damping_ratio, points_per_period), grid.in_range};
}

// RotD100 is the largest of the peaks of |u(t)| over time, each smooth in T, so its maxima are
// smooth (a grid finds them to second order) but its minima can be V-shaped, where the largest
// peak passes from one time to another: between two check periods 2.5 % apart such a dip was
// seen 4.5 % below both. Around every local extremum of RotD100/target in
// [period_min, period_max] whose misfit exceeds `threshold`, both neighbouring intervals are
// halved, and again around the extrema that gives, down to intervals of kDipResolution in ln T
// (a V of the steepest slope seen, 4 per unit of ln T, is then found to 0.05 %).
constexpr int kDipDivisions = 2;
constexpr double kDipResolution = 2e-4;
// Dips and peaks are sought where the misfit at a check period is within kDipMargin (or half the
// tolerance, if less) of the tolerance: the deepest dip seen between check periods 2.5 % apart
// was 4.5 % below its neighbours.
constexpr double kDipMargin = 0.05;

void RefineDips(const std::vector<double>& a1, const std::vector<double>& a2, double dt,
                double damping_ratio, int points_per_period, double threshold,
                const std::function<double(double)>& target, Measured* m) {
  for (;;) {
    std::vector<double> added;
    const std::size_t n = m->periods.size();
    for (std::size_t i = 1; i + 1 < n; ++i) {
      const double q = m->rotd[i] / m->target[i];
      const double before = m->rotd[i - 1] / m->target[i - 1];
      const double after = m->rotd[i + 1] / m->target[i + 1];
      const bool dip = q < 1.0 - threshold && q <= before && q <= after;
      const bool peak = q > 1.0 + threshold && q >= before && q >= after;
      if (!m->in_range[i] || !(dip || peak)) continue;
      for (const std::size_t left : {i - 1, i}) {
        const double width = std::log(m->periods[left + 1] / m->periods[left]);
        if (width <= kDipResolution) continue;
        for (int j = 1; j < kDipDivisions; ++j) {
          const double period = m->periods[left] * std::exp(width * j / kDipDivisions);
          if (m->in_range[left] && m->in_range[left + 1]) added.push_back(period);
        }
      }
    }
    if (added.empty()) return;
    std::sort(added.begin(), added.end());
    added.erase(std::unique(added.begin(), added.end()), added.end());
    const std::vector<double> rotd = RotD100(a1, a2, dt, added, damping_ratio, points_per_period);
    Measured merged;
    std::size_t i = 0, j = 0;
    while (i < n || j < added.size()) {
      if (j == added.size() || (i < n && m->periods[i] <= added[j])) {
        merged.periods.push_back(m->periods[i]);
        merged.target.push_back(m->target[i]);
        merged.weight.push_back(m->weight[i]);
        merged.rotd.push_back(m->rotd[i]);
        merged.in_range.push_back(m->in_range[i]);
        ++i;
      } else {
        merged.periods.push_back(added[j]);
        merged.target.push_back(target(added[j]));
        merged.weight.push_back(1.0);
        merged.rotd.push_back(rotd[j]);
        merged.in_range.push_back(true);
        ++j;
      }
    }
    *m = std::move(merged);
  }
}

double Misfit(const Measured& m) {
  double misfit = 0.0;
  for (std::size_t p = 0; p < m.rotd.size(); ++p) {
    if (m.in_range[p]) misfit = std::max(misfit, std::abs(m.rotd[p] / m.target[p] - 1.0));
  }
  return misfit;
}

// One correction of both components' Fourier amplitudes (header, step 3). Beyond the widened
// range the amplitudes are scaled by the geometric mean of the in-range ratios, so that what lies
// outside keeps its proportion to the matched band (the first iteration scales the starting
// records' arbitrary level; afterwards it is close to 1); in the margins the correction tapers
// to that level.
class SpectralScaling {
 public:
  SpectralScaling(std::size_t samples, double dt) : samples_(samples), dt_(dt) {
    padded_length_ = 1;
    while (padded_length_ < 2 * samples) padded_length_ *= 2;
  }

  void Apply(const Measured& grid, const std::vector<double>& gain, std::vector<double>* a1,
             std::vector<double>* a2) {
    const std::vector<double>& rotd = grid.rotd;
    const std::size_t n = grid.periods.size();
    std::vector<double> log_ratio(n);
    double mean = 0.0;
    int in_range = 0;
    for (std::size_t p = 0; p < n; ++p) {
      log_ratio[p] = std::log(grid.target[p] / rotd[p]);
      if (grid.in_range[p]) mean += log_ratio[p], ++in_range;
    }
    mean /= in_range;
    for (std::size_t p = 0; p < n; ++p) {
      log_ratio[p] = mean + grid.weight[p] * (gain[p] * log_ratio[p] - mean);
    }
    // Per bin (its frequency min(k, M - k) / (M dt)), log r interpolated linearly in log T.
    const std::size_t m = padded_length_;
    factor_.assign(m / 2 + 1, std::exp(mean));
    for (std::size_t k = 1; k <= m / 2; ++k) {
      const double period = static_cast<double>(m) * dt_ / static_cast<double>(k);
      if (period < grid.periods.front() || period > grid.periods.back()) continue;
      const auto upper = std::upper_bound(grid.periods.begin(), grid.periods.end(), period);
      const std::size_t i =
          std::min<std::size_t>(std::max<std::ptrdiff_t>(upper - grid.periods.begin(), 1), n - 1);
      const double s =
          std::log(period / grid.periods[i - 1]) / std::log(grid.periods[i] / grid.periods[i - 1]);
      factor_[k] = std::exp((1.0 - s) * log_ratio[i - 1] + s * log_ratio[i]);
    }
    Scale(a1);
    Scale(a2);
  }

 private:
  void Scale(std::vector<double>* a) {
    const std::size_t m = padded_length_;
    padded_.assign(m, 0.0);
    std::copy(a->begin(), a->end(), padded_.begin());
    fft_.fwd(spectrum_, padded_);
    for (std::size_t k = 0; k < m; ++k) spectrum_[k] *= factor_[std::min(k, m - k)];
    fft_.inv(padded_, spectrum_);
    std::copy(padded_.begin(), padded_.begin() + std::ptrdiff_t(samples_), a->begin());
  }

  std::size_t samples_, padded_length_;
  double dt_;
  Eigen::FFT<double> fft_;
  std::vector<double> padded_, factor_;
  std::vector<std::complex<double>> spectrum_;
};

std::string DescribeComponent(const MatchedPairSpec& spec, int pair, int component, int attempt,
                              std::uint64_t seed, const MatchedPair& result) {
  return fmt::format(
      "isolab spectrum-matched pair {} {} (pair seed {}): filtered noise seed {}{}, RotD100 at "
      "{:g} "
      "% damping matched to {} over [{:g}, {:g}] s by frequency-domain scaling (SIMQKE style, "
      "Gasparini & Vanmarcke 1976) with polynomial baseline correction; misfit {:.4f} after {} "
      "iterations{}",
      pair + 1, component == 0 ? "H1" : "H2", spec.seed, seed,
      attempt == 0 ? "" : fmt::format(" (attempt {})", attempt + 1), 100.0 * spec.damping_ratio,
      spec.target_name.empty() ? "the given target" : spec.target_name, spec.period_min,
      spec.period_max, result.misfit, result.iterations,
      result.converged ? "" : fmt::format(" (NOT within the tolerance {:g})", spec.tolerance));
}

// One attempt at pair k: from the filtered noise of its attempt's seeds (header) to the
// records of least misfit, written into a[0], a[1]; pair->misfit, iterations and seeds filled.
void MatchAttempt(const MatchedPairSpec& spec, const std::function<double(double)>& target,
                  const CheckGrid& grid, const BaselineCorrection& baseline,
                  SpectralScaling& scaling, int k, int attempt, std::uint64_t seeds[2],
                  std::vector<double> best_a[2], MatchedPair* best) {
  const double dt = spec.motion.dt;
  std::vector<double> a[2];
  for (int c = 0; c < 2; ++c) {
    analysis::FilteredNoiseSpec motion = spec.motion;
    motion.seed = seeds[c] = MatchedPairComponentSeed(spec.seed, k, c, attempt);
    motion.pga = 1.0;  // the first correction scales it to the target
    a[c] = analysis::FilteredNoiseRecord(motion).values;
    baseline.Apply(&a[c]);
  }
  // The least misfit seen by the matching spectrum, for an attempt that does not converge.
  double least = std::numeric_limits<double>::infinity();
  // The misfit as reported: the exact spectrum, dips and peaks sought between check periods.
  const auto reported = [&](const std::vector<double>& a1, const std::vector<double>& a2) {
    Measured m = Measure(a1, a2, dt, grid, spec.damping_ratio, kReportedPoints);
    RefineDips(
        a1, a2, dt, spec.damping_ratio, kReportedPoints,
        spec.tolerance - std::min(kDipMargin, 0.5 * spec.tolerance),
        [&](double period) { return TargetAt(spec, target, period); }, &m);
    return m;
  };
  std::vector<double> gain(grid.periods.size(), 1.0), previous(grid.periods.size(), 0.0);
  for (int iteration = 0;; ++iteration) {
    Measured m = Measure(a[0], a[1], dt, grid, spec.damping_ratio, kMatchingPoints);
    const double misfit = Misfit(m);
    if (misfit < least) {
      least = misfit;
      best->iterations = iteration;
      best_a[0] = a[0];
      best_a[1] = a[1];
    }
    if (misfit <= spec.tolerance) {
      m = reported(a[0], a[1]);
      best->misfit = Misfit(m);
      if (best->misfit <= spec.tolerance) {
        best->iterations = iteration;
        best_a[0] = std::move(a[0]);
        best_a[1] = std::move(a[1]);
        return;
      }
    }
    if (iteration >= spec.max_iterations || iteration - best->iterations >= kPatience) {
      best->misfit = Misfit(reported(best_a[0], best_a[1]));
      return;
    }
    // The gain of each check period (header); periods added by RefineDips take 1.
    std::vector<double> point_gain(m.periods.size(), 1.0);
    for (std::size_t p = 0, g = 0; p < m.periods.size() && g < grid.periods.size(); ++p) {
      if (m.periods[p] != grid.periods[g]) continue;
      const double d = std::log(m.target[p] / m.rotd[p]);
      if (iteration > 0 && d * previous[g] > 0 && std::abs(d) > kSlow * std::abs(previous[g])) {
        gain[g] = std::min(gain[g] * kGainUp, kMaxGain);
      } else if (d * previous[g] < 0) {
        gain[g] = std::max(gain[g] * kGainDown, 1.0);
      }
      previous[g] = d;
      point_gain[p] = gain[g++];
    }
    scaling.Apply(m, point_gain, &a[0], &a[1]);
    baseline.Apply(&a[0]);
    baseline.Apply(&a[1]);
  }
}

}  // namespace

void MatchedPairSpec::Validate() const {
  RequireField(count >= 1, "count", count, "must be >= 1");
  RequireField(motion.dt > 0 && std::isfinite(motion.dt), "motion.dt", motion.dt, "must be > 0");
  RequireField(motion.duration >= 10 * motion.dt && std::isfinite(motion.duration),
               "motion.duration", motion.duration,
               fmt::format("must be >= 10 motion.dt = {:g} s", 10 * motion.dt));
  RequireField(period_min >= 5 * motion.dt && std::isfinite(period_min), "period_min", period_min,
               fmt::format("must be >= 5 motion.dt = {:g} s: the margin below it, down to 0.8 "
                           "period_min, stays under the Nyquist frequency",
                           5 * motion.dt));
  RequireField(period_max > period_min && std::isfinite(period_max), "period_max", period_max,
               fmt::format("must be > period_min = {:g} s", period_min));
  RequireField(period_max <= motion.duration / 4, "period_max", period_max,
               fmt::format("must be at most a quarter of motion.duration, {:g} s: a record holds "
                           "several cycles of every period it matches",
                           motion.duration / 4));
  RequireField(damping_ratio >= 0 && damping_ratio < 1, "damping_ratio", damping_ratio,
               "must be in [0, 1)");
  RequireField(tolerance > 0 && std::isfinite(tolerance), "tolerance", tolerance, "must be > 0");
  RequireField(max_iterations >= 0, "max_iterations", max_iterations, "must be >= 0");
}

std::uint64_t MatchedPairComponentSeed(std::uint64_t seed, int pair, int component, int attempt) {
  // SplitMix64's n-th output from state `seed`: its state after n steps is seed + n * gamma.
  const std::uint64_t n = 2 * static_cast<std::uint64_t>(pair) + component + 1 +
                          (static_cast<std::uint64_t>(attempt) << 32);
  std::uint64_t z = seed + n * 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

std::vector<double> MatchedPairCheckPeriods(const MatchedPairSpec& spec) {
  const double range = std::log(spec.period_max / spec.period_min);
  const int intervals = std::clamp(static_cast<int>(std::ceil(range / std::log(kSpacing))),
                                   kMinIntervals, kMaxIntervals);
  const double step = range / intervals;
  const int low = static_cast<int>(std::ceil(std::log(1.0 / kLowMargin) / step));
  const int high = static_cast<int>(std::ceil(std::log(kHighMargin) / step));
  std::vector<double> periods;
  for (int i = -low; i <= intervals + high; ++i) {
    periods.push_back(i == 0           ? spec.period_min
                      : i == intervals ? spec.period_max
                                       : spec.period_min * std::exp(i * step));
  }
  return periods;
}

std::vector<MatchedPair> MatchPairs(const MatchedPairSpec& spec,
                                    const std::function<double(double)>& target) {
  spec.Validate();
  const CheckGrid grid = MakeGrid(spec, target);
  const double dt = spec.motion.dt;
  const std::size_t samples = static_cast<std::size_t>(std::round(spec.motion.duration / dt)) + 1;
  const BaselineCorrection baseline(samples, dt);
  SpectralScaling scaling(samples, dt);
  std::vector<MatchedPair> pairs;
  for (int k = 0; k < spec.count; ++k) {
    MatchedPair best;
    best.misfit = std::numeric_limits<double>::infinity();
    std::vector<double> best_a[2];
    std::uint64_t best_seeds[2] = {};
    int best_attempt = 0;
    for (int attempt = 0; attempt < kAttempts && !(best.misfit <= spec.tolerance); ++attempt) {
      MatchedPair pair;
      std::vector<double> pair_a[2];
      std::uint64_t seeds[2];
      MatchAttempt(spec, target, grid, baseline, scaling, k, attempt, seeds, pair_a, &pair);
      if (pair.misfit < best.misfit) {
        best = std::move(pair);
        best_a[0] = std::move(pair_a[0]);
        best_a[1] = std::move(pair_a[1]);
        best_seeds[0] = seeds[0];
        best_seeds[1] = seeds[1];
        best_attempt = attempt;
      }
    }
    best.converged = best.misfit <= spec.tolerance;
    io::Record* records[2] = {&best.h1, &best.h2};
    for (int c = 0; c < 2; ++c) {
      io::Record& record = *records[c];
      record.dt = dt;
      record.units = "g";
      record.format = "PEER AT2";
      record.values = std::move(best_a[c]);
      record.description = DescribeComponent(spec, k, c, best_attempt, best_seeds[c], best);
    }
    pairs.push_back(std::move(best));
  }
  return pairs;
}

}  // namespace isolab::design
