// The HDF5 results of a plan run (plan_analysis.h; docs/results.md, "Plan models"): the series
// described once, the root attributes every results file carries (run_attributes.h) and the plan's
// own.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include "isolab/analysis/plan_analysis.h"
#include "isolab/analysis/result_series.h"
#include "isolab/analysis/results_file.h"
#include "isolab/io/hdf5_file.h"
#include "run_attributes.h"

namespace isolab::analysis {
namespace {

using hysteresis::Vec2;
using integrators::ResponseHistory;
using integrators::ResponseRow;
using RowField = std::span<const double> ResponseRow::*;

constexpr int kDofs = structure::kPlanDofsPerFloor;

// Columns `first`, first + 3, ... of a response matrix with one entry per floor (`width` 1) or
// the floor's two translations (`width` 2, x then y).
Series FloorColumns(std::string name, std::string units, std::vector<std::string> columns,
                    RowField field, int first, int width) {
  return {std::move(name), std::move(units), std::move(columns),
          [field, first, width](const ResponseRow& row, double* out) {
            const std::span<const double> values = row.*field;
            for (std::size_t dof = first; dof < values.size(); dof += kDofs) {
              for (int k = 0; k < width; ++k) *out++ = values[dof + k];
            }
          }};
}

// One value per row.
Series Scalar(std::string name, std::string units,
              std::function<double(const ResponseRow&)> value) {
  return {std::move(name),
          std::move(units),
          {},
          [value = std::move(value)](const ResponseRow& row, double* out) { *out = value(row); }};
}

// Every series over the history's rows, one dataset each (the groups their names need first).
void WriteHistory(io::Hdf5File& file, const std::vector<Series>& series, const ResponseHistory& r) {
  CreateSeriesGroups(file, series);
  const std::size_t rows = static_cast<std::size_t>(r.rows_written);
  std::vector<double> buffer;
  for (const Series& s : series) {
    const std::size_t width = s.width();
    buffer.resize(rows * width);
    for (std::size_t k = 0; k < rows; ++k) {
      s.fill(r.Row(static_cast<int>(k)), buffer.data() + k * width);
    }
    std::vector<std::size_t> dims = {rows};
    if (!s.columns.empty()) dims.push_back(width);
    file.WriteDoubles(s.name, dims, buffer, s.units);
    if (!s.columns.empty()) file.WriteStringsAttribute(s.name, "columns", s.columns);
  }
}

std::vector<Series> PlanSeries(const model::PlanModelFile& model, const PlanAnalysisSetup& setup) {
  const UnitSystem& units = model.units;
  const std::string length = DescribeUnits(units, dimension::kLength);
  const std::string force = DescribeUnits(units, dimension::kForce);
  const std::string acceleration = DescribeUnits(units, dimension::kAcceleration);
  const std::string energy = fmt::format("{}*{}", units.force(), units.length());
  const structure::PlanStructure& s = setup.structure;

  std::vector<std::string> floors = {"base"}, floor_xy, isolator_xy, isolators;
  for (const structure::PlanStory& story : model.building.stories) floors.push_back(story.name);
  for (const std::string& floor : floors) {
    floor_xy.push_back(floor + ".x");
    floor_xy.push_back(floor + ".y");
  }
  for (const structure::PlanIsolator& isolator : s.isolators()) {
    isolators.push_back(isolator.name);
    isolator_xy.push_back(isolator.name + ".x");
    isolator_xy.push_back(isolator.name + ".y");
  }

  std::vector<Series> series;
  series.push_back(Scalar("time", units.time(), [](const ResponseRow& row) { return row.time; }));
  series.push_back({"ground_acceleration",
                    acceleration,
                    {"x", "y"},
                    [&setup](const ResponseRow& row, double* out) {
                      out[0] = setup.excitation.x.At(row.time);
                      out[1] = setup.excitation.y.At(row.time);
                    }});
  series.push_back(
      FloorColumns("floor/displacement", length, floor_xy, &ResponseRow::displacement, 0, 2));
  series.push_back(FloorColumns("floor/rotation", "rad", floors, &ResponseRow::displacement, 2, 1));
  series.push_back(FloorColumns("floor/absolute_acceleration", acceleration, floor_xy,
                                &ResponseRow::absolute_acceleration, 0, 2));
  series.push_back(
      {"isolator/displacement", length, isolator_xy, [&s](const ResponseRow& row, double* out) {
         for (std::size_t i = 0; i < s.isolators().size(); ++i) {
           const Vec2 u = s.IsolatorDeformation(i, row.displacement);
           *out++ = u.x;
           *out++ = u.y;
         }
       }});
  series.push_back(
      {"isolator/resultant", length, isolators, [&s](const ResponseRow& row, double* out) {
         for (std::size_t i = 0; i < s.isolators().size(); ++i) {
           *out++ = Norm(s.IsolatorDeformation(i, row.displacement));
         }
       }});
  series.push_back(
      {"isolator/force", force, isolator_xy, [&s](const ResponseRow& row, double* out) {
         const std::size_t first = s.isolator_force_column(0);
         for (std::size_t k = 0; k < 2 * s.isolators().size(); ++k) {
           *out++ = row.connection_force[first + k];
         }
       }});
  const auto energy_series = [&](const char* name, double integrators::Energies::*term) {
    series.push_back(Scalar(fmt::format("energy/{}", name), energy,
                            [term](const ResponseRow& row) { return row.energies.*term; }));
  };
  energy_series("input", &integrators::Energies::input);
  energy_series("kinetic", &integrators::Energies::kinetic);
  energy_series("damping", &integrators::Energies::damping);
  energy_series("elastic", &integrators::Energies::elastic);
  energy_series("hysteretic", &integrators::Energies::hysteretic);
  return series;
}

void WriteComponentAttributes(io::Hdf5File& file, const std::string& key,
                              const io::AppliedRecord& record, double gravity) {
  file.WriteAttribute("/", key, record.path);
  file.WriteAttribute("/", key + "_units", record.units);
  file.WriteAttribute("/", key + "_dt", record.dt);
  file.WriteAttribute("/", key + "_scale", record.scale);
  file.WriteAttribute("/", key + "_pga", record.pga);
  file.WriteAttribute("/", key + "_pga_g", record.pga / gravity);
}

}  // namespace

void CheckPlanResultsPath(const std::string& path) {
  CheckResultsPath(path);
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".csv") {
    throw InputError({path}, "plan results are written as HDF5 only (.h5, .hdf5)");
  }
}

void WritePlanResults(const std::string& path, const model::PlanModelFile& model,
                      const PlanAnalysisSetup& setup, const ResponseHistory& response,
                      const integrators::RunSummary& summary, const PlanPeaks& peaks,
                      const std::string& version) {
  CheckPlanResultsPath(path);
  const UnitSystem& units = model.units;
  io::Hdf5File file(path);
  WriteHistory(file, PlanSeries(model, setup), response);

  std::vector<double> peak_resultant;
  for (const Peak& peak : peaks.isolator_resultant) peak_resultant.push_back(peak.value);
  file.WriteDoubles("isolator/peak_resultant", {peak_resultant.size()}, peak_resultant,
                    DescribeUnits(units, dimension::kLength));
  std::vector<std::string> names;
  for (const structure::PlanIsolator& isolator : setup.structure.isolators()) {
    names.push_back(isolator.name);
  }
  file.WriteStringsAttribute("isolator/peak_resultant", "columns", names);
  std::vector<double> rotation;
  for (const Peak& peak : peaks.floor_rotation) rotation.push_back(peak.value);
  file.WriteDoubles("floor/peak_rotation", {rotation.size()}, rotation, "rad");
  file.WriteText("model_yaml", model.text);

  const double g = units.Convert(1.0, "g", dimension::kAcceleration);
  WriteProgramAttributes(file, version, model.path, units);
  file.WriteAttribute("/", "model_kind", "plan");
  WriteComponentAttributes(file, "record_h1", setup.h1, g);
  if (!setup.h2.path.empty()) WriteComponentAttributes(file, "record_h2", setup.h2, g);
  file.WriteAttribute("/", "incidence_angle", setup.angle);
  WriteIntegratorAttributes(file, model.analysis, setup.grid.dt, summary);
  file.WriteAttribute("/", "excitation_end", setup.excitation_end);
  file.WriteAttribute("/", "free_vibration", setup.free_vibration);
  file.WriteAttribute("/", "isolated_period", setup.isolated_period);
  file.WriteAttribute("/", "peak_centre_resultant", peaks.centre_resultant.value);
  file.WriteAttribute("/", "peak_isolator_resultant", peaks.largest_resultant.value);
  file.WriteAttribute("/", "torsional_amplification", peaks.torsional_amplification);
  file.WriteAttribute("/", "peak_base_shear", peaks.base_shear.value);
  file.Commit();
}

}  // namespace isolab::analysis
