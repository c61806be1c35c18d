// The HDF5 results of a plan run (plan_analysis.h; docs/results.md, "Plan models"): the series
// are described here once, written by the same writer as one-direction results.
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include "isolab/io/hdf5_file.h"
#include "isolab/io/plan_analysis.h"
#include "isolab/io/run_analysis.h"
#include "result_series.h"

namespace isolab::io {
namespace {

using hysteresis::Vec2;
using integrators::ResponseHistory;

constexpr int kDofs = structure::kPlanDofsPerFloor;

// Columns `first`, first + 3, ... of a response matrix with one entry per floor (`width` 1) or
// the floor's two translations (`width` 2, x then y).
Series FloorColumns(std::string name, std::string units, std::vector<std::string> columns,
                    const integrators::RowMatrix& matrix, int first, int width) {
  return {std::move(name), std::move(units), std::move(columns),
          [&matrix, first, width](int row, double* out) {
            for (Eigen::Index dof = first; dof < matrix.cols(); dof += kDofs) {
              for (int k = 0; k < width; ++k) *out++ = matrix(row, dof + k);
            }
          }};
}

std::vector<Series> PlanSeries(const PlanModelFile& model, const PlanAnalysisSetup& setup,
                               const ResponseHistory& r) {
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
  const auto u_row = [&r, &s](int row) {
    return std::span<const double>(r.displacement.row(row).data(), s.dofs());
  };

  std::vector<Series> series;
  series.push_back(Vector("time", units.time(), [&r](int row) { return r.time[row]; }));
  series.push_back(
      {"ground_acceleration", acceleration, {"x", "y"}, [&r, &setup](int row, double* out) {
         out[0] = setup.excitation.x.At(r.time[row]);
         out[1] = setup.excitation.y.At(r.time[row]);
       }});
  series.push_back(FloorColumns("floor/displacement", length, floor_xy, r.displacement, 0, 2));
  series.push_back(FloorColumns("floor/rotation", "rad", floors, r.displacement, 2, 1));
  series.push_back(FloorColumns("floor/absolute_acceleration", acceleration, floor_xy,
                                r.absolute_acceleration, 0, 2));
  series.push_back(
      {"isolator/displacement", length, isolator_xy, [&s, u_row](int row, double* out) {
         for (std::size_t i = 0; i < s.isolators().size(); ++i) {
           const Vec2 u = s.IsolatorDeformation(i, u_row(row));
           *out++ = u.x;
           *out++ = u.y;
         }
       }});
  series.push_back({"isolator/resultant", length, isolators, [&s, u_row](int row, double* out) {
                      for (std::size_t i = 0; i < s.isolators().size(); ++i) {
                        *out++ = Norm(s.IsolatorDeformation(i, u_row(row)));
                      }
                    }});
  series.push_back({"isolator/force", force, isolator_xy, [&s, &r](int row, double* out) {
                      const std::size_t first = s.isolator_force_column(0);
                      for (std::size_t k = 0; k < 2 * s.isolators().size(); ++k) {
                        *out++ = r.connection_force(row, first + k);
                      }
                    }});
  const auto energy_series = [&](const char* name, double integrators::Energies::*term) {
    series.push_back(Vector(fmt::format("energy/{}", name), energy,
                            [&r, term](int row) { return r.energies[row].*term; }));
  };
  energy_series("input", &integrators::Energies::input);
  energy_series("kinetic", &integrators::Energies::kinetic);
  energy_series("damping", &integrators::Energies::damping);
  energy_series("elastic", &integrators::Energies::elastic);
  energy_series("hysteretic", &integrators::Energies::hysteretic);
  return series;
}

void WriteComponentAttributes(Hdf5File& file, const std::string& key, const AppliedRecord& record,
                              double gravity) {
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

void WritePlanResults(const std::string& path, const PlanModelFile& model,
                      const PlanAnalysisSetup& setup, const ResponseHistory& response,
                      const integrators::RunSummary& summary, const PlanPeaks& peaks,
                      const std::string& version) {
  CheckPlanResultsPath(path);
  const UnitSystem& units = model.units;
  Hdf5File file(path);
  WriteSeriesHdf5(file, PlanSeries(model, setup, response), response.rows_written);

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
  file.WriteAttribute("/", "isolab_version", version);
  file.WriteAttribute("/", "model_file", model.path);
  file.WriteAttribute("/", "model_kind", "plan");
  file.WriteAttribute(
      "/", "units",
      fmt::format("force {}, length {}, time {}", units.force(), units.length(), units.time()));
  WriteComponentAttributes(file, "record_h1", setup.h1, g);
  if (!setup.h2.path.empty()) WriteComponentAttributes(file, "record_h2", setup.h2, g);
  file.WriteAttribute("/", "incidence_angle", setup.angle);
  file.WriteAttribute("/", "integrator", DescribeIntegrator(model.analysis, setup.grid.dt));
  file.WriteAttribute("/", "dt", setup.grid.dt);
  file.WriteIntegerAttribute("/", "steps", summary.steps);
  file.WriteIntegerAttribute("/", "newton_iterations", summary.newton_iterations);
  file.WriteAttribute("/", "solves_per_step", summary.SolvesPerStep());
  file.WriteIntegerAttribute("/", "step_cuts", summary.step_cuts);
  file.WriteAttribute("/", "wall_seconds", summary.wall_seconds);
  file.WriteAttribute("/", "termination", summary.ok() ? "completed" : "failed");
  file.WriteAttribute("/", "message", summary.message);
  file.WriteAttribute("/", "energy_balance_error", summary.energy_balance_error);
  file.WriteAttribute("/", "excitation_end", setup.excitation_end);
  file.WriteAttribute("/", "free_vibration", setup.free_vibration);
  file.WriteAttribute("/", "isolated_period", setup.isolated_period);
  file.WriteAttribute("/", "peak_centre_resultant", peaks.centre_resultant.value);
  file.WriteAttribute("/", "peak_isolator_resultant", peaks.largest_resultant.value);
  file.WriteAttribute("/", "torsional_amplification", peaks.torsional_amplification);
  file.WriteAttribute("/", "peak_base_shear", peaks.base_shear.value);
  file.Commit();
}

}  // namespace isolab::io
