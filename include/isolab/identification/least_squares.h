// A local least-squares refinement for output-error fits: Levenberg-Marquardt on a residual
// vector r(x) over the unit cube of search coordinates (the cube unit_cube_search.h searches),
// minimising S(x) = |r(x)|^2 from a start the global search found (or a start the user trusts).
//
// Output-error problems are smooth near their optimum, where CMA-ES's random steps converge
// slowly: one Gauss-Newton step on the residual's Jacobian lands where a population needs
// hundreds of simulations to go. The Jacobian is by central differences (one-sided at the cube's
// faces), each column a pair of simulations that threads run side by side; every column is
// written by its own task, so the result does not depend on the thread count. Bounds are kept
// by projection: a coordinate at a face whose gradient points out of the cube is held there.
//
// The convergence statement is local and checkable, both criteria measured at the final point
// with the Jacobian the next step would use:
//  - gradient: the Newton decrement, the gradient measured along the Gauss-Newton step (the
//    reduction of S that step predicts, relative to S), is below `decrement_tolerance`. Unlike
//    the gradient's own size it does not depend on how sharply the data fix a parameter: a
//    parameter known to 1e-4 of its range has a steep gradient 1e-3 away from its optimum;
//  - step: the Gauss-Newton step moves no coordinate by more than `step_tolerance` of its range.
// A fit reported converged is at a stationary point of this model on these data, not merely
// where the budget ran out.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "isolab/identification/task_spread.h"

namespace isolab::identification {

// The residual at a point of the unit cube; called from several threads at once, so it must only
// read shared data. A throw or a non-finite entry marks a point where the model does not run.
using Residual = std::function<Eigen::VectorXd(std::span<const double>)>;

struct RefinementProgress {
  int iteration = 0;
  long evaluations = 0;                // residual evaluations (simulations) so far
  double value = 0.0;                  // S at the current point
  double decrement = 0.0, step = 0.0;  // the convergence measures there (RefinementOutcome)
};

struct RefinementOptions {
  long budget = 1000;  // residual evaluations; >= 2 x dimension + 2
  // Threads that run the Jacobian's columns side by side (0: one per hardware thread, else 1 to
  // 1024); never changes the result.
  int threads = 0;
  // Other processes that run Jacobian columns beside this one (FitOptions::spread); null: none.
  const TaskSpread* spread = nullptr;
  double difference_step = 1e-3;  // of the unit cube, for the Jacobian's differences; (0, 0.1]
  // The convergence criteria. Output-error objectives of hysteretic models are smooth only down
  // to the kinks of their laws, which finite differences see as noise: tighter tolerances are
  // not met, looser ones stop short of the optimum (the BNCS building: docs/bncs.md, "Time").
  double decrement_tolerance = 1e-5;  // relative reduction of S the Gauss-Newton step predicts
  double step_tolerance = 5e-3;       // of the unit cube, the Gauss-Newton step; (0, 1)
  std::function<void(const RefinementProgress&)> progress;  // called every iteration

  // Throws InvalidParameter naming the first field out of range.
  void Validate(int dimension) const;
};

enum class RefinementStop {
  kConverged,  // the gradient and step criteria hold at the final point
  kStalled,    // no step along the Jacobian lowers S: the differences no longer see the slope
  kBudget,     // the budget ran out first
};

struct RefinementOutcome {
  std::vector<double> point;  // the final point, in the unit cube
  double value = 0.0;         // S there
  long evaluations = 0;
  int iterations = 0;  // Jacobians evaluated
  RefinementStop stop = RefinementStop::kBudget;
  double decrement = 0.0;  // the Newton decrement at the final point (relative to S)
  double step = 0.0;       // largest coordinate of the last Gauss-Newton step (unit cube)
  // The last Jacobian (rows: the residual's entries; columns: the coordinates), and whether it
  // was taken at `point` (no step accepted since): the covariance can then reuse it.
  Eigen::MatrixXd jacobian;
  bool jacobian_current = false;
};

// Minimises |residual(x)|^2 over [0, 1]^dimension from `start` (where the residual must be
// finite). Throws std::invalid_argument when it is not.
RefinementOutcome RefineLeastSquares(const Residual& residual, const std::vector<double>& start,
                                     const RefinementOptions& options);

struct DifferenceJacobianResult {
  Eigen::MatrixXd jacobian;  // rows: the residual's entries; columns: the coordinates
  long evaluations = 0;
};
// The Jacobian of `residual` at x (where it is r) by central differences of h in the unit cube,
// one-sided at the faces or where one side does not run; a column neither side gives is zero.
// Columns run on `threads` threads (0: every hardware thread) and the processes of `spread`
// (null: this one alone), each written by its own task.
DifferenceJacobianResult DifferenceJacobian(const Residual& residual, const std::vector<double>& x,
                                            const Eigen::VectorXd& r, double h, int threads,
                                            const TaskSpread* spread = nullptr);

// "converged", "stalled", "budget": the stop as the JSON outputs name it.
const char* RefinementStopName(RefinementStop stop);

// One sentence with the numbers, for the output; `objective_name` names S / scale as the user
// reads it (S x scale is the reported objective).
std::string RefinementSummary(const RefinementOutcome& outcome, const RefinementOptions& options,
                              const std::string& objective_name, double scale);

}  // namespace isolab::identification
