#include "isolab/identification/fit.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "isolab/core/errors.h"
#include "isolab/core/hardware_threads.h"
#include "parallel_for.h"

namespace isolab::identification {

FitData SelectCycles(std::vector<CyclicTestData> tests, const std::vector<int>& cycles,
                     bool one_specimen) {
  FitData data;
  data.one_specimen = one_specimen;
  for (const CyclicTestData& test : tests) {
    std::vector<CycleSpan> spans;
    if (cycles.empty()) {
      spans.push_back({0, test.displacement.size()});
    } else {
      for (const int c : cycles) {
        if (c < 1 || c > static_cast<int>(test.cycles.size())) {
          throw std::invalid_argument("test '" + test.name + "' has " +
                                      std::to_string(test.cycles.size()) + " cycles, no cycle " +
                                      std::to_string(c));
        }
        spans.push_back(test.cycles[c - 1]);
      }
    }
    if (spans.empty()) {
      throw std::invalid_argument("test '" + test.name + "' has no cycle to fit");
    }
    data.fitted.push_back(std::move(spans));
  }
  data.tests = std::move(tests);
  return data;
}

DataScales ScalesOf(const FitData& data) {
  DataScales scales{0.0, 0.0, 0.0};
  for (const CyclicTestData& test : data.tests) {
    for (std::size_t k = 0; k < test.time.size(); ++k) {
      scales.displacement = std::max(scales.displacement, std::abs(test.displacement[k]));
      scales.force = std::max(scales.force, std::abs(test.force[k]));
      if (k > 0 && test.time[k] > test.time[k - 1]) {
        scales.velocity =
            std::max(scales.velocity, std::abs(test.displacement[k] - test.displacement[k - 1]) /
                                          (test.time[k] - test.time[k - 1]));
      }
    }
  }
  for (double* scale : {&scales.displacement, &scales.force, &scales.velocity}) {
    if (!(*scale > 0.0)) *scale = 1.0;
  }
  return scales;
}

IdentifiedRange RangeOf(const FitData& data) {
  IdentifiedRange range;
  long reversals = 0;
  for (std::size_t i = 0; i < data.tests.size(); ++i) {
    const CyclicTestData& test = data.tests[i];
    range.data.push_back(test.name);
    const auto fitted = [&](std::size_t k) {
      return std::any_of(data.fitted[i].begin(), data.fitted[i].end(),
                         [k](const CycleSpan& span) { return k >= span.begin && k < span.end; });
    };
    for (const CycleSpan& span : data.fitted[i]) {
      for (std::size_t k = span.begin; k < span.end; ++k) {
        range.displacement = std::max(range.displacement, std::abs(test.displacement[k]));
        if (k > 0 && test.time[k] > test.time[k - 1]) {
          range.velocity =
              std::max(range.velocity, std::abs(test.displacement[k] - test.displacement[k - 1]) /
                                           (test.time[k] - test.time[k - 1]));
        }
      }
    }
    // Every half-cycle starts at a reversal, and the last one also ends at one.
    for (const CycleSpan& half : test.half_cycles) reversals += fitted(half.begin) ? 1 : 0;
    if (!test.half_cycles.empty() && fitted(test.half_cycles.back().end - 1)) ++reversals;
  }
  range.cycles = 0.5 * static_cast<double>(reversals);
  return range;
}

FitError ComputeFitError(const hysteresis::ParallelAssembly& assembly, const FitData& data) {
  FitError error;
  const auto forces = SimulateForces(assembly, data.tests, data.one_specimen);
  for (std::size_t i = 0; i < data.tests.size(); ++i) {
    const CyclicTestData& test = data.tests[i];
    const std::vector<double>& force = forces[i];
    double misfit = 0.0, norm = 0.0;
    for (const CycleSpan& span : data.fitted[i]) {
      for (std::size_t k = span.begin; k < span.end; ++k) {
        const double difference = test.force[k] - force[k];
        misfit += difference * difference;
        norm += test.force[k] * test.force[k];
      }
    }
    error.per_test.push_back(norm > 0.0 ? misfit / norm : misfit);
    error.total += error.per_test.back();
  }
  return error;
}

AmplitudeSolution SolveAmplitudes(const ModelParametrisation& model, std::span<const double> x,
                                  const FitData& data, int threads) {
  // Normal equations of the weighted problem sum_i w_i |F0_i - B_i a|^2, w_i = 1 / |F0_i|^2.
  const int m = model.amplitude_count();
  Eigen::MatrixXd normal = Eigen::MatrixXd::Zero(m, m);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m);
  double constant = 0.0;
  // The search calls this tens of thousands of times, from its threads, for bases of the same
  // size: fresh ones each time cost more than the rest of an evaluation (the kernel's zeroed
  // pages, then cold stores), so each thread keeps its own (Basis resizes it in place), up to
  // kKeptBasisBytes: beyond that a thread would hold too much memory once its fit is over.
  constexpr std::size_t kKeptBasisBytes = std::size_t{32} << 20;
  thread_local std::vector<Eigen::MatrixXd> bases;
  model.Basis(x, data.tests, data.one_specimen, &bases, threads);
  for (std::size_t i = 0; i < data.tests.size(); ++i) {
    const CyclicTestData& test = data.tests[i];
    const Eigen::MatrixXd& basis = bases[i];
    const Eigen::Map<const Eigen::VectorXd> measured(test.force.data(),
                                                     static_cast<Eigen::Index>(test.force.size()));
    double norm = 0.0;
    for (const CycleSpan& span : data.fitted[i]) {
      norm += measured.segment(span.begin, span.end - span.begin).squaredNorm();
    }
    const double weight = norm > 0.0 ? 1.0 / norm : 1.0;
    for (const CycleSpan& span : data.fitted[i]) {
      const Eigen::Index begin = static_cast<Eigen::Index>(span.begin);
      const Eigen::Index rows = static_cast<Eigen::Index>(span.end - span.begin);
      const auto b = basis.middleRows(begin, rows);
      normal.noalias() += weight * b.transpose() * b;
      rhs.noalias() += weight * b.transpose() * measured.segment(begin, rows);
    }
    constant += weight * norm;
  }
  // Active set on the sign-constrained amplitudes (Lawson & Hanson 1974, simplified): solve on
  // the passive set, drop the most negative, add back the one whose gradient asks most.
  const std::vector<bool>& nonnegative = model.nonnegative();
  std::vector<bool> passive(m, true);
  Eigen::VectorXd a = Eigen::VectorXd::Zero(m);
  const double ridge = 1e-13 * std::max(normal.diagonal().maxCoeff(), 1e-300);
  for (int iteration = 0; iteration < 4 * m + 4; ++iteration) {
    std::vector<int> index;
    for (int k = 0; k < m; ++k) {
      if (passive[k]) index.push_back(k);
    }
    const int n = static_cast<int>(index.size());
    Eigen::MatrixXd reduced(n, n);
    Eigen::VectorXd reduced_rhs(n);
    for (int r = 0; r < n; ++r) {
      reduced_rhs[r] = rhs[index[r]];
      for (int c = 0; c < n; ++c) reduced(r, c) = normal(index[r], index[c]);
      reduced(r, r) += ridge;
    }
    const Eigen::VectorXd solved = reduced.ldlt().solve(reduced_rhs);
    a.setZero();
    int worst = -1;
    for (int r = 0; r < n; ++r) {
      a[index[r]] = solved[r];
      if (nonnegative[index[r]] && solved[r] < 0.0 && (worst < 0 || solved[r] < a[worst])) {
        worst = index[r];
      }
    }
    if (worst >= 0) {
      passive[worst] = false;
      a[worst] = 0.0;
      continue;
    }
    const Eigen::VectorXd descent = rhs - normal * a;
    int best = -1;
    for (int k = 0; k < m; ++k) {
      if (!passive[k] && descent[k] > 1e-12 * std::abs(rhs[k]) + 1e-300 &&
          (best < 0 || descent[k] > descent[best])) {
        best = k;
      }
    }
    if (best < 0) break;
    passive[best] = true;
  }
  const double error = constant - 2.0 * a.dot(rhs) + a.dot(normal * a);
  std::size_t basis_bytes = 0;
  for (const Eigen::MatrixXd& basis : bases) basis_bytes += sizeof(double) * basis.size();
  if (basis_bytes > kKeptBasisBytes) bases.clear();
  return {a, std::max(error, 0.0)};
}

namespace {

// Columns of laws that the fit runs through the data at every evaluation, a measure of its cost.
long LawRuns(const ModelParametrisation& model) {
  long runs = 0;
  for (const ComponentSpec& spec : model.components()) {
    switch (spec.type) {
      case hysteresis::LawType::kLinearSpring:
      case hysteresis::LawType::kDashpot:
      case hysteresis::LawType::kTrilinearElastic:
        break;
      case hysteresis::LawType::kDegradingBhm2:
        runs += 2;
        break;
      default:
        runs += 1;
    }
  }
  return runs;
}

}  // namespace

long FittedSamples(const FitData& data) {
  long samples = 0;
  for (const auto& spans : data.fitted) {
    for (const CycleSpan& span : spans) samples += static_cast<long>(span.end - span.begin);
  }
  return samples;
}

FitResult Fit(const ModelParametrisation& model, const FitData& data, const FitOptions& options) {
  options.Validate();
  const auto start = std::chrono::steady_clock::now();
  const int threads = ThreadsOrHardware(options.threads);
  // Threads beyond one per island this process runs share each evaluation; below some work per
  // evaluation the threads would cost more to start than they save.
  const bool large = FittedSamples(data) * std::max(1L, LawRuns(model)) >= 200000;
  const std::size_t islands_here = options.spread
                                       ? OwnedTasks(std::size_t(options.islands),
                                                    options.spread->Rank(), options.spread->Ranks())
                                       : std::size_t(options.islands);
  const int evaluation_threads = large ? std::max(1, threads / std::max(1, int(islands_here))) : 1;
  FitResult result;
  int generations = 0;
  std::vector<double> best = model.StartPoint();
  if (model.dimension() == 0) {  // only linear amplitudes (springs, dashpots): one solve is the fit
    result.evaluations = 1;
    result.stop = FitStop::kConverged;
    result.stop_reason = "the model has no shape coordinates: one linear solve is the fit";
  } else {
    const SearchOutcome outcome = SearchUnitCube(
        [&](std::span<const double> x) {
          return SolveAmplitudes(model, x, data, evaluation_threads).error;
        },
        model.dimension(), best, options, "e^2");
    best = outcome.point;
    result.evaluations = outcome.evaluations;
    result.restarts = outcome.restarts;
    generations = outcome.generations;
    result.stop = outcome.stop;
    result.stop_reason = outcome.stop_reason;
  }
  const AmplitudeSolution solution = SolveAmplitudes(model, best, data, threads);
  if (!solution.amplitudes.allFinite() || !std::isfinite(solution.error)) {
    throw std::invalid_argument(
        "no parameters give a finite e^2 on these data: their sums of squares overflow or are "
        "not numbers (forces and displacements must be below about 1e150 in magnitude)");
  }
  result.point = best;
  result.amplitudes = solution.amplitudes;
  result.mathematical = model.Mathematical(best, result.amplitudes);
  result.error = ComputeFitError(model.Assembly(best, result.amplitudes), data);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (options.progress && model.dimension() > 0) {
    options.progress({result.evaluations, generations, result.error.total, true});
  }
  return result;
}

std::vector<std::size_t> ZeroComponents(const ModelParametrisation& model,
                                        const Eigen::VectorXd& amplitudes) {
  std::vector<std::size_t> zero;
  for (std::size_t c = 0; c < model.components().size(); ++c) {
    bool all_zero = true;
    for (int k = model.first_amplitude(c); k < model.first_amplitude(c + 1); ++k) {
      all_zero = all_zero && amplitudes[k] == 0.0;
    }
    if (all_zero) zero.push_back(c);
  }
  return zero;
}

std::vector<ComponentSpec> DropComponents(const ModelParametrisation& model,
                                          const std::vector<std::size_t>& drop, FitResult* fit) {
  const auto dropped = [&](std::size_t c) {
    return std::find(drop.begin(), drop.end(), c) != drop.end();
  };
  std::vector<ComponentSpec> kept;
  std::vector<std::vector<double>> mathematical;
  for (std::size_t c = 0; c < model.components().size(); ++c) {
    if (dropped(c)) continue;
    kept.push_back(model.components()[c]);
    mathematical.push_back(fit->mathematical[c]);
  }
  std::vector<double> point;
  for (int k = 0; k < model.dimension(); ++k) {
    if (!dropped(static_cast<std::size_t>(model.free_component(k)))) point.push_back(fit->point[k]);
  }
  std::vector<double> amplitudes;
  for (std::size_t c = 0; c < model.components().size(); ++c) {
    if (dropped(c)) continue;
    for (int k = model.first_amplitude(c); k < model.first_amplitude(c + 1); ++k) {
      amplitudes.push_back(fit->amplitudes[k]);
    }
  }
  fit->point = std::move(point);
  fit->amplitudes = Eigen::Map<const Eigen::VectorXd>(amplitudes.data(),
                                                      static_cast<Eigen::Index>(amplitudes.size()));
  fit->mathematical = std::move(mathematical);
  return kept;
}

}  // namespace isolab::identification
