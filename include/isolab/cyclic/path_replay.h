// A model driven along a given displacement path: `isolab cyclic --path` (a measured test's
// history, one direction or two) and `--orbit` (a circle or a figure-eight), and the Python
// module's cyclic(path=...). One feature for one direction and two: a path is a list of plan
// displacements (y = 0 in one direction), the model a one-direction assembly (ParallelAssembly)
// or a plan one (PlanAssembly: a coupled law, a one-direction model's laws in their coupled
// forms, or a plan model's isolator), and one loop drives either, with the velocity by backward
// differences of the path (0 at its first sample) and the path's own time, as identification
// drives a model through test data (identification::SimulateForce), so a replay of a fitted
// model along a test is the fit's own prediction of it.
//
// With the measured force in the path: e^2 = sum |F0 - F|^2 / sum |F0|^2 (the paper's error
// for one test), the NRMSE, RMS |F0 - F| over RMS |F0| (the identification literature's, and
// what `isolab shaketable` reports: above 1 the model does worse than a force of zero), the RMS
// error over the measured force's range (peak to peak, the larger direction's in plan), and the
// peaks: a blind prediction of the test.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "isolab/core/units.h"
#include "isolab/hysteresis/parallel_assembly.h"
#include "isolab/hysteresis/plan_assembly.h"
#include "isolab/io/displacement_path_file.h"

namespace isolab::cyclic {

using hysteresis::Vec2;

struct ReplayCycle {
  int index = 0;            // 1-based
  double dissipated = 0.0;  // over the cycle (force*length)
  double peak_force = 0.0;  // largest |F| over the cycle (force)
  Vec2 displacement_at_end, force_at_end;
};

struct ReplayComparison {
  double e2 = 0.0;                                  // sum |F0 - F|^2 / sum |F0|^2
  double nrmse = 0.0;                               // RMS |F0 - F| / RMS |F0|, sqrt(e2)
  double error_over_range = 0.0;                    // RMS |F0 - F| / the measured force's range
  double peak_measured = 0.0, peak_modelled = 0.0;  // largest |F|
};

struct ReplayResult {
  std::string name;  // the path's
  bool plan = false;
  std::vector<double> time;
  std::vector<Vec2> displacement, force;  // force: the model's
  std::vector<Vec2> measured;             // empty when the path has none
  std::vector<std::string> components;
  std::vector<Vec2> component_force;  // [sample * components + component]
  std::vector<double> dissipated;     // energy dissipated since the start, per sample
  std::vector<ReplayCycle> cycles;    // an orbit's cycles; empty for a measured path
  std::optional<ReplayComparison> comparison;
  double peak_displacement = 0.0, peak_force = 0.0;  // largest |u|, |F|
};

enum class OrbitShape { kCircle, kFigureEight };

// A plan path of `cycles` cycles of `steps_per_cycle` samples, period T:
//   circle:      u = A (cos theta, sin theta), theta = 2 pi t / T, reached from rest along x in
//                a quarter period (steps_per_cycle / 4 samples) before the first cycle;
//   figure-eight: u = A (sin theta, sin 2 theta / 2), from rest at the origin.
struct OrbitProtocol {
  OrbitShape shape = OrbitShape::kCircle;
  double amplitude = 0.0;     // A (length), > 0
  double period = 1.0;        // T (time), > 0
  int cycles = 2;             // >= 1
  int steps_per_cycle = 400;  // a multiple of 4

  // Throws InvalidParameter naming the first field out of range.
  void Validate() const;
};

// The orbit as a path, and where each cycle starts (sample index; the last entry ends the last).
io::DisplacementPath OrbitPath(const OrbitProtocol& protocol, std::vector<std::size_t>* cycles);

// `cycle_starts` (from OrbitPath) fills ReplayResult::cycles. The one-direction form reads the
// path's x and refuses (std::invalid_argument) a path in two directions.
ReplayResult Replay(const hysteresis::ParallelAssembly& model, const io::DisplacementPath& path,
                    const std::vector<std::size_t>& cycle_starts = {});
ReplayResult Replay(const hysteresis::PlanAssembly& model, const io::DisplacementPath& path,
                    const std::vector<std::size_t>& cycle_starts = {});

// A one-direction model's laws as a plan assembly: each law's coupled form, or with `coupled`
// false the law along x and again along y. Throws std::invalid_argument naming a law without a
// coupled form.
hysteresis::PlanAssembly PlanFromIsolation(const hysteresis::ParallelAssembly& isolation,
                                           bool coupled);

}  // namespace isolab::cyclic
