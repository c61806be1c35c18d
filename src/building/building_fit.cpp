#include "isolab/building/building_fit.h"

#include <fmt/format.h>

#include <Eigen/QR>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <limits>
#include <unsupported/Eigen/FFT>

#include "isolab/core/errors.h"
#include "isolab/diagnosis/spectral.h"
#include "isolab/identification/fit.h"
#include "isolab/identification/least_squares.h"
#include "isolab/identification/parametrisation.h"

namespace isolab::building {
namespace {

// Each motion's measured values of the channels.
ChannelHistories Measured(const std::vector<BuildingMotion>& motions,
                          const std::vector<BuildingChannel>& channels) {
  ChannelHistories out;
  for (const BuildingMotion& motion : motions) {
    std::vector<Signal>& signals = out.emplace_back();
    for (const BuildingChannel& channel : channels) {
      const std::size_t l = std::size_t(channel.level - 1);
      signals.push_back(channel.kind == BuildingChannel::Kind::kDisplacement
                            ? motion.measured.displacement[l]
                            : motion.measured.acceleration[l]);
    }
  }
  return out;
}

// Keeps the part of a history inside [low, high] (1/time): FFT, bins outside zeroed, inverse.
// The length is padded to a power of two with zeros, and cut back after.
class Band {
 public:
  Band(std::optional<double> low, std::optional<double> high, double dt)
      : low_(low), high_(high), dt_(dt) {}
  bool active() const { return low_ || high_; }
  Signal operator()(const Signal& x) const {
    if (!active()) return x;
    std::size_t n = 1;
    while (n < x.size()) n *= 2;
    std::vector<double> padded(x);
    padded.resize(n, 0.0);
    Eigen::FFT<double> fft;
    std::vector<std::complex<double>> spectrum;
    fft.fwd(spectrum, padded);
    for (std::size_t k = 0; k < spectrum.size(); ++k) {
      const double f = double(std::min(k, n - k)) / (double(n) * dt_);
      if ((low_ && f < *low_) || (high_ && f > *high_)) spectrum[k] = 0.0;
    }
    std::vector<double> back;
    fft.inv(back, spectrum);
    back.resize(x.size());
    return back;
  }

 private:
  std::optional<double> low_, high_;
  double dt_;
};

double SumOfSquares(const Signal& x) {
  double sum = 0.0;
  for (const double v : x) sum += v * v;
  return sum;
}

// The search coordinates of the parameters and where each lies.
struct Coordinates {
  std::vector<std::string> names;
  std::vector<identification::CoordinateRange> ranges;

  std::vector<double> Values(std::span<const double> x) const {
    std::vector<double> values(x.size());
    for (std::size_t p = 0; p < x.size(); ++p) values[p] = ranges[p].At(x[p]);
    return values;
  }
};

std::size_t Length(const std::vector<Signal>& signals) {
  std::size_t n = 0;
  for (const Signal& x : signals) n += x.size();
  return n;
}

// The global stage: CMA-ES for options.global_budget simulations, leaving the rest to the
// least-squares refinement; none at 0. The default is half the budget, or one chunk of
// generations where half is less and the budget leaves ten refinement iterations beside it: a
// start can lie in the wrong basin of a story stiffness (a mode tuned to another part of the
// record), and least squares alone stays there.
identification::SearchOutcome GlobalStage(const identification::Objective& objective,
                                          const std::vector<double>& start,
                                          const identification::FitOptions& options,
                                          double value_at_start) {
  const long dimension = long(start.size());
  const long chunk = identification::FirstChunkEvaluations(int(dimension), options.islands);
  // The refinement needs a Jacobian and a step at least: the default leaves it that, a global
  // budget given that does not is refused.
  const long refinement = 2 * dimension + 2;
  const long budget =
      options.global_budget >= 0
          ? options.global_budget
          : std::min(std::max(options.budget / 2,
                              std::min(chunk, options.budget - 10 * (2 * dimension + 1))),
                     options.budget - refinement);
  if (budget > options.budget - refinement) {
    throw InvalidParameter({"global_budget", double(budget),
                            fmt::format("must leave the refinement at least {} of the budget of {} "
                                        "simulations",
                                        refinement, options.budget)});
  }
  if (budget < chunk) {
    identification::SearchOutcome none;
    none.point = start;
    none.value = value_at_start;
    none.stop_reason = budget == 0
                           ? "no global search (a global budget of 0)"
                           : fmt::format(
                                 "no global search (its budget of {} is less than one chunk of "
                                 "CMA-ES generations, {} simulations)",
                                 budget, chunk);
    return none;
  }
  identification::FitOptions global = options;
  global.budget = budget;
  global.polish_share = 0.0;
  identification::SearchOutcome outcome =
      identification::SearchUnitCube(objective, int(dimension), start, global, "mean NRMSE^2");
  // Said as the first stage of two: CMA-ES's own convergence is not the fit's.
  outcome.stop_reason = fmt::format(
      "global search: {} simulations of CMA-ES ({} generations{}), best mean NRMSE^2 {:.6g}",
      outcome.evaluations, outcome.generations,
      outcome.stop == identification::FitStop::kConverged ? ", its convergence stop met" : "",
      outcome.value);
  return outcome;
}

// The motions and channels checked against the model and the specification before any run.
std::vector<BuildingChannel> CheckedChannels(const model::ModelFile& model,
                                             const std::vector<BuildingMotion>& motions,
                                             const BuildingFitSpec& spec) {
  if (motions.empty()) throw InputError({model.path}, "no motions to fit");
  if (spec.parameters.empty()) throw InputError({model.path}, "no parameters to fit");
  const std::size_t levels = LevelMasses(model).size();
  std::vector<BuildingChannel> channels = FittedChannels(model, spec);
  for (const BuildingChannel& channel : channels) {
    if (std::size_t(channel.level) > levels) {
      throw InputError({model.path},
                       fmt::format("channel {}: the model has {} levels", channel.Name(), levels));
    }
  }
  for (const BuildingMotion& motion : motions) {
    if (motion.measured.time.size() < 2) {
      throw InputError({motion.name}, "needs at least two samples");
    }
    for (const BuildingChannel& channel : channels) {
      const std::vector<Signal>& kind = channel.kind == BuildingChannel::Kind::kDisplacement
                                            ? motion.measured.displacement
                                            : motion.measured.acceleration;
      const std::size_t l = std::size_t(channel.level - 1);
      if (l >= kind.size() || kind[l].size() != motion.measured.time.size()) {
        throw InputError({motion.name},
                         fmt::format("channel {} is not measured in this motion", channel.Name()));
      }
    }
  }
  if (spec.substeps < 1) {
    throw InputError({model.path}, fmt::format("substeps {}: expected >= 1", spec.substeps));
  }

  return channels;
}

// The fitted parameters' search coordinates, and the start in them (`start`).
// The spec's priors with their values: given, or the model's. Throws InputError for a name the
// model lacks (building_parameters.h), a fitted one, or a value not > 0.
std::vector<model::ParameterPrior> ResolvedPriors(const model::ModelFile& model,
                                                  const BuildingFitSpec& spec) {
  std::vector<model::ParameterPrior> priors;
  for (const PriorSpec& prior : spec.priors) {
    for (const FittedParameterSpec& fitted : spec.parameters) {
      if (fitted.name == prior.name) {
        throw InputError({model.path}, fmt::format("prior '{}': the parameter is also fitted; a "
                                                   "prior gives what the fit does not",
                                                   prior.name));
      }
    }
    const double value = prior.value ? *prior.value : analysis::ParameterValue(model, prior.name);
    if (!(value > 0.0)) {
      throw InputError({model.path}, fmt::format("prior '{}': its value {:g} must be > 0 (drawn "
                                                 "in ln p)",
                                                 prior.name, value));
    }
    priors.push_back({prior.name, value, prior.sigma, prior.source});
  }
  return priors;
}

Coordinates SearchCoordinates(const model::ModelFile& model, const BuildingFitSpec& spec,
                              std::vector<double>& start) {
  Coordinates coordinates;
  for (const FittedParameterSpec& parameter : spec.parameters) {
    const double value = parameter.start.value_or(analysis::ParameterValue(model, parameter.name));
    analysis::ParameterRange range = analysis::DefaultRange(parameter.name, value);
    if (parameter.low) range.low = *parameter.low;
    if (parameter.high) range.high = *parameter.high;
    range.log = range.low > 0.0;
    if (!(range.high > range.low)) {
      throw InputError({model.path}, fmt::format("parameter '{}': the range [{:g}, {:g}] is empty",
                                                 parameter.name, range.low, range.high));
    }
    coordinates.names.push_back(parameter.name);
    coordinates.ranges.push_back({range.low, range.high, range.log});
    start.push_back(coordinates.ranges.back().Inverse(value));
  }
  return coordinates;
}

// The weighted residual of a trial model against the measurements: per motion and channel
// band(simulated - measured) / |band(measured)|.
class BuildingResiduals {
 public:
  BuildingResiduals(const std::vector<BuildingMotion>& motions,
                    const std::vector<BuildingChannel>& channels, const BuildingFitSpec& spec)
      : motions_(motions), channels_(channels), spec_(spec) {
    const ChannelHistories measured_raw = Measured(motions, channels);
    for (const BuildingMotion& motion : motions) {
      bands_.emplace_back(spec.band_low, spec.band_high, SampleStep(motion.measured));
    }
    for (std::size_t m = 0; m < motions.size(); ++m) {
      std::vector<Signal>& filtered = measured_.emplace_back();
      for (std::size_t c = 0; c < measured_raw[m].size(); ++c) {
        filtered.push_back(bands_[m](measured_raw[m][c]));
        const double sum = SumOfSquares(filtered.back());
        if (!(sum > 0.0)) {
          throw InputError(
              {motions[m].name},
              fmt::format("channel {} is zero throughout{}: nothing to fit", channels_[c].Name(),
                          bands_[m].active() ? " in the band" : ""));
        }
        scale_.push_back(1.0 / sum);
      }
    }
  }

  std::vector<Signal> operator()(const model::ModelFile& trial) const {
    const ChannelHistories simulated =
        SimulateChannels(trial, motions_, channels_, spec_.sequential, spec_.pause, spec_.substeps);
    std::vector<Signal> out;
    std::size_t i = 0;
    for (std::size_t m = 0; m < motions_.size(); ++m) {
      for (std::size_t c = 0; c < channels_.size(); ++c, ++i) {
        Signal r = bands_[m](simulated[m][c]);
        const double weight = std::sqrt(scale_[i]);
        for (std::size_t k = 0; k < r.size(); ++k) r[k] = (r[k] - measured_[m][c][k]) * weight;
        out.push_back(std::move(r));
      }
    }
    return out;
  }
  // The objective: the mean over motions and channels of the squared NRMSE.
  double Objective(const std::vector<Signal>& r) const {
    double sum = 0.0;
    for (const Signal& x : r) sum += SumOfSquares(x);
    return sum / count();
  }
  double count() const { return double(scale_.size()); }

 private:
  const std::vector<BuildingMotion>& motions_;
  const std::vector<BuildingChannel>& channels_;
  const BuildingFitSpec& spec_;
  std::vector<Band> bands_;    // per motion, at its own sampling step
  ChannelHistories measured_;  // band-passed
  std::vector<double> scale_;  // per motion x channel: 1 / sum of squares of the measured
};

// The least-squares refinement from the global search's best (never worse than the start, which
// its first population holds), then from the specification's start where the search moved away
// from it: a short global search can end in a poorer basin than a good start lies in (the BNCS
// building from its diagnosed isolation), so the start is never lost. Sets the result's
// refinement, evaluations and stop reason.
void Refine(const identification::Residual& stacked, const std::vector<double>& start,
            const identification::FitOptions& options, double count, BuildingFitResult& result) {
  identification::RefinementOptions local;
  local.threads = options.threads;
  local.spread = options.spread;
  long spent = result.search.evaluations;
  if (options.progress) {
    local.progress = [&](const identification::RefinementProgress& p) {
      identification::FitProgress line{spent + p.evaluations, p.iteration, p.value / count, true};
      line.decrement = p.decrement;
      line.step = p.step;
      options.progress(line);
    };
  }
  std::vector<std::pair<std::string, identification::RefinementOutcome>> refined;
  for (const auto& [from, point] :
       {std::pair{std::string(result.search.evaluations > 0 ? "the global search's best"
                                                            : "the specification's start"),
                  result.search.point},
        std::pair{std::string("the specification's start"), start}}) {
    if (!refined.empty() && point == result.search.point) break;
    // An IPOP restart can take the global stage past its budget by a population; the first
    // refinement still gets a Jacobian and a step, the second only what is left.
    const long least = 2L * long(start.size()) + 2;
    local.budget = options.budget - spent;
    if (!refined.empty() && local.budget < least) break;
    local.budget = std::max(local.budget, least);
    refined.emplace_back(from, identification::RefineLeastSquares(stacked, point, local));
    spent += refined.back().second.evaluations;
  }
  const auto kept = std::min_element(
      refined.begin(), refined.end(),
      [](const auto& a, const auto& b) { return a.second.value < b.second.value; });
  result.refinement = kept->second;
  result.evaluations = spent;
  result.stop_reason = fmt::format(
      "{}; least squares from {}: {}", result.search.stop_reason, kept->first,
      identification::RefinementSummary(result.refinement, local, "mean NRMSE^2", 1.0 / count));
  for (const auto& [from, outcome] : refined) {
    if (&outcome == &kept->second) continue;
    result.stop_reason += fmt::format(" (from {}: {}, mean NRMSE^2 {:.6g} after {} simulations)",
                                      from, identification::RefinementStopName(outcome.stop),
                                      outcome.value / count, outcome.evaluations);
  }
}

// Samples and their worth: each channel's samples over its residual's correlation time.
void CountSamples(const std::vector<Signal>& r, const std::vector<BuildingMotion>& motions,
                  std::size_t channels, BuildingFitResult& result) {
  for (std::size_t c = 0; c < r.size(); ++c) {
    const double n = double(r[c].size());
    const double tau = diagnosis::IntegratedCorrelationTime(r[c]);
    result.samples += n;
    result.effective_samples += n / tau;
    result.correlation_time += n * tau * SampleStep(motions[c / channels].measured);
  }
  result.correlation_time /= result.samples;
}

// The parameters' covariance from the Jacobian in the unit coordinates (s^2 (J'J)^+, inflated by
// samples over effective samples), their correlations, and the pairs the data do not separate.
void Uncertainty(Eigen::MatrixXd jacobian, const Coordinates& coordinates, double count,
                 BuildingFitResult& result) {
  const int parameters = int(coordinates.names.size());
  for (int p = 0; p < parameters; ++p) {
    const identification::CoordinateRange& range = coordinates.ranges[std::size_t(p)];
    jacobian.col(p) /= range.log ? std::log(range.high / range.low) : range.high - range.low;
  }
  const Eigen::MatrixXd normal = jacobian.transpose() * jacobian;
  const double ssr = result.objective * count;
  const double s2 = ssr / std::max(result.samples - parameters, 1.0);
  const double inflation = result.samples / std::max(result.effective_samples, 1.0);
  // A pseudo-inverse: a direction the data do not see at all has no finite variance, and the
  // correlations still say which parameters it mixes.
  const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> decomposition(normal);
  result.covariance = decomposition.pseudoInverse() * (s2 * inflation);
  const Eigen::VectorXd sd = result.covariance.diagonal().cwiseMax(0.0).cwiseSqrt();
  result.correlation = result.covariance;
  for (int a = 0; a < parameters; ++a) {
    for (int b = 0; b < parameters; ++b) {
      const double d = sd[a] * sd[b];
      result.correlation(a, b) = d > 0.0 ? result.covariance(a, b) / d : (a == b ? 1.0 : 0.0);
    }
  }
  for (int a = 0; a < parameters; ++a) {
    for (int b = a + 1; b < parameters; ++b) {
      if (std::abs(result.correlation(a, b)) >= 0.95) {
        result.not_separated.push_back({coordinates.names[std::size_t(a)],
                                        coordinates.names[std::size_t(b)],
                                        result.correlation(a, b)});
      }
    }
  }
  std::sort(result.not_separated.begin(), result.not_separated.end(),
            [](const auto& x, const auto& y) {
              return std::abs(x.correlation) > std::abs(y.correlation);
            });
}

// The range the isolation was identified on: the slab's motion relative to the table over the
// motions fitted, as a cyclic-test fit reads its data.
identification::IdentifiedRange SlabRange(const std::vector<BuildingMotion>& motions) {
  std::vector<identification::CyclicTestData> slab;
  for (const BuildingMotion& motion : motions) {
    identification::CyclicTestData& test = slab.emplace_back();
    test.name = motion.name;
    test.time = motion.measured.time;
    test.displacement = motion.measured.displacement.front();
    test.force.assign(test.time.size(), 0.0);
    identification::Segment(&test);
  }
  return identification::RangeOf(identification::SelectCycles(std::move(slab), {}));
}

}  // namespace

std::vector<BuildingChannel> FittedChannels(const model::ModelFile& model,
                                            const BuildingFitSpec& spec) {
  if (!spec.channels.empty()) return spec.channels;
  std::vector<BuildingChannel> channels;
  const std::size_t levels = LevelMasses(model).size();
  for (const auto kind :
       {BuildingChannel::Kind::kDisplacement, BuildingChannel::Kind::kAcceleration}) {
    for (std::size_t l = 1; l <= levels; ++l) channels.push_back({kind, int(l)});
  }
  return channels;
}

BuildingFitResult FitBuilding(const model::ModelFile& model,
                              const std::vector<BuildingMotion>& motions,
                              const BuildingFitSpec& spec,
                              const identification::FitOptions& options) {
  options.Validate();
  const auto clock = std::chrono::steady_clock::now();
  const std::vector<BuildingChannel> channels = CheckedChannels(model, motions, spec);
  std::vector<double> start;
  const Coordinates coordinates = SearchCoordinates(model, spec, start);
  // The starting values must make a model that runs: a name the model lacks is an error here,
  // not an infinite objective in the search. The priors hold their values throughout.
  model::ModelFile base = model;
  const std::vector<model::ParameterPrior> priors = ResolvedPriors(model, spec);
  for (const model::ParameterPrior& prior : priors) {
    analysis::SetParameters(&base, std::span(&prior.name, 1), std::span(&prior.value, 1));
  }
  analysis::SetParameters(&base, coordinates.names, coordinates.Values(start));
  const BuildingResiduals residuals(motions, channels, spec);
  const double count = residuals.count();
  const auto model_at = [&](std::span<const double> x) {
    model::ModelFile trial = base;
    analysis::SetParameters(&trial, coordinates.names, coordinates.Values(x));
    return trial;
  };
  const identification::Objective objective = [&](std::span<const double> x) {
    try {
      return residuals.Objective(residuals(model_at(x)));
    } catch (const std::exception&) {
      // A point where a law's rules break or the run fails is no answer.
      return std::numeric_limits<double>::infinity();
    }
  };

  BuildingFitResult result;
  const std::vector<Signal> r_start = residuals(base);
  result.objective_start = residuals.Objective(r_start);
  result.search = GlobalStage(objective, start, options, result.objective_start);
  // The residual the refinement squares and sums: the objective's terms, so |r|^2 is count times
  // the objective.
  const identification::Residual stacked = [&](std::span<const double> x) {
    const std::vector<Signal> r = residuals(model_at(x));
    Eigen::VectorXd out(long(Length(r)));
    long row = 0;
    for (const Signal& channel : r) {
      for (const double v : channel) out[row++] = v;
    }
    return out;
  };
  Refine(stacked, start, options, count, result);
  const std::vector<double>& best = result.refinement.point;
  result.fitted = model_at(best);
  const std::vector<Signal> r = residuals(result.fitted);
  result.objective = residuals.Objective(r);

  // Each channel's NRMSE before and after.
  std::size_t i = 0;
  for (std::size_t m = 0; m < motions.size(); ++m) {
    for (const BuildingChannel& channel : channels) {
      result.channels.push_back({motions[m].name, channel.Name(),
                                 std::sqrt(SumOfSquares(r_start[i])),
                                 std::sqrt(SumOfSquares(r[i]))});
      ++i;
    }
  }
  CountSamples(r, motions, channels.size(), result);

  // The Jacobian of the stacked residual in the coordinates (ln p or p): the refinement's last,
  // where it was taken at the fitted point, else by the same central differences there.
  Eigen::MatrixXd jacobian = std::move(result.refinement.jacobian);
  if (!result.refinement.jacobian_current) {
    jacobian =
        identification::DifferenceJacobian(stacked, best, stacked(best),
                                           identification::RefinementOptions{}.difference_step,
                                           options.threads, options.spread)
            .jacobian;
  }
  Uncertainty(std::move(jacobian), coordinates, count, result);

  const std::vector<double> values = coordinates.Values(best);
  const std::vector<double> starts = coordinates.Values(start);
  const Eigen::VectorXd sd = result.covariance.diagonal().cwiseMax(0.0).cwiseSqrt();
  for (std::size_t q = 0; q < best.size(); ++q) {
    const identification::CoordinateRange& range = coordinates.ranges[q];
    result.parameters.push_back({coordinates.names[q], starts[q], values[q], range.low, range.high,
                                 range.log, sd[long(q)], best[q] < 1e-3 || best[q] > 1.0 - 1e-3});
  }
  result.fitted.identified_range = SlabRange(motions);
  model::ParameterUncertainty& uncertainty = result.fitted.uncertainty.emplace();
  uncertainty.names = coordinates.names;
  uncertainty.values = values;
  for (const auto& range : coordinates.ranges) uncertainty.log.push_back(range.log);
  uncertainty.covariance = result.covariance;
  uncertainty.priors = priors;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock).count();
  return result;
}

}  // namespace isolab::building
