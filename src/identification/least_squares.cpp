#include "isolab/identification/least_squares.h"

#include <fmt/format.h>

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "isolab/core/errors.h"
#include "isolab/core/hardware_threads.h"
#include "spread_for.h"

namespace isolab::identification {
namespace {

// The residual at x, or false where the model does not run there.
bool Evaluate(const Residual& residual, std::span<const double> x, Eigen::VectorXd* r) {
  try {
    *r = residual(x);
  } catch (const std::exception&) {
    return false;
  }
  return r->allFinite();
}

// Coordinates free to move: those not at a face of the cube with the gradient pointing out.
std::vector<long> FreeCoordinates(const std::vector<double>& x, const Eigen::VectorXd& gradient) {
  std::vector<long> free;
  for (std::size_t p = 0; p < x.size(); ++p) {
    const bool held =
        (x[p] <= 0.0 && gradient[long(p)] > 0.0) || (x[p] >= 1.0 && gradient[long(p)] < 0.0);
    if (!held) free.push_back(long(p));
  }
  return free;
}

// The step on the free coordinates that minimises |r + J d|^2 + lambda sum D_p d_p^2 (D the
// diagonal of J^T J: Marquardt's scaling, so lambda is free of the coordinates' units), clipped to
// the cube. lambda 0 is the Gauss-Newton step (minimum norm where J^T J is singular).
std::vector<double> Step(const Eigen::MatrixXd& normal, const Eigen::VectorXd& gradient,
                         const std::vector<long>& free, const std::vector<double>& x,
                         double lambda) {
  const long m = long(free.size());
  Eigen::MatrixXd a(m, m);
  Eigen::VectorXd b(m);
  for (long i = 0; i < m; ++i) {
    b[i] = -0.5 * gradient[free[std::size_t(i)]];
    for (long j = 0; j < m; ++j) a(i, j) = normal(free[std::size_t(i)], free[std::size_t(j)]);
  }
  for (long i = 0; i < m; ++i) a(i, i) += lambda * std::max(a(i, i), 1e-12);
  const Eigen::VectorXd d = a.completeOrthogonalDecomposition().solve(b);
  std::vector<double> trial = x;
  for (long i = 0; i < m; ++i) {
    const std::size_t p = std::size_t(free[std::size_t(i)]);
    trial[p] = std::clamp(x[p] + d[i], 0.0, 1.0);
  }
  return trial;
}

Eigen::VectorXd Move(const std::vector<double>& from, const std::vector<double>& to) {
  Eigen::VectorXd d(long(from.size()));
  for (std::size_t p = 0; p < from.size(); ++p) d[long(p)] = to[p] - from[p];
  return d;
}

}  // namespace

DifferenceJacobianResult DifferenceJacobian(const Residual& residual, const std::vector<double>& x,
                                            const Eigen::VectorXd& r, double h, int threads,
                                            const TaskSpread* spread) {
  const std::size_t n = x.size();
  // Each column's task gives its simulations, then the column.
  const std::vector<std::vector<double>> columns =
      SpreadFor(spread, n, std::min(ThreadsOrHardware(threads), int(n)), [&](std::size_t p) {
        std::vector<double> point = x;
        const double up = std::min(1.0, x[p] + h), down = std::max(0.0, x[p] - h);
        Eigen::VectorXd r_up = r, r_down = r;
        double at_up = x[p], at_down = x[p];
        std::vector<double> out(std::size_t(r.size()) + 1, 0.0);
        if (up > x[p]) {
          point[p] = up;
          ++out[0];
          if (Evaluate(residual, point, &r_up)) at_up = up;
        }
        if (down < x[p]) {
          point[p] = down;
          ++out[0];
          if (Evaluate(residual, point, &r_down)) at_down = down;
        }
        if (at_up > at_down) {
          Eigen::Map<Eigen::VectorXd>(out.data() + 1, r.size()) =
              ((at_up > x[p] ? r_up : r) - (at_down < x[p] ? r_down : r)) / (at_up - at_down);
        }
        return out;
      });
  DifferenceJacobianResult result;
  result.jacobian.resize(r.size(), long(n));
  for (std::size_t p = 0; p < n; ++p) {
    result.evaluations += long(columns[p][0]);
    result.jacobian.col(long(p)) =
        Eigen::Map<const Eigen::VectorXd>(columns[p].data() + 1, r.size());
  }
  return result;
}

void RefinementOptions::Validate(int dimension) const {
  if (budget < 2L * dimension + 2) {
    throw InvalidParameter(
        {"budget", double(budget),
         fmt::format("must be >= {} (2 per parameter, plus 2)", 2 * dimension + 2)});
  }
  if (threads < 0 || threads > 1024) {
    throw InvalidParameter(
        {"threads", double(threads), "must be 0 (every hardware thread) or in [1, 1024]"});
  }
  if (!(difference_step > 0.0 && difference_step <= 0.1)) {
    throw InvalidParameter({"difference_step", difference_step, "must be in (0, 0.1]"});
  }
  if (!(decrement_tolerance > 0.0 && decrement_tolerance < 1.0)) {
    throw InvalidParameter({"decrement_tolerance", decrement_tolerance, "must be in (0, 1)"});
  }
  if (!(step_tolerance > 0.0 && step_tolerance < 1.0)) {
    throw InvalidParameter({"step_tolerance", step_tolerance, "must be in (0, 1)"});
  }
}

RefinementOutcome RefineLeastSquares(const Residual& residual, const std::vector<double>& start,
                                     const RefinementOptions& options) {
  const int dimension = int(start.size());
  options.Validate(dimension);
  RefinementOutcome out;
  out.point = start;
  Eigen::VectorXd r;
  out.evaluations = 1;
  if (!Evaluate(residual, out.point, &r)) {
    throw std::invalid_argument("the model does not run at the refinement's start");
  }
  out.value = r.squaredNorm();
  double lambda = 1e-3, growth = 2.0;
  for (;;) {
    if (out.evaluations + 2L * dimension > options.budget) break;
    DifferenceJacobianResult differences = DifferenceJacobian(
        residual, out.point, r, options.difference_step, options.threads, options.spread);
    out.evaluations += differences.evaluations;
    out.jacobian = std::move(differences.jacobian);
    out.jacobian_current = true;
    ++out.iterations;
    const Eigen::MatrixXd& jacobian = out.jacobian;
    const Eigen::VectorXd gradient = 2.0 * jacobian.transpose() * r;
    const Eigen::MatrixXd normal = jacobian.transpose() * jacobian;
    const std::vector<long> free = FreeCoordinates(out.point, gradient);
    // The Gauss-Newton step and the reduction of S it predicts: the convergence measures.
    const std::vector<double> newton =
        free.empty() ? out.point : Step(normal, gradient, free, out.point, 0.0);
    const Eigen::VectorXd d_newton = Move(out.point, newton);
    out.step = d_newton.size() ? d_newton.cwiseAbs().maxCoeff() : 0.0;
    out.decrement =
        out.value > 0.0 ? (out.value - (r + jacobian * d_newton).squaredNorm()) / out.value : 0.0;
    if (options.progress) {
      options.progress({out.iterations, out.evaluations, out.value, out.decrement, out.step});
    }
    if (out.value == 0.0 || free.empty() ||
        (out.decrement <= options.decrement_tolerance && out.step <= options.step_tolerance)) {
      out.stop = RefinementStop::kConverged;
      return out;
    }
    // Levenberg-Marquardt: shorter, steeper steps until one lowers S (Nielsen's update of
    // lambda from the gain ratio, so a good model of S lengthens the next step).
    bool accepted = false;
    while (!accepted) {
      if (out.evaluations + 1 > options.budget) return out;
      if (lambda > 1e16) {
        out.stop = RefinementStop::kStalled;
        return out;
      }
      const std::vector<double> trial = Step(normal, gradient, free, out.point, lambda);
      const Eigen::VectorXd d = Move(out.point, trial);
      const double predicted = out.value - (r + jacobian * d).squaredNorm();
      Eigen::VectorXd r_trial;
      ++out.evaluations;
      const bool runs = d.cwiseAbs().maxCoeff() > 0.0 && Evaluate(residual, trial, &r_trial);
      const double value = runs ? r_trial.squaredNorm() : INFINITY;
      if (value < out.value) {
        const double gain = predicted > 0.0 ? (out.value - value) / predicted : 0.0;
        lambda *= std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * gain - 1.0, 3));
        growth = 2.0;
        out.point = trial;
        out.value = value;
        r = std::move(r_trial);
        out.jacobian_current = false;
        accepted = true;
      } else {
        lambda *= growth;
        growth *= 2.0;
      }
    }
  }
  return out;
}

const char* RefinementStopName(RefinementStop stop) {
  switch (stop) {
    case RefinementStop::kConverged:
      return "converged";
    case RefinementStop::kStalled:
      return "stalled";
    case RefinementStop::kBudget:
      break;
  }
  return "budget";
}

std::string RefinementSummary(const RefinementOutcome& outcome, const RefinementOptions& options,
                              const std::string& objective_name, double scale) {
  const std::string where = fmt::format(
      "the Gauss-Newton step from there would lower {} by {:.2g} relative (the gradient along it; "
      "tolerance {:g}) and moves no parameter by more than {:.2g} of its range (step; tolerance "
      "{:g})",
      objective_name, outcome.decrement, options.decrement_tolerance, outcome.step,
      options.step_tolerance);
  const std::string done =
      fmt::format("{} iterations, {} simulations, {} = {:.6g}", outcome.iterations,
                  outcome.evaluations, objective_name, outcome.value * scale);
  switch (outcome.stop) {
    case RefinementStop::kConverged:
      return fmt::format("converged ({}): {}", done, where);
    case RefinementStop::kStalled:
      return fmt::format(
          "stalled ({}): no step along the Jacobian lowers {} further, so the "
          "finite differences no longer resolve its slope; at the last Jacobian {}",
          done, objective_name, where);
    case RefinementStop::kBudget:
      break;
  }
  return fmt::format("NOT converged: the budget ran out ({}); at the last Jacobian {}", done,
                     where);
}

}  // namespace isolab::identification
