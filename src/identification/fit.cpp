#include "isolab/identification/fit.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <pagmo/algorithm.hpp>
#include <pagmo/algorithms/cmaes.hpp>
#include <pagmo/algorithms/compass_search.hpp>
#include <pagmo/archipelago.hpp>
#include <pagmo/islands/thread_island.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>
#include <stdexcept>
#include <string>
#include <thread>

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
                                  const FitData& data) {
  // Normal equations of the weighted problem sum_i w_i |F0_i - B_i a|^2, w_i = 1 / |F0_i|^2.
  const int m = model.amplitude_count();
  Eigen::MatrixXd normal = Eigen::MatrixXd::Zero(m, m);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m);
  double constant = 0.0;
  std::vector<Eigen::MatrixXd> bases;
  model.Basis(x, data.tests, data.one_specimen, &bases);
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

  pagmo::vector_double fitness(const pagmo::vector_double& x) const {
    const double e2 = SolveAmplitudes(*model, x, *data).error;
    return {std::isfinite(e2) ? e2 : 1e300};
  }
  std::pair<pagmo::vector_double, pagmo::vector_double> get_bounds() const {
    return {pagmo::vector_double(model->dimension(), 0.0),
            pagmo::vector_double(model->dimension(), 1.0)};
  }
  pagmo::thread_safety get_thread_safety() const { return pagmo::thread_safety::constant; }
  std::string get_name() const { return "isolab cyclic-test fit"; }
};

constexpr int kGenerationsPerChunk = 20;

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

}  // namespace

FitResult Fit(const ModelParametrisation& model, const FitData& data, const FitOptions& options) {
  if (options.budget < 100) throw std::invalid_argument("the budget must be >= 100 evaluations");
  if (!(options.polish_share >= 0.0 && options.polish_share < 1.0)) {
    throw std::invalid_argument("the polish share must be in [0, 1)");
  }
  const auto start = std::chrono::steady_clock::now();
  const int dimension = model.dimension();
  if (dimension == 0) {  // only linear amplitudes (springs, dashpots): one solve is the fit
    FitResult result;
    result.amplitudes = SolveAmplitudes(model, {}, data).amplitudes;
    result.mathematical = model.Mathematical({}, result.amplitudes);
    result.error = ComputeFitError(model.Assembly({}, result.amplitudes), data);
    result.evaluations = 1;
    return result;
  }
  const int islands = options.islands > 0
                          ? options.islands
                          : std::max(2, static_cast<int>(std::thread::hardware_concurrency()));
  // Population of CMA-ES's default 4 + 3 ln D, doubled for the multimodal landscapes of
  // parallel hysteretic components.
  const int population_size = 2 * (4 + static_cast<int>(3.0 * std::log(dimension)));
  const pagmo::problem problem{FitProblem{std::make_shared<const ModelParametrisation>(model),
                                          std::make_shared<const FitData>(data)}};

  const long cmaes_budget = static_cast<long>(options.budget * (1.0 - options.polish_share));
  // Per island: IPOP restarts (a fresh random population, twice as large, when the island has
  // stagnated), and the best point it has found across its restarts.
  struct IslandState {
    int restarts = 0;
    int population = 0;
    int chunks_without_progress = 0;
    double best_f = INFINITY;
    pagmo::vector_double best_x;
  };
  std::vector<IslandState> states(islands);
  pagmo::archipelago archipelago;
  for (int i = 0; i < islands; ++i) {
    states[i].population = population_size;
    pagmo::population population{problem,
                                 static_cast<pagmo::population::size_type>(population_size),
                                 IslandSeed(options.seed, i, 1000)};
    if (i == 0) population.set_x(0, model.StartPoint());  // the given (or middle) start
    archipelago.push_back(pagmo::thread_island{}, Cmaes(IslandSeed(options.seed, i, 0)),
                          std::move(population));
  }
  long retired = 0;  // evaluations of populations replaced at restarts
  const auto evaluations_so_far = [&] {
    long sum = retired;
    for (const auto& island : archipelago) {
      sum += static_cast<long>(island.get_population().get_problem().get_fevals());
    }
    return sum;
  };
  const auto chunk_cost = [&] {
    long cost = 0;
    for (const IslandState& state : states) cost += state.population * kGenerationsPerChunk;
    return cost;
  };
  int generation = 0;
  while (evaluations_so_far() + chunk_cost() <= cmaes_budget) {
    archipelago.evolve();
    archipelago.wait_check();
    generation += kGenerationsPerChunk;
    for (int i = 0; i < islands; ++i) {
      auto& island = archipelago[static_cast<std::size_t>(i)];
      IslandState& state = states[i];
      const pagmo::population population = island.get_population();
      const double f = population.champion_f()[0];
      if (f < state.best_f * (1.0 - 1e-6)) {
        state.best_f = f;
        state.best_x = population.champion_x();
        state.chunks_without_progress = 0;
      } else if (++state.chunks_without_progress >= 5) {
        // Stagnated for 100 generations: restart from new random points with a larger
        // population (IPOP-CMA-ES), which explores more widely each time.
        ++state.restarts;
        state.population = std::min(2 * state.population, 16 * population_size);
        state.chunks_without_progress = 0;
        retired += static_cast<long>(population.get_problem().get_fevals());
        island.set_algorithm(Cmaes(IslandSeed(options.seed, i, state.restarts)));
        island.set_population(
            pagmo::population{problem, static_cast<pagmo::population::size_type>(state.population),
                              IslandSeed(options.seed, i, 1000 + state.restarts)});
        state.best_f = std::min(state.best_f, f);
      }
    }
    if (options.progress) {
      double best = INFINITY;
      for (const IslandState& state : states) best = std::min(best, state.best_f);
      options.progress({evaluations_so_far(), generation, best, false});
    }
  }

  // The best point over islands and restarts, then a compass-search polish from it.
  pagmo::vector_double best_x = model.StartPoint();
  double best_f = INFINITY;
  for (int i = 0; i < islands; ++i) {
    const pagmo::population population = archipelago[static_cast<std::size_t>(i)].get_population();
    if (population.champion_f()[0] < best_f) {
      best_f = population.champion_f()[0];
      best_x = population.champion_x();
    }
    if (states[i].best_f < best_f) {
      best_f = states[i].best_f;
      best_x = states[i].best_x;
    }
  }
  long evaluations = evaluations_so_far();
  const long polish_budget = options.budget - evaluations;
  if (polish_budget > 2 * dimension) {
    pagmo::population single{problem, 0u, options.seed};
    single.push_back(best_x);
    pagmo::algorithm compass{
        pagmo::compass_search(static_cast<unsigned>(polish_budget), 0.02, 1e-9, 0.5)};
    if (options.progress) options.progress({evaluations, generation, single.champion_f()[0], true});
    single = compass.evolve(single);
    evaluations += static_cast<long>(single.get_problem().get_fevals()) - 1;
    best_x = single.champion_x();
  }

  FitResult result;
  result.point = best_x;
  result.amplitudes = SolveAmplitudes(model, best_x, data).amplitudes;
  result.mathematical = model.Mathematical(best_x, result.amplitudes);
  result.error = ComputeFitError(model.Assembly(best_x, result.amplitudes), data);
  result.evaluations = evaluations;
  for (const IslandState& state : states) result.restarts += state.restarts;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (options.progress) options.progress({evaluations, generation, result.error.total, true});
  return result;
}

}  // namespace isolab::identification
