#include "isolab/integrators/ida.h"

#include <fmt/format.h>
#include <idas/idas.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_klu.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>
#include <stdexcept>

#include "blow_up.h"
#include "isolab/core/errors.h"
#include "rate_form_system.h"

namespace isolab::integrators {

void IdaOptions::Validate() const {
  if (!(relative_tolerance > 0.0 && relative_tolerance < 0.1)) {
    throw InvalidParameter({"rtol", relative_tolerance, "must be in (0, 0.1)"});
  }
  if (!(absolute_tolerance > 0.0 && std::isfinite(absolute_tolerance))) {
    throw InvalidParameter({"atol", absolute_tolerance, "must be > 0"});
  }
  if (!(max_step >= 0.0 && std::isfinite(max_step))) {
    throw InvalidParameter({"max_step", max_step, "must be >= 0 (0 for no limit)"});
  }
  if (max_steps < 1) throw InvalidParameter({"max_steps", double(max_steps), "must be >= 1"});
}

namespace {

// Owners of the SUNDIALS objects, freed in reverse order of creation.
struct ContextDeleter {
  void operator()(SUNContext context) const { SUNContext_Free(&context); }
};
struct VectorDeleter {
  void operator()(N_Vector vector) const { N_VDestroy(vector); }
};
struct MatrixDeleter {
  void operator()(SUNMatrix matrix) const { SUNMatDestroy(matrix); }
};
struct SolverDeleter {
  void operator()(SUNLinearSolver solver) const { SUNLinSolFree(solver); }
};
struct IdaDeleter {
  void operator()(void* memory) const { IDAFree(&memory); }
};
using Context = std::unique_ptr<std::remove_pointer_t<SUNContext>, ContextDeleter>;
using Vector = std::unique_ptr<std::remove_pointer_t<N_Vector>, VectorDeleter>;
using Matrix = std::unique_ptr<std::remove_pointer_t<SUNMatrix>, MatrixDeleter>;
using LinearSolver = std::unique_ptr<std::remove_pointer_t<SUNLinearSolver>, SolverDeleter>;
using IdaMemory = std::unique_ptr<void, IdaDeleter>;

// IDAGetReturnFlagName returns a malloc'd string.
std::string FlagName(int flag) {
  char* name = IDAGetReturnFlagName(flag);
  std::string text = name ? name : "unknown flag";
  std::free(name);
  return text;
}

class IdaRun {
 public:
  IdaRun(const structure::Structure& structure, const Excitation& excitation,
         const IdaOptions& options, RunSummary* summary)
      : system_(structure, excitation),
        excitation_(excitation),
        summary_(*summary),
        rtol_(options.relative_tolerance),
        atol_(options.absolute_tolerance) {
    SUNContext raw_context = nullptr;
    if (SUNContext_Create(nullptr, &raw_context) != 0) {
      throw std::runtime_error("SUNContext_Create failed");
    }
    context_.reset(raw_context);
    const sunindextype n = system_.size();
    y_.reset(Created(N_VNew_Serial(n, context_.get()), "N_VNew_Serial"));
    yp_.reset(Created(N_VNew_Serial(n, context_.get()), "N_VNew_Serial"));
    energy_.reset(Created(N_VNew_Serial(kEnergyRates, context_.get()), "N_VNew_Serial"));
    N_VConst(0.0, y_.get());
    N_VConst(0.0, energy_.get());
    system_.ConsistentDerivative(0.0, N_VGetArrayPointer(y_.get()), N_VGetArrayPointer(yp_.get()));

    const auto& pattern = system_.jacobian_pattern();
    jacobian_.reset(Created(SUNSparseMatrix(n, n, pattern.nonZeros(), CSC_MAT, context_.get()),
                            "SUNSparseMatrix"));
    solver_.reset(
        Created(SUNLinSol_KLU(y_.get(), jacobian_.get(), context_.get()), "SUNLinSol_KLU"));
    ida_.reset(Created(IDACreate(context_.get()), "IDACreate"));
    void* ida = ida_.get();
    Check(IDASetErrHandlerFn(ida, &IdaRun::KeepMessage, this), "IDASetErrHandlerFn");
    Check(IDAInit(ida, &IdaRun::Residual, 0.0, y_.get(), yp_.get()), "IDAInit");
    Check(IDASetUserData(ida, this), "IDASetUserData");
    Check(IDASStolerances(ida, options.relative_tolerance, options.absolute_tolerance),
          "IDASStolerances");
    Check(IDASetLinearSolver(ida, solver_.get(), jacobian_.get()), "IDASetLinearSolver");
    Check(IDASetJacFn(ida, &IdaRun::Jacobian), "IDASetJacFn");
    Check(IDASetMaxNumSteps(ida, options.max_steps), "IDASetMaxNumSteps");
    if (options.max_step > 0.0) Check(IDASetMaxStep(ida, options.max_step), "IDASetMaxStep");
    Check(IDAQuadInit(ida, &IdaRun::EnergyRates, energy_.get()), "IDAQuadInit");
    // The energy integrals are under error control too: the balance is a check of the
    // integration, so its terms must be as accurate as the motion.
    Check(IDAQuadSStolerances(ida, options.relative_tolerance, options.absolute_tolerance),
          "IDAQuadSStolerances");
    Check(IDASetQuadErrCon(ida, SUNTRUE), "IDASetQuadErrCon");
    roots_found_.resize(system_.root_count());
    if (system_.root_count() > 0) {
      Check(IDARootInit(ida, system_.root_count(), &IdaRun::Roots), "IDARootInit");
      // Every root function is positive while its phase holds: only a fall through zero is an
      // event, so one that starts an event at zero and then grows is never mistaken for one.
      std::vector<int> falling(system_.root_count(), -1);
      Check(IDASetRootDirection(ida, falling.data()), "IDASetRootDirection");
      Check(IDASetNoInactiveRootWarn(ida), "IDASetNoInactiveRootWarn");
    }
  }

  // Integrates to `t_out`, stopping at every excitation sample and restarting at every event.
  // False (with the summary's message set) when IDA fails.
  bool AdvanceTo(double t_out) {
    try {
      return Integrate(t_out);
    } catch (const std::runtime_error& error) {  // a failed SUNDIALS call while integrating
      summary_.message = fmt::format("at t = {:.6g}: {}", t_, error.what());
      return false;
    }
  }

  // Hands the state at grid step `step` to the observer; returns its energies.
  Energies Record(int step, ResponseObserver& observer) {
    double t = t_;
    if (step > 0) Check(IDAGetQuad(ida_.get(), &t, energy_.get()), "IDAGetQuad");
    const ResponseRow row =
        system_.Record(step, t_, N_VGetArrayPointer(y_.get()), N_VGetArrayPointer(energy_.get()));
    observer.Observe(row);
    return row.energies;
  }

  // IDA's counters restart with IDAReInit (the linear solver's only at its next solve), so they
  // are banked at each restart that followed a solve, and at the end.
  void CollectStatistics() {
    if (!solved_since_restart_) return;
    solved_since_restart_ = false;
    long steps = 0, jacobians = 0, failures = 0;
    Check(IDAGetNumSteps(ida_.get(), &steps), "IDAGetNumSteps");
    Check(IDAGetNumJacEvals(ida_.get(), &jacobians), "IDAGetNumJacEvals");
    Check(IDAGetNumErrTestFails(ida_.get(), &failures), "IDAGetNumErrTestFails");
    summary_.ida_steps += steps;
    summary_.jacobian_evaluations += jacobians;
    summary_.error_test_failures += failures;
  }

 private:
  bool Integrate(double t_out) {
    void* ida = ida_.get();
    while (t_ < t_out) {
      if (!solved_since_restart_ && !RatesInScale()) return false;
      const double stop = excitation_.NextSample(t_, t_out);
      if (stop - t_ <= 1e-10 * std::max(stop, 1.0)) {  // an event landed on the stop time
        t_ = stop;
        continue;
      }
      Check(IDASetStopTime(ida, stop), "IDASetStopTime");
      const int flag = IDASolve(ida, stop, &t_, y_.get(), yp_.get(), IDA_NORMAL);
      if (flag < 0) {
        summary_.message =
            fmt::format("IDASolve failed at t = {:.6g}: {}: {}", t_, FlagName(flag), last_message_);
        return false;
      }
      solved_since_restart_ = true;
      if (flag == IDA_ROOT_RETURN && !Restart()) return false;
    }
    return true;
  }

  // IDA's first step after a (re)start is sized from the weighted norm of the rates dy/dt: one
  // that overflows leaves it a step of zero, which it reports as a stop time "behind" the
  // current one (IDA_ILL_INPUT). Said as what it is instead: rates out of scale, where and how
  // large.
  bool RatesInScale() {
    const double* y = N_VGetArrayPointer(y_.get());
    const double* yp = N_VGetArrayPointer(yp_.get());
    const sunindextype n = N_VGetLength(yp_.get());
    double sum = 0.0, largest = 0.0;
    sunindextype at = 0;
    for (sunindextype i = 0; i < n; ++i) {
      const double weighted = yp[i] / (rtol_ * std::abs(y[i]) + atol_);
      sum += weighted * weighted;
      if (std::isfinite(largest) && !(std::abs(yp[i]) <= largest)) {  // NaN, once met, stays
        largest = std::abs(yp[i]);
        at = i;
      }
    }
    if (std::isfinite(sum)) return true;
    if (!std::isfinite(largest)) {
      summary_.message = fmt::format(
          "at t = {:.6g} the state's rate on state variable {} of {} is not finite ({}): the "
          "model's laws or loads give no defined motion there",
          t_, at + 1, n, largest);
      return false;
    }
    summary_.message = fmt::format(
        "at t = {:.6g} the state's rates are out of IDA's scale (|dy/dt| = {:.3g} per unit time "
        "on state variable {} of {}; its weighted norm with rtol {:g} and atol {:g} overflows): "
        "a mass, stiffness or load out of proportion, or a unit slip in the model",
        t_, largest, at + 1, n, rtol_, atol_);
    return false;
  }

  // At an event: switch the phases whose roots fell, put the state on their surfaces, and
  // restart IDA there (its counters restart too, so they are banked first).
  bool Restart() {
    void* ida = ida_.get();
    Check(IDAGetRootInfo(ida, roots_found_.data()), "IDAGetRootInfo");
    double t = t_;
    Check(IDAGetQuad(ida, &t, energy_.get()), "IDAGetQuad");
    double* y = N_VGetArrayPointer(y_.get());
    summary_.events += system_.SwitchPhases(roots_found_.data(), y);
    // Events that keep coming without the time moving on are a chattering phase (a law that
    // cannot decide between stick and slip): stop rather than loop. IDA cannot return a root at
    // the restart time itself, so "the same instant" is a window of a few hundred ulps.
    const bool same_instant =
        std::abs(t_ - last_event_time_) <= 1e3 * 2.2e-16 * std::max(std::abs(t_), 1.0);
    same_time_events_ = same_instant ? same_time_events_ + 1 : 0;
    last_event_time_ = t_;
    if (same_time_events_ > 100) {
      summary_.message =
          fmt::format("phase changes chatter at t = {:.9g}: over 100 events at one instant", t_);
      return false;
    }
    system_.ConsistentDerivative(t_, y, N_VGetArrayPointer(yp_.get()));
    CollectStatistics();
    Check(IDAReInit(ida, t_, y_.get(), yp_.get()), "IDAReInit");
    Check(IDAQuadReInit(ida, energy_.get()), "IDAQuadReInit");
    return true;
  }

  template <typename T>
  static T Created(T object, const char* call) {
    if (!object) throw std::runtime_error(fmt::format("{} failed (out of memory?)", call));
    return object;
  }
  void Check(int flag, const char* call) const {
    if (flag < 0) {
      throw std::runtime_error(
          fmt::format("{} failed: {}: {}", call, FlagName(flag), last_message_));
    }
  }

  static IdaRun& Of(void* user_data) { return *static_cast<IdaRun*>(user_data); }
  static int Residual(double t, N_Vector y, N_Vector yp, N_Vector r, void* user_data) {
    double* residual = N_VGetArrayPointer(r);
    Of(user_data).system_.Residual(t, N_VGetArrayPointer(y), N_VGetArrayPointer(yp), residual);
    // A non-finite residual (a trial far off) is recoverable: IDA retries with a smaller step.
    for (sunindextype i = 0; i < N_VGetLength(r); ++i) {
      if (!std::isfinite(residual[i])) return 1;
    }
    return 0;
  }
  static int Jacobian(double t, double cj, N_Vector y, N_Vector, N_Vector, SUNMatrix jacobian,
                      void* user_data, N_Vector, N_Vector, N_Vector) {
    IdaRun& run = Of(user_data);
    const auto& pattern = run.system_.jacobian_pattern();
    // IDA zeroes the whole sparse matrix, pattern included, before each call.
    sunindextype* columns = SUNSparseMatrix_IndexPointers(jacobian);
    sunindextype* rows = SUNSparseMatrix_IndexValues(jacobian);
    std::copy(pattern.outerIndexPtr(), pattern.outerIndexPtr() + pattern.cols() + 1, columns);
    std::copy(pattern.innerIndexPtr(), pattern.innerIndexPtr() + pattern.nonZeros(), rows);
    run.system_.Jacobian(t, cj, N_VGetArrayPointer(y), SUNSparseMatrix_Data(jacobian));
    return 0;
  }
  static int Roots(double, N_Vector y, N_Vector, double* roots, void* user_data) {
    Of(user_data).system_.Roots(N_VGetArrayPointer(y), roots);
    return 0;
  }
  static int EnergyRates(double t, N_Vector y, N_Vector, N_Vector rates, void* user_data) {
    Of(user_data).system_.EnergyRates(t, N_VGetArrayPointer(y), N_VGetArrayPointer(rates));
    return 0;
  }
  static void KeepMessage(int, const char*, const char* function, char* message, void* user_data) {
    Of(user_data).last_message_ = fmt::format("{}: {}", function, message);
  }

  RateFormSystem system_;
  const Excitation& excitation_;
  RunSummary& summary_;
  Context context_;
  Vector y_, yp_, energy_;
  Matrix jacobian_;
  LinearSolver solver_;
  IdaMemory ida_;
  std::vector<int> roots_found_;
  std::string last_message_;
  double rtol_, atol_;
  double t_ = 0.0;
  double last_event_time_ = -1.0;
  bool solved_since_restart_ = false;
  int same_time_events_ = 0;
};

RunSummary Run(const structure::Structure& structure, const Excitation& excitation,
               const TimeGrid& grid, const IdaOptions& options, ResponseObserver& observer) {
  options.Validate();
  if (!structure.axial_loads().empty() || !excitation.vertical.values.empty()) {
    throw std::invalid_argument(
        "IDA does not take bearings' axial loads or a vertical ground motion: run Newmark");
  }
  const auto start = std::chrono::steady_clock::now();
  RunSummary summary;
  IdaRun run(structure, excitation, options, &summary);
  const int every = std::max(grid.output_every, 1);
  const int rows = grid.steps / every + 1;
  run.Record(0, observer);
  double max_input = 0.0, max_balance = 0.0;
  for (int row = 1; row < rows; ++row) {
    if (!run.AdvanceTo(row * every * grid.dt)) {
      summary.termination = RunSummary::Termination::kFailed;
      break;
    }
    const Energies e = run.Record(row * every, observer);
    summary.steps = row * every;
    max_input = std::max(max_input, e.Supplied());
    max_balance = std::max(max_balance, std::abs(e.Balance()));
    if (ShowsBlowUp(e, max_input)) {
      summary.termination = RunSummary::Termination::kFailed;
      summary.message = fmt::format("blow-up at t = {:.6g}: {}", row * every * grid.dt,
                                    DescribeBlowUp(e, max_input));
      break;
    }
  }
  run.CollectStatistics();
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

RunSummary RunIda(const structure::Structure& structure, const Excitation& excitation,
                  const TimeGrid& grid, const IdaOptions& options, ResponseObserver& observer) {
  return Run(structure, excitation, grid, options, observer);
}

RunSummary RunIda(const structure::Structure& structure, const Excitation& excitation,
                  const TimeGrid& grid, const IdaOptions& options, ResponseHistory* response) {
  HistoryRecorder recorder = RecordHistory(structure, grid, response);
  return Run(structure, excitation, grid, options, recorder);
}

}  // namespace isolab::integrators
