// What a time-history run returns: the response sampled at the output times, and a summary in the
// manner of Ceres' Solver::Summary (termination, message, statistics, energy balance).
#pragma once

#include <cmath>

#include <Eigen/Core>
#include <span>
#include <string>
#include <vector>

#include "isolab/structure/structure.h"

namespace isolab::integrators {

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// Energy terms since the start (force*length). Input = kinetic + damping + elastic + hysteretic
// up to the integrator's balance error.
struct Energies {
  double input = 0.0;       // work of the effective loads p - M 1 a_g on the relative motion
  double kinetic = 0.0;     // of the relative motion
  double damping = 0.0;     // viscous: damping matrix and dashpot components
  double elastic = 0.0;     // recoverable energy of every law
  double hysteretic = 0.0;  // slider work of every law
  // Work of the varying axial loads on the pendulum bearings that take them
  // (structure/axial_load.h): raising N at a displaced position raises the pendulum's stored
  // energy N u^2 / (2 R) with no horizontal work. 0 without axial loads.
  double axial = 0.0;
  double Balance() const { return input + axial - kinetic - damping - elastic - hysteretic; }
  // The work supplied so far, the scale of the balance and of the blow-up check: the input's and
  // the axial loads' (a bearing landing after uplift gains kinetic energy from the latter).
  double Supplied() const { return std::abs(input) + std::abs(axial); }
};

// Steps of dt from rest, k = 0..steps; the response is recorded every `output_every` steps (an
// analysis finer than the output, e.g. 15 kHz integration of a 750 Hz record).
struct TimeGrid {
  double dt = 0.0;
  int steps = 0;
  int output_every = 1;
};

// The response at one instant of the grid, as an integrator hands it to a ResponseObserver: views
// into the integrator's own storage, valid only during the call.
struct ResponseRow {
  int step = 0;  // on the grid: 0 at rest, then every completed step of dt
  double time = 0.0;
  std::span<const double> displacement, velocity, acceleration;  // per DOF, relative
  std::span<const double> absolute_acceleration;                 // per DOF
  std::span<const double> connection_force;  // per force column of the structure's members
  std::span<const double> law_force;         // per law component
  Energies energies;
  // Per bearing of the structure's axial loads (structure/axial_load.h), the axial load N its
  // laws were scaled by over the step that reached this row (force); empty without axial loads.
  std::span<const double> axial_load{};
  // Every law's committed state (the structure's state array), where the integrator keeps them
  // (Newmark); empty otherwise.
  std::span<const hysteresis::LawState> law_states{};
};

// Sees the response as the integrator advances: Newmark calls it at rest and after every step,
// IDA at rest and at every output time of its grid (TimeGrid.output_every). What to keep (peaks,
// every N-th row, a file) is the observer's business, so a run need not hold its history.
class ResponseObserver {
 public:
  virtual ~ResponseObserver() = default;
  virtual void Observe(const ResponseRow& row) = 0;
};

// Passes every row to each of several observers, in order.
class ObserverList final : public ResponseObserver {
 public:
  explicit ObserverList(std::vector<ResponseObserver*> observers)
      : observers_(std::move(observers)) {}
  void Observe(const ResponseRow& row) override {
    for (ResponseObserver* observer : observers_) observer->Observe(row);
  }

 private:
  std::vector<ResponseObserver*> observers_;
};

// One row per output time; columns per degree of freedom, connection or law component.
struct ResponseHistory {
  std::vector<double> time;
  RowMatrix displacement, velocity, acceleration;  // relative to the ground
  RowMatrix absolute_acceleration;                 // acceleration + ground acceleration
  RowMatrix connection_force;                      // each member force column
  RowMatrix law_force;                             // each law component's force
  RowMatrix axial_load;  // each bearing's axial load (ResponseRow::axial_load); none without
  std::vector<Energies> energies;
  int rows_written = 0;  // < time.size() when the run stopped early
  int output_every = 1;  // grid steps between rows

  void Resize(int rows, int dofs, int connections, int laws, int bearings);
  // Row `row` (< rows_written) as an integrator hands it out, viewing this history's storage.
  ResponseRow Row(int row) const;
};

// Keeps every grid.output_every-th step in a ResponseHistory, sized for the whole grid: the
// in-memory path of RunNewmark and RunIda.
class HistoryRecorder final : public ResponseObserver {
 public:
  HistoryRecorder(ResponseHistory* history, const TimeGrid& grid, int dofs, int connections,
                  int laws, int bearings);
  void Observe(const ResponseRow& row) override;

 private:
  ResponseHistory& history_;
};

// A recorder sized for a run of `structure` on `grid`.
HistoryRecorder RecordHistory(const structure::Structure& structure, const TimeGrid& grid,
                              ResponseHistory* response);

struct RunSummary {
  enum class Termination { kCompleted, kFailed };
  Termination termination = Termination::kCompleted;
  std::string message;         // why a failed run stopped
  int steps = 0;               // analysis steps completed
  long newton_iterations = 0;  // over all steps and sub-steps; one linear solve each
  int max_iterations_in_a_step = 0;
  int step_cuts = 0;        // halvings performed
  long factorisations = 0;  // tangents factorised; one repeated bit for bit reuses its factors
  double energy_balance_error = 0.0;  // max |balance| / max Supplied() over the run
  // IDA only (zero for Newmark): internal steps, phase-change events located, Jacobian
  // evaluations and local error-test failures.
  long ida_steps = 0;
  long events = 0;
  long jacobian_evaluations = 0;
  long error_test_failures = 0;
  double wall_seconds = 0.0;

  bool ok() const { return termination == Termination::kCompleted; }
  // Newmark: linear solves per completed step (1 is the least a step can take; 0 before any).
  double SolvesPerStep() const { return steps > 0 ? double(newton_iterations) / steps : 0.0; }
};

}  // namespace isolab::integrators
