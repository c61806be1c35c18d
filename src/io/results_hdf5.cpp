// The HDF5 results layout (results_file.h, docs/results.md).
#include <fmt/format.h>

#include <set>

#include "isolab/io/hdf5_file.h"
#include "isolab/io/run_analysis.h"
#include "record_attributes.h"
#include "result_series.h"

namespace isolab::io {
namespace {

// Every group a series name needs ("isolator" for "isolator/force"), created once.
void CreateGroups(Hdf5File& file, const std::vector<Series>& series) {
  std::set<std::string> groups;
  for (const Series& s : series) {
    const std::size_t slash = s.name.rfind('/');
    if (slash != std::string::npos && groups.insert(s.name.substr(0, slash)).second) {
      file.CreateGroup(s.name.substr(0, slash));
    }
  }
}

// A whole history at once: contiguous, the cheapest to write. (A run that streams its output
// would append the same rows through Hdf5File::Rows instead.)
// `buffer` is reused from series to series.
void WriteSeries(Hdf5File& file, const Series& s, int rows, std::vector<double>* buffer) {
  const std::size_t width = s.width(), count = static_cast<std::size_t>(rows) * width;
  const double* values = s.rows;
  if (values == nullptr) {
    if (buffer->size() < count) buffer->resize(count);
    for (int r = 0; r < rows; ++r) s.fill(r, buffer->data() + r * width);
    values = buffer->data();
  }
  std::vector<std::size_t> dims = {static_cast<std::size_t>(rows)};
  if (!s.columns.empty()) dims.push_back(width);
  file.WriteDoubles(s.name, dims, std::span<const double>(values, count), s.units);
  if (!s.columns.empty()) file.WriteStringsAttribute(s.name, "columns", s.columns);
}

void WriteModelSummary(Hdf5File& file, const ModelSummary& m, const UnitSystem& units) {
  file.CreateGroup("model_summary");
  const auto scalar = [&](const char* name, double value, Dimension dimension) {
    file.WriteDoubles(fmt::format("model_summary/{}", name), {}, std::span<const double>(&value, 1),
                      DescribeUnits(units, dimension));
  };
  scalar("total_mass", m.total_mass, dimension::kMass);
  scalar("total_weight", m.total_weight, dimension::kForce);
  file.WriteDoubles("model_summary/fixed_base_periods", {m.fixed_base_periods.size()},
                    m.fixed_base_periods, units.time());
  scalar("trial_displacement", m.trial_displacement, dimension::kLength);
  scalar("secant_stiffness", m.secant_stiffness, dimension::kStiffness);
  scalar("isolated_period", m.isolated_period, dimension::kTime);
  scalar("pga", m.pga, dimension::kAcceleration);
}

void WriteRunAttributes(Hdf5File& file, const RunDescription& run) {
  const AnalysisSetup& setup = *run.setup;
  const integrators::RunSummary& summary = *run.summary;
  const UnitSystem& units = run.model->units;
  const double g = units.Convert(1.0, "g", dimension::kAcceleration);
  const auto integer = [&](const char* name, long value) {
    file.WriteIntegerAttribute("/", name, value);
  };
  file.WriteAttribute("/", "isolab_version", run.version);
  file.WriteAttribute("/", "model_file", run.model->path);
  file.WriteAttribute(
      "/", "units",
      fmt::format("force {}, length {}, time {}", units.force(), units.length(), units.time()));
  WriteRecordAttributes(file, setup.record, g);
  file.WriteAttribute("/", "integrator", DescribeIntegrator(*run.analysis, setup.grid.dt));
  file.WriteAttribute("/", "dt", setup.grid.dt);
  integer("steps", summary.steps);
  integer("newton_iterations", summary.newton_iterations);
  file.WriteAttribute("/", "solves_per_step", summary.SolvesPerStep());
  integer("max_iterations_in_a_step", summary.max_iterations_in_a_step);
  integer("factorisations", summary.factorisations);
  integer("step_cuts", summary.step_cuts);
  integer("ida_steps", summary.ida_steps);
  integer("events", summary.events);
  integer("jacobian_evaluations", summary.jacobian_evaluations);
  integer("error_test_failures", summary.error_test_failures);
  file.WriteAttribute("/", "wall_seconds", summary.wall_seconds);
  file.WriteAttribute("/", "termination", summary.ok() ? "completed" : "failed");
  file.WriteAttribute("/", "message", summary.message);
  file.WriteAttribute("/", "energy_balance_error", summary.energy_balance_error);
  file.WriteAttribute("/", "excitation_end", setup.excitation_end);
  file.WriteAttribute("/", "free_vibration", setup.free_vibration);
  file.WriteAttribute("/", "residual_window", setup.residual_window);
  if (setup.layout.isolation >= 0) {
    const ResponsePeaks& peaks = *run.peaks;
    file.WriteAttribute("/", "residual_isolator_displacement",
                        peaks.residual_isolator_displacement);
    file.WriteAttribute("/", "residual_oscillation", peaks.residual_oscillation);
    file.WriteAttribute("/", "isolator_displacement_at_excitation_end",
                        peaks.isolator_displacement_at_excitation_end);
  }
  std::string warnings;  // one per line: f.attrs["warnings"].splitlines()
  for (const std::string& warning : RunWarnings(run)) warnings += warning + "\n";
  file.WriteAttribute("/", "warnings", warnings);
}

}  // namespace

void WriteSeriesHdf5(Hdf5File& file, const std::vector<Series>& series, int rows) {
  CreateGroups(file, series);
  std::vector<double> buffer;
  for (const Series& s : series) WriteSeries(file, s, rows, &buffer);
}

void WriteResultsHdf5(const std::string& path, const RunDescription& run) {
  Hdf5File file(path);
  WriteSeriesHdf5(file, ResultSeries(run), run.response->rows_written);
  const AnalysisSetup& setup = *run.setup;
  if (!setup.layout.stories.empty()) {
    file.WriteDoubles("story/height", {setup.layout.story_heights.size()},
                      setup.layout.story_heights,
                      DescribeUnits(run.model->units, dimension::kLength));
  }
  WriteModelSummary(file, setup.summary, run.model->units);
  file.WriteText("model_yaml", run.model->text);
  WriteRunAttributes(file, run);
  file.Commit();
}

}  // namespace isolab::io
