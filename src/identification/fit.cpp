#include "isolab/identification/fit.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <pagmo/algorithm.hpp>
#include <pagmo/algorithms/cmaes.hpp>
#include <pagmo/algorithms/compass_search.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>
#include <stdexcept>
#include <string>
#include <thread>

#include "isolab/core/errors.h"
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
  std::vector<Eigen::MatrixXd> bases;
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
  return {a, std::max(error, 0.0)};
}

namespace {

// The pagmo user-defined problem: e^2 on the unit cube. Holds only immutable shared data, so
// copies in parallel islands evaluate independently.
struct FitProblem {
  std::shared_ptr<const ModelParametrisation> model;
  std::shared_ptr<const FitData> data;
  int threads = 1;  // sharing each evaluation's laws (Basis)

  pagmo::vector_double fitness(const pagmo::vector_double& x) const {
    const double e2 = SolveAmplitudes(*model, x, *data, threads).error;
    return {std::isfinite(e2) ? e2 : kNotFinite};
  }
  std::pair<pagmo::vector_double, pagmo::vector_double> get_bounds() const {
    return {pagmo::vector_double(model->dimension(), 0.0),
            pagmo::vector_double(model->dimension(), 1.0)};
  }
  pagmo::thread_safety get_thread_safety() const { return pagmo::thread_safety::constant; }
  std::string get_name() const { return "isolab cyclic-test fit"; }

  static constexpr double kNotFinite = 1e300;
};

constexpr int kGenerationsPerChunk = 20;
constexpr double kSettledE2 = 1e-12;

unsigned IslandSeed(unsigned seed, int island, int restart) {
  return seed * 2654435761u + 7919u * static_cast<unsigned>(island) +
         104729u * static_cast<unsigned>(restart);
}

pagmo::algorithm Cmaes(unsigned seed) {
  // sigma0 0.3 of the unit cube; tolerances tight enough for parameter recovery; memory keeps
  // the adapted covariance between chunks; bounds enforced by clipping.
  return pagmo::algorithm{
      pagmo::cmaes(kGenerationsPerChunk, -1, -1, -1, -1, 0.3, 1e-14, 1e-10, true, true, seed)};
}

// The spread of a population in the unit cube: the largest standard deviation of a coordinate.
// CMA-ES's population spreads about its mean by its step size, so this is the step size in
// coordinates a reader can compare with the cube.
double Spread(const pagmo::population& population) {
  const auto& xs = population.get_x();
  if (xs.size() < 2) return 0.0;
  double spread = 0.0;
  for (std::size_t d = 0; d < xs.front().size(); ++d) {
    double sum = 0.0, square = 0.0;
    for (const auto& x : xs) sum += x[d], square += x[d] * x[d];
    const double n = static_cast<double>(xs.size());
    spread = std::max(spread, std::sqrt(std::max(square / n - (sum / n) * (sum / n), 0.0)));
  }
  return spread;
}

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

void FitOptions::Validate() const {
  if (budget < 100) throw InvalidParameter({"budget", double(budget), "must be >= 100"});
  if (islands < 1 || islands > 64) {
    throw InvalidParameter({"islands", double(islands), "must be in [1, 64]"});
  }
  if (threads < 0 || threads > 1024) {
    throw InvalidParameter({"threads", double(threads),
                            "must be 0 (every hardware thread) or "
                            "in [1, 1024]"});
  }
  if (!(polish_share >= 0.0 && polish_share < 1.0)) {
    throw InvalidParameter({"polish_share", polish_share, "must be in [0, 1)"});
  }
  if (stop_window < 0) {
    throw InvalidParameter({"stop_window", double(stop_window), "must be >= 0 evaluations"});
  }
  if (!(stop_window_share >= 0.0 && stop_window_share <= 1.0)) {
    throw InvalidParameter({"stop_window_share", stop_window_share, "must be in [0, 1]"});
  }
  if (!(stop_e2 >= 0.0 && stop_e2 < 1.0)) {
    throw InvalidParameter({"stop_e2", stop_e2, "must be in [0, 1)"});
  }
  if (!(stop_step >= 0.0 && stop_step <= 1.0)) {
    throw InvalidParameter({"stop_step", stop_step, "must be in [0, 1]"});
  }
}

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
  const int dimension = model.dimension();
  const int threads = ThreadCount(options.threads);
  const auto finish = [&](FitResult result, const pagmo::vector_double& x) {
    const AmplitudeSolution solution = SolveAmplitudes(model, x, data, threads);
    if (!solution.amplitudes.allFinite() || !std::isfinite(solution.error)) {
      throw std::invalid_argument(
          "no parameters give a finite e^2 on these data: their sums of squares overflow or are "
          "not numbers (forces and displacements must be below about 1e150 in magnitude)");
    }
    result.point = x;
    result.amplitudes = solution.amplitudes;
    result.mathematical = model.Mathematical(x, result.amplitudes);
    result.error = ComputeFitError(model.Assembly(x, result.amplitudes), data);
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
  };
  if (dimension == 0) {  // only linear amplitudes (springs, dashpots): one solve is the fit
    FitResult result;
    result.evaluations = 1;
    result.stop = FitStop::kConverged;
    result.stop_reason = "the model has no shape coordinates: one linear solve is the fit";
    return finish(std::move(result), {});
  }
  const int islands = options.islands;
  // Threads beyond one per island share each evaluation; below some work per evaluation the
  // threads would cost more to start than they save.
  const bool large = FittedSamples(data) * std::max(1L, LawRuns(model)) >= 200000;
  const int evaluation_threads = large ? std::max(1, threads / islands) : 1;
  // Population of CMA-ES's default 4 + 3 ln D, doubled for the multimodal landscapes of
  // parallel hysteretic components.
  const int population_size = 2 * (4 + static_cast<int>(3.0 * std::log(dimension)));
  const pagmo::problem problem{FitProblem{std::make_shared<const ModelParametrisation>(model),
                                          std::make_shared<const FitData>(data),
                                          evaluation_threads}};

  const long cmaes_budget = static_cast<long>(options.budget * (1.0 - options.polish_share));
  // Per island: its algorithm and population, IPOP restarts (a fresh random population, twice
  // as large, when the island has stagnated), and the best point it has found across restarts.
  struct Island {
    pagmo::algorithm algorithm;
    pagmo::population population;
    int restarts = 0;
    int population_size = 0;
    int chunks_without_progress = 0;
    double best_f = INFINITY;
    pagmo::vector_double best_x;
    double best_step = 1.0;  // the population's spread when it found best_x
  };
  std::vector<Island> archipelago;
  for (int i = 0; i < islands; ++i) {
    pagmo::population population{problem,
                                 static_cast<pagmo::population::size_type>(population_size),
                                 IslandSeed(options.seed, i, 1000)};
    if (i == 0) population.set_x(0, model.StartPoint());  // the given (or middle) start
    Island island{Cmaes(IslandSeed(options.seed, i, 0)),
                  std::move(population),
                  0,
                  population_size,
                  0,
                  INFINITY,
                  {},
                  1.0};
    archipelago.push_back(std::move(island));
  }
  long retired = 0;  // evaluations of populations replaced at restarts
  const auto evaluations_so_far = [&] {
    long sum = retired;
    for (const Island& island : archipelago) {
      sum += static_cast<long>(island.population.get_problem().get_fevals());
    }
    return sum;
  };
  const auto chunk_cost = [&] {
    long cost = 0;
    for (const Island& island : archipelago) cost += island.population_size * kGenerationsPerChunk;
    return cost;
  };
  // The best e^2 after each chunk, for the convergence stop's window.
  std::vector<std::pair<long, double>> history;
  FitResult result;
  int generation = 0;
  while (evaluations_so_far() + chunk_cost() <= cmaes_budget) {
    // Islands share nothing, so running them on any number of threads gives the same result.
    ParallelFor(archipelago.size(), std::min(threads, islands), [&](std::size_t i) {
      archipelago[i].population = archipelago[i].algorithm.evolve(archipelago[i].population);
    });
    generation += kGenerationsPerChunk;
    for (int i = 0; i < islands; ++i) {
      Island& island = archipelago[static_cast<std::size_t>(i)];
      const double f = island.population.champion_f()[0];
      if (f < island.best_f * (1.0 - 1e-6)) {
        island.best_f = f;
        island.best_x = island.population.champion_x();
        island.best_step = Spread(island.population);
        island.chunks_without_progress = 0;
      } else if (++island.chunks_without_progress >= 5) {
        // Stagnated for 100 generations: restart from new random points with a larger
        // population (IPOP-CMA-ES), which explores more widely each time.
        ++island.restarts;
        island.population_size = std::min(2 * island.population_size, 16 * population_size);
        island.chunks_without_progress = 0;
        retired += static_cast<long>(island.population.get_problem().get_fevals());
        if (f < island.best_f) {
          island.best_f = f;
          island.best_x = island.population.champion_x();
          island.best_step = Spread(island.population);
        }
        island.algorithm = Cmaes(IslandSeed(options.seed, i, island.restarts));
        island.population = pagmo::population{
            problem, static_cast<pagmo::population::size_type>(island.population_size),
            IslandSeed(options.seed, i, 1000 + island.restarts)};
      }
    }
    const auto leader =
        std::min_element(archipelago.begin(), archipelago.end(),
                         [](const Island& a, const Island& b) { return a.best_f < b.best_f; });
    const double best = leader->best_f;
    const long evaluations = evaluations_so_far();
    history.emplace_back(evaluations, best);
    if (options.progress) options.progress({evaluations, generation, best, false});
    const long window = std::max(
        options.stop_window, static_cast<long>(options.stop_window_share * double(evaluations)));
    if (options.stop_window > 0 && evaluations - history.front().first >= window) {
      // The best as it stood a window ago (the latest record at least a window back).
      double then = history.front().second;
      for (const auto& [at, value] : history) {
        if (evaluations - at >= window) then = value;
      }
      const double step = leader->best_step;
      // An e^2 at the round-off of the normal equations (1e-12: an RMS error of 1e-6 of the
      // force) counts as settled however its last digits move.
      if (then - best <= options.stop_e2 * then + kSettledE2 && step <= options.stop_step) {
        result.stop = FitStop::kConverged;
        result.stop_reason = fmt::format(
            "converged after {} evaluations: over the last {} the best e^2 ({:.6g} %) improved "
            "by less than {:g} relative and the step size is {:.2g} (below {:g}) in the unit "
            "cube of shape coordinates",
            evaluations, window, 100 * best, options.stop_e2, step, options.stop_step);
        break;
      }
    }
  }

  // The best point over islands and restarts, then a compass-search polish from it.
  pagmo::vector_double best_x = model.StartPoint();
  double best_f = INFINITY;
  for (const Island& island : archipelago) {
    if (island.population.champion_f()[0] < best_f) {
      best_f = island.population.champion_f()[0];
      best_x = island.population.champion_x();
    }
    if (island.best_f < best_f) {
      best_f = island.best_f;
      best_x = island.best_x;
    }
  }
  long evaluations = evaluations_so_far();
  // The polish gets what CMA-ES left of the budget, or, after the convergence stop, its own
  // share. Compass search may overrun its count by one poll of the 2 D points around the current
  // one, and the population it starts from costs one more: both are left out of what it is given,
  // so the evaluations never exceed the budget.
  const long remaining = options.budget - evaluations;
  const long polish_budget =
      (result.stop == FitStop::kConverged ? std::min(remaining, options.budget - cmaes_budget)
                                          : remaining) -
      2 * dimension - 1;
  if (polish_budget > 2 * dimension) {
    pagmo::population single{problem, 0u, options.seed};
    single.push_back(best_x);
    pagmo::algorithm compass{
        pagmo::compass_search(static_cast<unsigned>(polish_budget), 0.02, 1e-9, 0.5)};
    if (options.progress) options.progress({evaluations, generation, single.champion_f()[0], true});
    single = compass.evolve(single);
    evaluations += static_cast<long>(single.get_problem().get_fevals());
    // Compass search keeps its best point: never worse than where it started.
    if (single.champion_f()[0] <= best_f) best_x = single.champion_x();
  }
  if (result.stop != FitStop::kConverged) {
    result.stop = FitStop::kBudget;
    result.stop_reason = fmt::format("the budget of {} evaluations was spent", options.budget);
  }
  result.evaluations = evaluations;
  for (const Island& island : archipelago) result.restarts += island.restarts;
  result = finish(std::move(result), best_x);
  if (options.progress) options.progress({evaluations, generation, result.error.total, true});
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
