// The search every fit in isolab runs: pagmo2's CMA-ES over the unit cube of a problem's search
// coordinates, a fixed number of islands, each with its own seed and IPOP restarts (a fresh
// population, twice as large, when an island stagnates), a convergence stop, then pagmo's compass
// search from the best point. The objective is a black box, so the cyclic-test fit (fit.h: e^2
// with the stiffnesses solved exactly at each point) and the building-level output-error fit
// (building/building_fit.h: a simulation per point) share one search.
//
// The same answer on every machine: the number of islands is an option with a fixed default,
// never the core count, because the budget is split across islands and so their number shapes
// the search. Threads only run islands side by side, so a fixed seed reproduces a search to the
// last digit whatever the thread count.
#pragma once

#include <functional>
#include <span>
#include <string>
#include <vector>

#include "isolab/identification/task_spread.h"

namespace isolab::identification {

struct FitProgress {
  long evaluations = 0;
  int generation = 0;      // CMA-ES generations of the leading island
  double best = 0.0;       // best objective (e^2) so far
  bool polishing = false;  // the polish, or a least-squares refinement (least_squares.h)
  // A refinement's convergence measures (RefinementOutcome::decrement and step); 0 otherwise.
  double decrement = 0.0, step = 0.0;
};

struct FitOptions {
  unsigned seed = 1;    // a fixed seed reproduces the fit to the last digit, on any machine
  long budget = 60000;  // model evaluations over all islands, CMA-ES and polish; >= 100
  // CMA-ES islands, each with its own seed and share of the budget; 1 to 64. Fixed by default
  // (not the core count), so the result is the same on every machine.
  int islands = 2;
  // Threads that run the islands side by side and share each evaluation's work; 0: one per
  // hardware thread, else 1 to 1024. Changes how fast a fit runs, never its result.
  int threads = 0;
  // Other processes that run islands and Jacobian columns beside this one (MPI ranks); null:
  // this process alone. Like threads, changes how fast a fit runs, never its result.
  const TaskSpread* spread = nullptr;
  // Share of the budget for the compass-search polish; [0, 1); 0: no polish, the CMA-ES stage
  // ends with its last whole chunk of generations that fits the budget.
  double polish_share = 0.1;
  // Fits that end with a least-squares refinement instead of the polish (the building fit,
  // building/building_fit.h) give the CMA-ES stage this many evaluations and the refinement the
  // rest of the budget. -1: half the budget, or one chunk of generations where half is less
  // and the budget allows it; 0: no global stage; else >= 100. A global budget below
  // FirstChunkEvaluations runs no global stage either: CMA-ES would not move.
  long global_budget = -1;
  // Convergence stop of the CMA-ES stage: it ends when, over a window of the last
  // max(stop_window, stop_window_share x evaluations so far) evaluations, the best e^2 has
  // improved by less than `stop_e2` relative and the step size with which the island that holds
  // it found it (the spread of its population in the unit cube of search coordinates) is below
  // `stop_step`: the point is located, and restarts for as long again as the search took to find
  // it have not beaten it. An e^2 below 1e-12 (an RMS error of 1e-6 of the force) counts as
  // settled. The window grows with the search because an IPOP restart that finds a better basin
  // comes late on hard landscapes (the nine-component HDRB fit: flat from 24,000 to 41,000
  // evaluations, then 8 times lower). stop_window 0 runs the whole budget. stop_window >= 0
  // evaluations; stop_window_share in [0, 1]; stop_e2 in [0, 1); stop_step in [0, 1].
  long stop_window = 3000;
  double stop_window_share = 0.5;
  double stop_e2 = 1e-6;
  double stop_step = 1e-3;
  std::function<void(const FitProgress&)> progress;  // called every few generations

  // Throws InvalidParameter naming the first field out of range.
  void Validate() const;
};

enum class FitStop {
  kBudget,     // the whole budget was spent
  kConverged,  // the convergence stop (FitOptions::stop_window) ended the CMA-ES stage
};

// The objective at a point of the unit cube; called from several threads at once, so it must
// only read shared data. A non-finite value counts as the worst.
using Objective = std::function<double(std::span<const double>)>;

struct SearchOutcome {
  std::vector<double> point;  // the best point, in the unit cube
  double value = 0.0;         // the objective there
  long evaluations = 0;       // CMA-ES and polish; <= budget
  int generations = 0;        // CMA-ES generations of each island
  int restarts = 0;
  FitStop stop = FitStop::kBudget;
  std::string stop_reason;  // one sentence with the numbers, for the output
};

// The evaluations of the islands' first populations and their first chunk of generations: the
// least budget in which CMA-ES moves at all.
long FirstChunkEvaluations(int dimension, int islands);

// Minimises `objective` over [0, 1]^dimension (dimension >= 1) from `start` (the first island's
// first member) with `options` (validated by the caller); `objective_name` names it in the stop
// reason ("e^2"), where it is printed as a percentage.
SearchOutcome SearchUnitCube(const Objective& objective, int dimension,
                             const std::vector<double>& start, const FitOptions& options,
                             const std::string& objective_name);

}  // namespace isolab::identification
