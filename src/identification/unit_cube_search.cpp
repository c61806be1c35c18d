#include "isolab/identification/unit_cube_search.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <pagmo/algorithm.hpp>
#include <pagmo/algorithms/cmaes.hpp>
#include <pagmo/algorithms/compass_search.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>
#include <string>

#include "isolab/core/errors.h"
#include "isolab/core/hardware_threads.h"
#include "spread_for.h"

namespace isolab::identification {
namespace {

// The pagmo user-defined problem: the objective on the unit cube. Holds only immutable shared
// data, so copies in parallel islands evaluate independently.
struct SearchProblem {
  std::shared_ptr<const Objective> objective;
  int dimension = 1;

  pagmo::vector_double fitness(const pagmo::vector_double& x) const {
    const double value = (*objective)(x);
    return {std::isfinite(value) ? value : kNotFinite};
  }
  std::pair<pagmo::vector_double, pagmo::vector_double> get_bounds() const {
    return {pagmo::vector_double(dimension, 0.0), pagmo::vector_double(dimension, 1.0)};
  }
  pagmo::thread_safety get_thread_safety() const { return pagmo::thread_safety::constant; }
  std::string get_name() const { return "isolab fit"; }

  static constexpr double kNotFinite = 1e300;
};

constexpr int kGenerationsPerChunk = 20;
constexpr double kSettledValue = 1e-12;

// CMA-ES's default population 4 + 3 ln D, doubled for the multimodal landscapes of parallel
// hysteretic components.
int PopulationSize(int dimension) { return 2 * (4 + static_cast<int>(3.0 * std::log(dimension))); }

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

// Per island: its algorithm and population, IPOP restarts (a fresh random population, twice
// as large, when the island has stagnated), and the best point it has found across restarts.
// Under a spread (task_spread.h) only the process that owns an island holds its algorithm and
// population; every process holds the rest, as the owner sends it after each chunk.
struct Island {
  pagmo::algorithm algorithm;
  pagmo::population population;
  long retired = 0;  // evaluations of the populations replaced at restarts (owner only)
  int chunks_without_progress = 0;  // owner only
  // What every process knows:
  long evaluations = 0;  // of every population the island has had
  int restarts = 0;
  int population_size = 0;
  double best_f = INFINITY;
  pagmo::vector_double best_x;
  double best_step = 1.0;  // the population's spread when it found best_x
  double champion_f = INFINITY;
  pagmo::vector_double champion_x;  // the current population's best
};

// The owner's island as the numbers it sends: counts, values, then best_x and champion_x.
std::vector<double> Encode(Island& island) {
  island.evaluations = island.retired + long(island.population.get_problem().get_fevals());
  island.champion_f = island.population.champion_f()[0];
  island.champion_x = island.population.champion_x();
  const pagmo::vector_double& best = island.best_x.empty() ? island.champion_x : island.best_x;
  std::vector<double> numbers{double(island.evaluations),
                              double(island.restarts),
                              double(island.population_size),
                              island.best_f,
                              island.best_step,
                              island.champion_f};
  numbers.insert(numbers.end(), best.begin(), best.end());
  numbers.insert(numbers.end(), island.champion_x.begin(), island.champion_x.end());
  return numbers;
}

void Decode(const std::vector<double>& numbers, Island& island) {
  constexpr std::size_t kHead = 6;
  const std::size_t dimension = (numbers.size() - kHead) / 2;
  island.evaluations = long(numbers[0]);
  island.restarts = int(numbers[1]);
  island.population_size = int(numbers[2]);
  island.best_f = numbers[3];
  island.best_step = numbers[4];
  island.champion_f = numbers[5];
  const auto best = numbers.begin() + long(kHead);
  island.best_x.assign(best, best + long(dimension));
  island.champion_x.assign(best + long(dimension), numbers.end());
}

// Every island's numbers, as their owners sent them, on every process.
void Share(const std::vector<std::vector<double>>& numbers, std::vector<Island>& archipelago) {
  for (std::size_t i = 0; i < archipelago.size(); ++i) Decode(numbers[i], archipelago[i]);
}

// Island i's first population, seeded for it; the first island's holds the start.
void StartIsland(Island& island, int i, const pagmo::problem& problem,
                 const std::vector<double>& start, const FitOptions& options, int population_size) {
  island.algorithm = Cmaes(IslandSeed(options.seed, i, 0));
  island.population =
      pagmo::population{problem, static_cast<pagmo::population::size_type>(population_size),
                        IslandSeed(options.seed, i, 1000)};
  if (i == 0) island.population.set_x(0, start);
  island.population_size = population_size;
}

// An island after a chunk of generations: its best kept where it improved; after 100 stagnant
// generations, restarted from new random points with a larger population (IPOP-CMA-ES), which
// explores more widely each time.
void AfterChunk(Island& island, int i, const pagmo::problem& problem, const FitOptions& options,
                int population_size) {
  const double f = island.population.champion_f()[0];
  if (f < island.best_f * (1.0 - 1e-6)) {
    island.best_f = f;
    island.best_x = island.population.champion_x();
    island.best_step = Spread(island.population);
    island.chunks_without_progress = 0;
  } else if (++island.chunks_without_progress >= 5) {
    ++island.restarts;
    island.population_size = std::min(2 * island.population_size, 16 * population_size);
    island.chunks_without_progress = 0;
    island.retired += static_cast<long>(island.population.get_problem().get_fevals());
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

// The convergence stop: over the last window of evaluations the best improved by less than
// stop_e2 relative and the step size is below stop_step. Sets the result's stop where met.
bool Converged(const std::vector<std::pair<long, double>>& history, long evaluations, double best,
               double step, const FitOptions& options, const std::string& objective_name,
               SearchOutcome& result) {
  const long window = std::max(options.stop_window,
                               static_cast<long>(options.stop_window_share * double(evaluations)));
  if (options.stop_window > 0 && evaluations - history.front().first >= window) {
    // The best as it stood a window ago (the latest record at least a window back).
    double then = history.front().second;
    for (const auto& [at, value] : history) {
      if (evaluations - at >= window) then = value;
    }
    // A value at round-off (1e-12: an RMS error of 1e-6 of the data, for the objectives of
    // fit.h and building_fit.h) counts as settled however its last digits move.
    if (then - best <= options.stop_e2 * then + kSettledValue && step <= options.stop_step) {
      result.stop = FitStop::kConverged;
      result.stop_reason = fmt::format(
          "converged after {} evaluations: over the last {} the best {} ({:.6g} %) improved "
          "by less than {:g} relative and the step size is {:.2g} (below {:g}) in the unit "
          "cube of search coordinates",
          evaluations, window, objective_name, 100 * best, options.stop_e2, step,
          options.stop_step);
      return true;
    }
  }
  return false;
}

// The best point over the islands, their restarts included.
void BestOverIslands(const std::vector<Island>& archipelago, pagmo::vector_double& best_x,
                     double& best_f) {
  for (const Island& island : archipelago) {
    if (island.champion_f < best_f) {
      best_f = island.champion_f;
      best_x = island.champion_x;
    }
    if (island.best_f < best_f) {
      best_f = island.best_f;
      best_x = island.best_x;
    }
  }
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
  if (global_budget < -1 || (global_budget > 0 && global_budget < 100)) {
    throw InvalidParameter(
        {"global_budget", double(global_budget), "must be -1 (the default), 0 or >= 100"});
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

long FirstChunkEvaluations(int dimension, int islands) {
  // The first populations, the start set into the first one (evaluated again), the generations.
  return long(islands) * PopulationSize(dimension) * (kGenerationsPerChunk + 1) + 1;
}

SearchOutcome SearchUnitCube(const Objective& objective, int dimension,
                             const std::vector<double>& start, const FitOptions& options,
                             const std::string& objective_name) {
  const int threads = ThreadsOrHardware(options.threads);
  const int islands = options.islands;
  const int population_size = PopulationSize(dimension);
  const pagmo::problem problem{
      SearchProblem{std::make_shared<const Objective>(objective), dimension}};

  const long cmaes_budget = static_cast<long>(options.budget * (1.0 - options.polish_share));
  // Islands share nothing, so running them on any number of threads or processes gives the
  // same result.
  std::vector<Island> archipelago(static_cast<std::size_t>(islands));
  const int island_threads = std::min(threads, islands);
  Share(SpreadFor(options.spread, archipelago.size(), island_threads,
                  [&](std::size_t i) {
                    StartIsland(archipelago[i], int(i), problem, start, options, population_size);
                    return Encode(archipelago[i]);
                  }),
        archipelago);
  const auto evaluations_so_far = [&] {
    long sum = 0;
    for (const Island& island : archipelago) sum += island.evaluations;
    return sum;
  };
  const auto chunk_cost = [&] {
    long cost = 0;
    for (const Island& island : archipelago) cost += island.population_size * kGenerationsPerChunk;
    return cost;
  };
  // The best value after each chunk, for the convergence stop's window.
  std::vector<std::pair<long, double>> history;
  SearchOutcome result;
  int generation = 0;
  while (evaluations_so_far() + chunk_cost() <= cmaes_budget) {
    Share(SpreadFor(options.spread, archipelago.size(), island_threads,
                    [&](std::size_t i) {
                      Island& island = archipelago[i];
                      island.population = island.algorithm.evolve(island.population);
                      AfterChunk(island, int(i), problem, options, population_size);
                      return Encode(island);
                    }),
          archipelago);
    generation += kGenerationsPerChunk;
    const auto leader =
        std::min_element(archipelago.begin(), archipelago.end(),
                         [](const Island& a, const Island& b) { return a.best_f < b.best_f; });
    const double best = leader->best_f;
    const long evaluations = evaluations_so_far();
    history.emplace_back(evaluations, best);
    if (options.progress) options.progress({evaluations, generation, best, false});
    if (Converged(history, evaluations, best, leader->best_step, options, objective_name, result)) {
      break;
    }
  }

  // The best point over islands and restarts, then a compass-search polish from it.
  pagmo::vector_double best_x = start;
  double best_f = INFINITY;
  BestOverIslands(archipelago, best_x, best_f);
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
  if (options.polish_share > 0.0 && polish_budget > 2 * dimension) {
    pagmo::population single{problem, 0u, options.seed};
    single.push_back(best_x);
    pagmo::algorithm compass{
        pagmo::compass_search(static_cast<unsigned>(polish_budget), 0.02, 1e-9, 0.5)};
    if (options.progress) options.progress({evaluations, generation, single.champion_f()[0], true});
    single = compass.evolve(single);
    evaluations += static_cast<long>(single.get_problem().get_fevals());
    // Compass search keeps its best point: never worse than where it started.
    if (single.champion_f()[0] <= best_f) {
      best_f = single.champion_f()[0];
      best_x = single.champion_x();
    }
  }
  if (result.stop != FitStop::kConverged) {
    result.stop = FitStop::kBudget;
    result.stop_reason = fmt::format("the budget of {} evaluations was spent", options.budget);
  }
  result.evaluations = evaluations;
  result.generations = generation;
  for (const Island& island : archipelago) result.restarts += island.restarts;
  result.point = best_x;
  result.value = best_f;
  return result;
}

}  // namespace isolab::identification
