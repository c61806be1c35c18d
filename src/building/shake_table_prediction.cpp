#include "isolab/building/shake_table_prediction.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "isolab/analysis/problem.h"
#include "isolab/core/errors.h"
#include "isolab/model/build_structure.h"

namespace isolab::building {
namespace {

// A column of a history, sampled at the measured times (linear between output rows).
Signal AtTimes(const integrators::ResponseHistory& history, const integrators::RowMatrix& columns,
               int column, const Signal& at) {
  const int rows = history.rows_written;
  const std::vector<double>& time = history.time;
  Signal out(at.size());
  std::size_t j = 0;
  for (std::size_t k = 0; k < at.size(); ++k) {
    while (j + 2 < static_cast<std::size_t>(rows) && time[j + 1] < at[k]) ++j;
    const std::size_t next = std::min<std::size_t>(j + 1, rows - 1);
    const double t0 = time[j], t1 = time[next];
    const double w = t1 > t0 ? std::clamp((at[k] - t0) / (t1 - t0), 0.0, 1.0) : 0.0;
    out[k] = (1 - w) * columns(j, column) + w * columns(next, column);
  }
  return out;
}

}  // namespace

std::vector<double> LevelMasses(const model::ModelFile& model) {
  const structure::LaidOutStructure built = model::BuildStructure(model);
  if (!built.layout.isolated() || built.layout.directions != 1) {
    throw InputError({model.path},
                     "the model needs a building in one direction on isolators (a shear_building "
                     "structure with a base_mass, the isolation slab, and its stories' masses) or "
                     "an sdof");
  }
  std::vector<double> masses;
  for (const structure::Level& level : built.layout.levels) {
    masses.push_back(built.structure.mass()[level.dofs[structure::kX]]);
  }
  return masses;
}

double SampleStep(const BuildingMeasurements& measured) {
  return (measured.time.back() - measured.time.front()) /
         static_cast<double>(measured.time.size() - 1);
}

analysis::RecordOverride TableRecord(const UnitSystem& units, const Signal& acceleration,
                                     double dt) {
  analysis::RecordOverride table;
  table.name = "the table's acceleration";
  io::Record& record = table.data.emplace();
  record.path = "table acceleration (measured)";
  record.format = "shake-table data";
  record.units = DescribeUnits(units, dimension::kAcceleration);
  record.units_source = "the shake-table data";
  record.dt = units.SiFactor(dimension::kTime) * dt;
  record.values = acceleration;
  return table;
}

Signal BaseShear(const std::vector<Signal>& acceleration, const std::vector<double>& masses) {
  Signal shear(acceleration.front().size(), 0.0);
  for (std::size_t l = 0; l < masses.size(); ++l) {
    for (std::size_t k = 0; k < shear.size(); ++k) shear[k] -= masses[l] * acceleration[l][k];
  }
  return shear;
}

double PeakAbs(const Signal& x) {
  double peak = 0.0;
  for (const double v : x) peak = std::max(peak, std::abs(v));
  return peak;
}

double Rms(const Signal& x) {
  double sum = 0.0;
  for (const double v : x) sum += v * v;
  return x.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(x.size()));
}

double Nrmse(const Signal& measured, const Signal& predicted) {
  double error = 0.0;
  for (std::size_t k = 0; k < measured.size(); ++k) {
    error += std::pow(predicted[k] - measured[k], 2);
  }
  return std::sqrt(error / static_cast<double>(measured.size())) / Rms(measured);
}

ShakeTablePrediction PredictShakeTable(const model::ModelFile& model,
                                       const BuildingMeasurements& measured,
                                       const analysis::SolveOptions& options) {
  const std::vector<double> masses = LevelMasses(model);
  // The table's motion as a record in the model's acceleration unit, from its first sample.
  analysis::RunOverrides overrides;
  overrides.records.push_back(
      TableRecord(model.units, measured.table_acceleration, SampleStep(measured)));
  const analysis::Problem problem = analysis::Prepare(model, overrides);

  integrators::ResponseHistory history;
  integrators::HistoryRecorder recorder =
      integrators::RecordHistory(problem.structure, problem.grid, &history);
  integrators::ResponseObserver* const also[] = {&recorder};
  ShakeTablePrediction prediction;
  prediction.summary = analysis::Solve(options, problem, also);
  if (!prediction.summary.ok()) {
    throw std::runtime_error("the prediction stopped: " + prediction.summary.run.message);
  }
  Signal at(measured.time.size());
  for (std::size_t k = 0; k < at.size(); ++k) at[k] = measured.time[k] - measured.time.front();
  const structure::Layout& layout = problem.layout;
  prediction.isolator_displacement =
      AtTimes(history, history.displacement, layout.levels.front().dofs[structure::kX], at);
  std::vector<Signal> predicted_a;
  for (const structure::Level& level : layout.levels) {
    predicted_a.push_back(
        AtTimes(history, history.absolute_acceleration, level.dofs[structure::kX], at));
  }
  prediction.roof_acceleration = predicted_a.back();
  prediction.base_shear = BaseShear(predicted_a, masses);
  prediction.measured_base_shear = BaseShear(measured.acceleration, masses);
  const UnitSystem& units = model.units;
  prediction.peaks = {
      {"peak isolator displacement", units.length(), PeakAbs(measured.displacement.front()),
       PeakAbs(prediction.isolator_displacement)},
      {"peak base shear", units.force(), PeakAbs(prediction.measured_base_shear),
       PeakAbs(prediction.base_shear)},
      {"peak roof absolute acceleration", DescribeUnits(units, dimension::kAcceleration),
       PeakAbs(measured.acceleration.back()), PeakAbs(prediction.roof_acceleration)},
  };
  prediction.nrmse_isolator_displacement =
      Nrmse(measured.displacement.front(), prediction.isolator_displacement);
  prediction.nrmse_roof_acceleration =
      Nrmse(measured.acceleration.back(), prediction.roof_acceleration);
  return prediction;
}

}  // namespace isolab::building
