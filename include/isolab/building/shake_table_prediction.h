// A building model run under a shake table's measured motion and compared with the measured floor
// responses: the blind prediction of a shake-table test (`isolab shaketable --predict`, the
// Python module). Measurements and prediction are in model units, levels bottom (the isolation
// slab) to roof; the model must stand on isolators and move in one direction, as a one-direction
// table test does.
#pragma once

#include <string>
#include <vector>

#include "isolab/analysis/problem.h"
#include "isolab/analysis/solve.h"
#include "isolab/model/model_file.h"

namespace isolab::building {

using Signal = std::vector<double>;

struct BuildingMeasurements {
  Signal time;                // (the model's time unit), from the first sample
  Signal table_acceleration;  // the table's absolute acceleration
  // A force-driven test instead (the Bouc-Wen benchmark's form): the force applied to level 1,
  // the ground still (table_acceleration empty), so displacements are relative to a fixed frame.
  Signal applied_force;
  std::vector<Signal> acceleration;  // each level's absolute acceleration
  std::vector<Signal> displacement;  // each level's displacement relative to the table
};

// Each level's mass, bottom to roof, of a model standing on isolators in one direction (an sdof:
// its one mass). Throws InputError (naming the model) for any other.
std::vector<double> LevelMasses(const model::ModelFile& model);

// The measurements' sampling step (time): their span over the intervals.
double SampleStep(const BuildingMeasurements& measured);

// The table's measured acceleration (in the model's units, sampled every `dt` of its time unit)
// as a run's record.
analysis::RecordOverride TableRecord(const UnitSystem& units, const Signal& acceleration,
                                     double dt);

// Minus the sum over levels of mass x absolute acceleration: the force the isolators carry.
Signal BaseShear(const std::vector<Signal>& acceleration, const std::vector<double>& masses);
double PeakAbs(const Signal& x);
double Rms(const Signal& x);  // 0 for an empty signal
// RMS of the difference over the RMS of the measured history.
double Nrmse(const Signal& measured, const Signal& predicted);

struct ComparedPeak {
  std::string quantity, unit;
  double measured = 0.0, predicted = 0.0;
};

struct ShakeTablePrediction {
  analysis::Summary summary;  // of the run
  // Predicted at the measured times: the isolator's displacement, the roof's absolute
  // acceleration and the base shear (from the predicted floor accelerations, as measured).
  Signal isolator_displacement, roof_acceleration, base_shear;
  Signal measured_base_shear;
  std::vector<ComparedPeak> peaks;  // isolator displacement, base shear, roof acceleration
  double nrmse_isolator_displacement = 0.0, nrmse_roof_acceleration = 0.0;
};

// Runs `model` (with `options`: its integrator, and a results file when asked) under the measured
// table acceleration, from rest, and compares. Throws InputError for a model it cannot predict
// with, and std::runtime_error when the run stops early.
ShakeTablePrediction PredictShakeTable(const model::ModelFile& model,
                                       const BuildingMeasurements& measured,
                                       const analysis::SolveOptions& options);

}  // namespace isolab::building
