#include "isolab/integrators/newmark.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include "blow_up.h"
#include "isolab/core/errors.h"
#include "tangent_solver.h"

namespace isolab::integrators {

void NewmarkOptions::Validate() const {
  if (!(beta > 0.0 && beta <= 0.5)) throw InvalidParameter({"beta", beta, "must be in (0, 0.5]"});
  if (!(gamma >= 0.5 && gamma <= 1.0)) {
    throw InvalidParameter({"gamma", gamma, "must be in [0.5, 1]"});
  }
  if (!(force_tolerance > 0.0 && force_tolerance < 1.0)) {
    throw InvalidParameter({"force_tolerance", force_tolerance, "must be in (0, 1)"});
  }
  if (!(displacement_tolerance > 0.0 && displacement_tolerance < 1.0)) {
    throw InvalidParameter({"displacement_tolerance", displacement_tolerance, "must be in (0, 1)"});
  }
  if (max_iterations < 1) {
    throw InvalidParameter({"max_iterations", double(max_iterations), "must be >= 1"});
  }
  switch (linear_solver) {
    case LinearSolver::kAuto:
    case LinearSolver::kKlu:
    case LinearSolver::kDense:
    case LinearSolver::kBanded:
      break;
    default:
      throw InvalidParameter({"linear_solver", double(static_cast<int>(linear_solver)),
                              "must be auto, klu, dense or banded"});
  }
  if (max_step_cuts < 0 || max_step_cuts > kMaxStepCuts) {
    throw InvalidParameter(
        {"max_step_cuts", double(max_step_cuts), fmt::format("must be in [0, {}]", kMaxStepCuts)});
  }
}

namespace {

using Eigen::VectorXd;
using hysteresis::LawResponse;
using hysteresis::LawState;

// The largest magnitude of the numbers added; NaN where one is NaN, so that no convergence test
// passes on it. A running sum catches the NaN instead of a test of each number: a NaN, or
// infinities of both signs, make the sum NaN.
class MaxMagnitude {
 public:
  void Add(double x) {
    largest_ = std::max(largest_, std::abs(x));
    sum_ += x;
  }
  double value() const { return sum_ == sum_ ? largest_ : sum_; }

 private:
  double largest_ = 0.0, sum_ = 0.0;
};

double MaxAbs(const VectorXd& x) {
  MaxMagnitude largest;
  for (const double xi : x) largest.Add(xi);
  return largest.value();
}

// The force test compares the residual with force_tolerance times the step's force scale. Where
// displacements are large next to the forces (a tall, flexible building still swaying after the
// record has died out), that product falls below the round-off of the residual's own evaluation:
// rounding u to double precision alone leaves a residual of about eps |K_eff| |u|, so the test
// could never pass, and every step would pay a second solve whose correction is round-off (the
// displacement test then ends it). A residual below this many times eps || |K_eff| |u| ||_inf
// counts as converged too: it decides only where the tolerance is out of reach (the two criteria
// are checked in that order), and it means displacements within a few units in the last place of
// the exact solution of the step's equations, far inside displacement_tolerance. Measured
// residuals after one solve at 1000 stories reach half that floor; twice it leaves a margin.
constexpr double kRoundoffFloorFactor = 2.0;

// One run's working state; every vector is sized once, so a step allocates nothing.
using structure::Structure;

class NewmarkRun {
 public:
  NewmarkRun(const Structure& structure, const Excitation& excitation,
             const NewmarkOptions& options, RunSummary* summary)
      : structure_(structure),
        excitation_(excitation),
        options_(options),
        summary_(*summary),
        mass_influence_(excitation.MassInfluence(structure.mass())),
        tangent_(structure.tangent_pattern()),
        constant_tangent_(structure.tangent_pattern()),
        solver_(structure.tangent_pattern(), options.linear_solver),
        committed_(structure.law_count()),
        trial_(structure.law_count()),
        rest_(structure.law_count()),
        responses_(structure.law_count()),
        member_forces_(structure.force_columns()),
        law_forces_(structure.law_count()) {
    pending_levels_.reserve(options.max_step_cuts + 1);
    const int n = structure.dofs();
    for (VectorXd* x :
         {&u_, &v_, &a_, &u_trial_, &v_trial_, &a_trial_, &load_, &load_trial_, &force_, &residual_,
          &increment_, &viscous_, &viscous_trial_, &zero_, &roundoff_, &absolute_acceleration_}) {
      x->setZero(n);
    }
    excitation_.EffectiveLoad(0.0, mass_influence_, &load_);
    a_ = load_.cwiseQuotient(structure_.mass());  // at rest, M a0 = p_eff(0)
    if (!axial_.empty()) StartAxialLoads();
  }

  // Advances from t0 by h, cutting a sub-step in halves while Newton fails on it. The sub-steps
  // still to take are a stack of halving levels (the one on top is next in time): a failed one
  // is replaced by its two halves, so the stack never holds more than max_step_cuts + 1.
  bool Advance(double t0, double h, int step) {
    double t = t0;
    pending_levels_.assign(1, 0);
    while (!pending_levels_.empty()) {
      const int level = pending_levels_.back();
      pending_levels_.pop_back();
      const double size = level == 0 ? h : std::ldexp(h, -level);
      if (TryStep(t, size)) {
        t += size;
        continue;
      }
      if (level >= options_.max_step_cuts) {
        summary_.message = fmt::format(
            "Newton did not converge at t = {:.6g} (step {}) after {} iterations, residual {:.3g} "
            "against force scale {:.3g}, with the step cut {} times to {:.3g}",
            t + size, step, options_.max_iterations, last_residual_, last_scale_, level, size);
        return false;
      }
      ++summary_.step_cuts;
      pending_levels_.insert(pending_levels_.end(), 2, level + 1);
    }
    return true;
  }

  // Hands the committed state at grid step `step` (time t) to the observer.
  void Record(int step, double t, ResponseObserver& observer) {
    absolute_acceleration_ = a_;
    excitation_.AddGroundAcceleration(t, absolute_acceleration_);
    for (std::size_t k = 0; k < responses_.size(); ++k) law_forces_[k] = responses_[k].force;
    const auto view = [](const VectorXd& x) {
      return std::span<const double>(x.data(), static_cast<std::size_t>(x.size()));
    };
    observer.Observe({step, t, view(u_), view(v_), view(a_), view(absolute_acceleration_),
                      member_forces_, law_forces_, energies_, axial_load_, committed_});
  }

  const Energies& energies() const { return energies_; }
  long factorisations() const { return solver_.factorisations(); }

 private:
  bool TryStep(double t0, double h) {
    const double beta = options_.beta, gamma = options_.gamma;
    const double c0 = 1.0 / (beta * h * h), c1 = gamma / (beta * h);
    const structure::TangentFactors factors{c0, c1};
    excitation_.EffectiveLoad(t0 + h, mass_influence_, &load_trial_);
    if (!axial_.empty()) AxialLoadsAt(t0, h);
    // The predictor carries the committed acceleration through the step: Newmark's relations
    // then give a_trial = a and v_trial = v + h a for any beta and gamma. Each law's first
    // tangent is then the one of the increment the step will most likely take: its phase, the
    // turned slip direction of a plan slider, the friction of a pendulum at about the step's
    // speed. Repeating the committed displacement instead (du = 0) gives only the committed
    // phase's tangent, and at average acceleration a trial velocity of -v, so friction that rises
    // with speed starts on a slope of the wrong sign. Measured (integrators_benchmark): the
    // coupled plan Table 9 model 2.03 to 1.52 solves a step, friction pendulums 3.17 to 2.17, the
    // one-direction Table 9 building 1.05 to 1.00.
    Predict(h);
    bool displacement_converged = false;
    for (int iteration = 0; iteration <= options_.max_iterations; ++iteration) {
      TrialRates(h, c0, c1);
      const bool refactor = NeedsFactorisation(iteration, h);
      // Modified-initial Newton assembles its tangent at rest below, not at the trial state.
      const bool tangent_here =
          refactor && options_.newton != NewmarkOptions::Newton::kModifiedInitial;
      if (tangent_here) StartTangent(factors);
      structure_.Evaluate(committed_, t0 + h, u_trial_, v_trial_, trial_, responses_, &force_,
                          member_forces_, factors, tangent_here ? &tangent_ : nullptr, scales_,
                          linear_mode_);
      Residual();
      if (last_residual_ <= options_.force_tolerance * last_scale_ || displacement_converged ||
          (iteration > 0 && last_residual_ <= kRoundoffFloorFactor * RoundoffResidual())) {
        Commit(t0 + h, iteration);
        return true;
      }
      if (iteration == options_.max_iterations) break;
      if (refactor) {
        if (options_.newton == NewmarkOptions::Newton::kModifiedInitial) {
          StartTangent(factors);
          structure_.Evaluate(rest_, 0.0, zero_, zero_, trial_, responses_, &force_, member_forces_,
                              factors, &tangent_);
        }
        factored_step_ = h;
        if (!solver_.Factorize(tangent_)) break;
      }
      solver_.Solve(&residual_);  // the correction, in place: the next Residual() writes anew
      ++summary_.newton_iterations;
      displacement_converged = Correct(residual_);
      if (options_.newton == NewmarkOptions::Newton::kModifiedInitial && refactor) {
        // The rest-state evaluation above overwrote trial states: evaluate again next iteration.
        displacement_converged = false;
      }
    }
    return false;
  }

  // The vectors below are a building's dofs, often a few: plain loops, as an expression's set-up
  // costs more than its arithmetic there. Each term is evaluated as written, in its order.

  // u_trial = u + h v + (h^2 / 2) a.
  void Predict(double h) {
    const double half_h2 = 0.5 * h * h;
    const double *u = u_.data(), *v = v_.data(), *a = a_.data();
    double* u_trial = u_trial_.data();
    for (Eigen::Index i = 0; i < u_.size(); ++i) u_trial[i] = u[i] + h * v[i] + half_h2 * a[i];
  }

  // v_trial and a_trial at u_trial by Newmark's relations.
  void TrialRates(double h, double c0, double c1) {
    const double beta = options_.beta, gamma = options_.gamma;
    const double v_of_v = 1.0 - gamma / beta, v_of_a = h * (1.0 - gamma / (2.0 * beta));
    const double a_of_v = 1.0 / (beta * h), a_of_a = 1.0 / (2.0 * beta) - 1.0;
    const double *u = u_.data(), *v = v_.data(), *a = a_.data(), *u_trial = u_trial_.data();
    double *v_trial = v_trial_.data(), *a_trial = a_trial_.data();
    for (Eigen::Index i = 0; i < u_.size(); ++i) {
      const double du = u_trial[i] - u[i];
      v_trial[i] = c1 * du + v_of_v * v[i] + v_of_a * a[i];
      a_trial[i] = c0 * du - a_of_v * v[i] - a_of_a * a[i];
    }
  }

  // residual_ = load - M a - force at the trial state, with its largest magnitude and the step's
  // force scale (the largest load, internal force or inertia force), in one pass.
  void Residual() {
    const double* mass = structure_.mass().data();
    MaxMagnitude residual;
    double scale = 0.0;  // a NaN in a term reaches the residual
    for (Eigen::Index i = 0; i < residual_.size(); ++i) {
      const double inertia = mass[i] * a_trial_[i];
      const double r = residual_[i] = load_trial_[i] - inertia - force_[i];
      scale = std::max({scale, std::abs(load_trial_[i]), std::abs(force_[i]), std::abs(inertia)});
      residual.Add(r);
    }
    last_scale_ = scale;
    last_residual_ = residual.value();
  }

  // Adds the Newton correction to the trial displacement; true when it is below the
  // displacement tolerance relative to that displacement.
  bool Correct(const VectorXd& du) {
    MaxMagnitude correction;
    double displacement = 0.0;  // a NaN in the correction reaches the displacement
    for (Eigen::Index i = 0; i < u_trial_.size(); ++i) {
      correction.Add(du[i]);
      displacement = std::max(displacement, std::abs(u_trial_[i] += du[i]));
    }
    return correction.value() <= options_.displacement_tolerance * std::max(displacement, 1e-300);
  }

  // eps || |K_eff| |u| ||_inf at the trial displacement, with the last assembled tangent. One
  // pass over the tangent's entries, made only after a solve and when the force test has failed
  // (the predictor's residual is the extrapolation's error, never round-off worth a check).
  double RoundoffResidual() {
    const int* columns = tangent_.outerIndexPtr();
    const int* rows = tangent_.innerIndexPtr();
    const double* values = tangent_.valuePtr();
    roundoff_.setZero();
    for (int j = 0; j < tangent_.outerSize(); ++j) {
      const double uj = std::abs(u_trial_[j]);
      for (int k = columns[j]; k < columns[j + 1]; ++k)
        roundoff_[rows[k]] += std::abs(values[k]) * uj;
    }
    return std::numeric_limits<double>::epsilon() * MaxAbs(roundoff_);
  }

  // The tangent's values set to the structure's terms that do not depend on the state (computed
  // again only when the step size changes), for Evaluate to add the rest to.
  void StartTangent(const structure::TangentFactors& factors) {
    if (!constant_factors_ || factors.mass != constant_factors_->mass ||
        factors.damping != constant_factors_->damping) {
      structure_.ConstantTangent(factors, &constant_tangent_);
      constant_factors_ = factors;
    }
    std::copy_n(constant_tangent_.valuePtr(), constant_tangent_.nonZeros(), tangent_.valuePtr());
  }

  bool NeedsFactorisation(int iteration, double h) const {
    switch (options_.newton) {
      case NewmarkOptions::Newton::kFull:
        return true;
      case NewmarkOptions::Newton::kModifiedStep:
        return iteration == 0;
      case NewmarkOptions::Newton::kModifiedInitial:
        return factored_step_ != h;
    }
    return true;
  }

  void Commit(double t, int iterations) {
    summary_.max_iterations_in_a_step = std::max(summary_.max_iterations_in_a_step, iterations);
    if (linear_mode_ == Structure::LinearLaws::kForceOnly) {
      structure_.UpdateLinearLaws(committed_, t, u_trial_, v_trial_, trial_, responses_);
    }
    structure_.DampingForce(v_trial_, &viscous_trial_);
    const VectorXd& du = increment_ = u_trial_ - u_;
    energies_.input += 0.5 * (load_ + load_trial_).dot(du);
    viscous_energy_ += 0.5 * (viscous_ + viscous_trial_).dot(du);
    std::swap(committed_, trial_);
    u_.swap(u_trial_);
    v_.swap(v_trial_);
    a_.swap(a_trial_);
    load_.swap(load_trial_);
    viscous_.swap(viscous_trial_);
    energies_.kinetic = 0.5 * v_.dot(structure_.mass().cwiseProduct(v_));
    energies_.elastic = structure_.StoredEnergy(committed_);
    const double dashpots = structure_.DashpotEnergy(committed_);
    energies_.hysteretic = structure_.DissipatedEnergy(committed_) - dashpots;
    energies_.damping = viscous_energy_ + dashpots;
    if (!axial_.empty()) CommitAxialLoads();
  }

  // The bearings' loads and scales at rest (the record's first vertical sample, no overturning:
  // the structure at rest has no absolute acceleration).
  void StartAxialLoads() {
    scales_.assign(structure_.slots(), 1.0);
    const std::size_t count = axial_.bearings.size();
    for (std::vector<double>* x :
         {&axial_load_, &axial_load_trial_, &axial_scale_, &axial_scale_trial_, &axial_stored_,
          &axial_dissipated_, &axial_scaled_dissipated_}) {
      x->assign(count, 0.0);
    }
    committed_absolute_.setZero(structure_.dofs());
    const double vertical = excitation_.vertical.At(0.0);
    for (std::size_t j = 0; j < count; ++j) {
      axial_load_[j] = axial_.Load(
          j, vertical,
          {committed_absolute_.data(), static_cast<std::size_t>(committed_absolute_.size())});
      axial_scale_[j] = axial_.Scale(j, axial_load_[j]);
    }
  }

  // The loads over the step from t0 to t0 + h: the vertical ground acceleration at its end, the
  // overturning from the inertial forces at its start (axial_load.h: explicit in the moment).
  void AxialLoadsAt(double t0, double h) {
    committed_absolute_ = a_;
    excitation_.AddGroundAcceleration(t0, committed_absolute_);
    const std::span<const double> absolute(committed_absolute_.data(),
                                           static_cast<std::size_t>(committed_absolute_.size()));
    const double vertical = excitation_.vertical.At(t0 + h);
    for (std::size_t j = 0; j < axial_.bearings.size(); ++j) {
      axial_load_trial_[j] = axial_.Load(j, vertical, absolute);
      axial_scale_trial_[j] = scales_[axial_.bearings[j].slot] =
          axial_.Scale(j, axial_load_trial_[j]);
    }
  }

  // The energies of the scaled bearings: stored s E and dissipated sum s dD, from their laws' own
  // (unscaled) E and D, and the axial loads' work sum E ds (trapezoidal, as the input's).
  void CommitAxialLoads() {
    for (std::size_t j = 0; j < axial_.bearings.size(); ++j) {
      const std::size_t slot = axial_.bearings[j].slot;
      const double stored = structure_.SlotStoredEnergy(slot, committed_);
      const double dissipated = structure_.SlotDissipatedEnergy(slot, committed_);
      const double s0 = axial_scale_[j], s1 = axial_scale_trial_[j];
      axial_scaled_dissipated_[j] += 0.5 * (s0 + s1) * (dissipated - axial_dissipated_[j]);
      axial_work_ += 0.5 * (axial_stored_[j] + stored) * (s1 - s0);
      energies_.elastic += (s1 - 1.0) * stored;
      energies_.hysteretic += axial_scaled_dissipated_[j] - dissipated;
      axial_stored_[j] = stored;
      axial_dissipated_[j] = dissipated;
      axial_scale_[j] = s1;
      axial_load_[j] = axial_load_trial_[j];
    }
    energies_.axial = axial_work_;
  }

  const Structure& structure_;
  const Excitation& excitation_;
  const NewmarkOptions& options_;
  RunSummary& summary_;
  const std::vector<VectorXd> mass_influence_;  // M r of each ground component
  structure::SparseMatrix tangent_;
  structure::SparseMatrix constant_tangent_;  // StartTangent's terms, for constant_factors_
  std::optional<structure::TangentFactors> constant_factors_;
  TangentSolver solver_;
  // Between Evaluates with LinearLaws::kForceOnly and Commit, the linear members' entries of
  // trial_ and responses_ are stale: Commit writes them (UpdateLinearLaws).
  std::vector<LawState> committed_, trial_, rest_;
  std::vector<LawResponse> responses_;
  std::vector<double> member_forces_, law_forces_;
  std::vector<int> pending_levels_;  // halving levels of the sub-steps Advance has still to take
  // Axial loads (structure/axial_load.h); all empty without them. Per slot, the scale of the
  // step being tried; per bearing, the committed and trial load and scale, and the committed
  // unscaled stored and dissipated energies and the scaled dissipated energy.
  const structure::AxialLoads& axial_ = structure_.axial_loads();
  std::vector<double> scales_;
  // The iterations take the linear members' force alone, and Commit their laws' states (their
  // force is the trial (u, v)'s, their tangent constant); with axial loads, Evaluate's scales
  // ask for every law's update.
  const Structure::LinearLaws linear_mode_ =
      axial_.empty() ? Structure::LinearLaws::kForceOnly : Structure::LinearLaws::kUpdate;
  std::vector<double> axial_load_, axial_load_trial_, axial_scale_, axial_scale_trial_,
      axial_stored_, axial_dissipated_, axial_scaled_dissipated_;
  VectorXd committed_absolute_;
  double axial_work_ = 0.0;
  VectorXd u_, v_, a_, u_trial_, v_trial_, a_trial_, load_, load_trial_, force_, residual_,
      increment_, viscous_, viscous_trial_, zero_, roundoff_, absolute_acceleration_;
  Energies energies_;
  double viscous_energy_ = 0.0;
  double factored_step_ = 0.0;  // step size of the current modified-Newton factorisation
  double last_residual_ = 0.0, last_scale_ = 0.0;
};

RunSummary Run(const Structure& structure, const Excitation& excitation, const TimeGrid& grid,
               const NewmarkOptions& options, ResponseObserver& observer) {
  options.Validate();
  const auto start = std::chrono::steady_clock::now();
  RunSummary summary;
  NewmarkRun run(structure, excitation, options, &summary);
  run.Record(0, 0.0, observer);
  double max_input = 0.0, max_balance = 0.0;
  for (int step = 1; step <= grid.steps; ++step) {
    const double t0 = (step - 1) * grid.dt;
    if (!run.Advance(t0, grid.dt, step)) {
      summary.termination = RunSummary::Termination::kFailed;
      break;
    }
    run.Record(step, step * grid.dt, observer);
    summary.steps = step;
    max_input = std::max(max_input, run.energies().Supplied());
    max_balance = std::max(max_balance, std::abs(run.energies().Balance()));
    if (ShowsBlowUp(run.energies(), max_input)) {
      summary.termination = RunSummary::Termination::kFailed;
      summary.message = fmt::format("blow-up at t = {:.6g}: {}", step * grid.dt,
                                    DescribeBlowUp(run.energies(), max_input));
      break;
    }
  }
  summary.factorisations = run.factorisations();
  // Undefined (NaN) when the input energy overflowed: a run the caller must not call completed.
  summary.energy_balance_error = !std::isfinite(max_input)
                                     ? std::numeric_limits<double>::quiet_NaN()
                                 : max_input > 0.0 ? max_balance / max_input
                                                   : 0.0;
  summary.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

}  // namespace

RunSummary RunNewmark(const structure::Structure& structure, const Excitation& excitation,
                      const TimeGrid& grid, const NewmarkOptions& options,
                      ResponseObserver& observer) {
  return Run(structure, excitation, grid, options, observer);
}

RunSummary RunNewmark(const structure::Structure& structure, const Excitation& excitation,
                      const TimeGrid& grid, const NewmarkOptions& options,
                      ResponseHistory* response) {
  HistoryRecorder recorder = RecordHistory(structure, grid, response);
  return Run(structure, excitation, grid, options, recorder);
}

}  // namespace isolab::integrators
