// The HDF5 results layout (results_file.h, docs/results.md).
#include <fmt/format.h>

#include <set>

#include "isolab/analysis/solve.h"
#include "isolab/analysis/summary_peaks.h"
#include "isolab/io/hdf5_file.h"
#include "isolab/io/record_attributes.h"
#include "results_sink.h"
#include "run_attributes.h"

namespace isolab::analysis {
namespace {

// Periods (a dataset) with their modes' directions (its "directions" attribute).
void WriteModes(io::Hdf5File& file, const std::string& name, const std::vector<Mode>& modes,
                const UnitSystem& units) {
  std::vector<double> periods;
  std::vector<std::string> directions;
  for (const Mode& mode : modes) {
    periods.push_back(mode.period);
    directions.push_back(mode.direction);
  }
  file.WriteDoubles(name, {periods.size()}, periods, units.time());
  file.WriteStringsAttribute(name, "directions", directions);
}

void WriteModelSummary(io::Hdf5File& file, const ModelSummary& m, const UnitSystem& units) {
  file.CreateGroup("model_summary");
  const auto scalar = [&](const char* name, double value, Dimension dimension) {
    file.WriteDoubles(fmt::format("model_summary/{}", name), {}, std::span<const double>(&value, 1),
                      DescribeUnits(units, dimension));
  };
  scalar("total_mass", m.total_mass, dimension::kMass);
  scalar("total_weight", m.total_weight, dimension::kForce);
  WriteModes(file, "model_summary/fixed_base_periods", m.fixed_base_modes, units);
  WriteModes(file, "model_summary/rigid_periods", m.rigid_modes, units);
  WriteModes(file, "model_summary/isolated_periods", m.isolated_modes, units);
  scalar("trial_displacement", m.trial_displacement, dimension::kLength);
  scalar("secant_stiffness", m.secant_stiffness, dimension::kStiffness);
  scalar("isolated_period", m.isolated_period, dimension::kTime);
  scalar("pga", m.pga, dimension::kAcceleration);
}

void WriteRunAttributes(io::Hdf5File& file, const RunDescription& run) {
  const Problem& problem = *run.problem;
  const integrators::RunSummary& summary = *run.summary;
  const UnitSystem& units = problem.units();
  const double g = units.Convert(1.0, "g", dimension::kAcceleration);
  WriteProgramAttributes(file, run.version, problem.model.path, units);
  io::WriteRecordAttributes(file,
                            problem.records.empty() ? io::AppliedRecord{} : problem.records[0], g);
  if (problem.records.size() > 1)
    io::WriteRecordAttributes(file, problem.records[1], g, "record_h2");
  if (const std::optional<double> angle = problem.IncidenceAngle()) {
    file.WriteAttribute("/", "incidence_angle", *angle);
  }
  WriteIntegratorAttributes(file, *run.analysis, problem.grid.dt, summary);
  file.WriteAttribute("/", "excitation_end", problem.excitation_end);
  file.WriteAttribute("/", "free_vibration", problem.free_vibration);
  file.WriteAttribute("/", "residual_window", problem.residual_window);
  if (problem.layout.rotations) {
    file.WriteAttribute("/", "torsional_amplification", run.peaks->torsional_amplification);
  }
  if (problem.layout.isolated()) {
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

// Each peak as a scalar with its units, time and (where it has one) index.
void WritePeaks(io::Hdf5File& file, const RunDescription& run) {
  const Problem& problem = *run.problem;
  const ResponsePeaks& peaks = *run.peaks;
  const UnitSystem& units = problem.units();
  file.CreateGroup("peaks");
  for (const NamedPeak& p : SummaryPeaks(problem.layout, peaks)) {
    const std::string path = fmt::format("peaks/{}", p.name);
    file.WriteDoubles(path, {}, std::span<const double>(&p.peak->value, 1),
                      PeakUnit(units, p.dimension));
    file.WriteAttribute(path, "time", p.peak->time);
    if (p.peak->index >= 0) file.WriteIntegerAttribute(path, "index", p.peak->index);
  }
  if (!problem.layout.stories.empty()) {
    file.WriteAttribute("peaks/story_drift", "ratio", peaks.story_drift_ratio);
  }
  if (problem.layout.isolated()) {
    // Each isolator's peak displacement, force and residual, in the layout's order.
    std::vector<std::string> names;
    for (const structure::IsolatorLayout& isolator : problem.layout.isolators) {
      names.push_back(isolator.name);
    }
    const auto values = [](const std::vector<Peak>& list) {
      std::vector<double> v;
      for (const Peak& peak : list) v.push_back(peak.value);
      return v;
    };
    const std::string length = DescribeUnits(units, dimension::kLength);
    file.CreateGroup("peaks/isolators");
    file.WriteDoubles("peaks/isolators/displacement", {names.size()},
                      values(peaks.isolator_displacements), length);
    file.WriteDoubles("peaks/isolators/force", {names.size()}, values(peaks.isolator_forces),
                      DescribeUnits(units, dimension::kForce));
    file.WriteDoubles("peaks/isolators/residual", {names.size()}, peaks.isolator_residuals, length);
    for (const char* name : {"displacement", "force", "residual"}) {
      file.WriteStringsAttribute(fmt::format("peaks/isolators/{}", name), "columns", names);
    }
  }
  const structure::AxialLoads& axial = problem.structure.axial_loads();
  if (!axial.empty()) {
    // Per bearing that takes an axial load, in /isolator/axial_load's column order: the JSON
    // summary's axial_loads (first_uplift -1: never uplifted).
    std::vector<std::string> names;
    std::vector<double> statics, minima, minimum_times, maxima;
    for (std::size_t j = 0; j < axial.bearings.size(); ++j) {
      names.push_back(axial.bearings[j].name);
      statics.push_back(axial.bearings[j].static_load);
      minima.push_back(peaks.axial_load_minima[j].value);
      minimum_times.push_back(peaks.axial_load_minima[j].time);
      maxima.push_back(peaks.axial_load_maxima[j].value);
    }
    const std::string force = DescribeUnits(units, dimension::kForce);
    const std::string time = DescribeUnits(units, dimension::kTime);
    struct Column {
      const char* name;
      const std::vector<double>& values;
      const std::string& units;
    };
    const Column columns[] = {{"static", statics, force},
                              {"minimum", minima, force},
                              {"minimum_time", minimum_times, time},
                              {"maximum", maxima, force},
                              {"uplift_duration", peaks.uplift_durations, time},
                              {"first_uplift", peaks.first_uplift_times, time}};
    file.CreateGroup("peaks/axial_loads");
    for (const Column& column : columns) {
      const std::string path = fmt::format("peaks/axial_loads/{}", column.name);
      file.WriteDoubles(path, {names.size()}, column.values, column.units);
      file.WriteStringsAttribute(path, "columns", names);
    }
  }
  file.CreateGroup("final_energy");
  const std::string energy = fmt::format("{}*{}", units.force(), units.length());
  const auto term = [&](const char* name, double value) {
    file.WriteDoubles(fmt::format("final_energy/{}", name), {}, std::span<const double>(&value, 1),
                      energy);
  };
  term("input", peaks.energies.input);
  term("kinetic", peaks.energies.kinetic);
  term("damping", peaks.energies.damping);
  term("elastic", peaks.energies.elastic);
  term("hysteretic", peaks.energies.hysteretic);
}

// What the histories hold: every how many steps, which quantities and levels.
void WriteSelectionAttributes(io::Hdf5File& file, const RunDescription& run) {
  const model::OutputSelection& selection = run.selection;
  file.WriteIntegerAttribute("/", "output_every", selection.every);
  file.WriteIntegerAttribute("/", "summary_only", selection.summary_only ? 1 : 0);
  file.WriteStringsAttribute("/", "output_quantities", RecordedQuantities(selection));
  file.WriteStringsAttribute("/", "output_levels", RecordedLevels(selection, *run.problem));
}

class Hdf5Sink final : public ResultsWriter::Sink {
 public:
  Hdf5Sink(const std::string& path, const std::vector<Series>& series, std::size_t chunk_rows,
           std::size_t expected_rows)
      : file_(path), chunk_rows_(chunk_rows) {
    groups_ = CreateSeriesGroups(file_, series);
    for (const Series& s : series) {
      widths_.push_back(s.width());
      rows_.push_back(
          file_.CreateRows(s.name, s.columns.size(), s.units, chunk_rows, expected_rows));
      if (!s.columns.empty()) file_.WriteStringsAttribute(s.name, "columns", s.columns);
    }
  }

  void Write(std::span<const std::span<const double>> blocks, std::size_t rows) override {
    for (std::size_t s = 0; s < rows_.size(); ++s) {
      const std::span<const double> block = blocks[s];
      if (rows < chunk_rows_) {
        rows_[s].AppendLastChunk(block.first(chunk_rows_ * widths_[s]), rows);
      } else {
        rows_[s].Append(block.first(rows * widths_[s]));
      }
    }
  }

  void Finish(const RunDescription& run) override {
    for (io::Hdf5File::Rows& rows : rows_) rows.Close();  // trimmed and closed before the commit
    rows_.clear();
    const Problem& problem = *run.problem;
    if (!problem.layout.stories.empty()) {
      if (!groups_.contains("story")) file_.CreateGroup("story");
      std::vector<double> heights;
      for (const structure::StoryLayout& story : problem.layout.stories) {
        heights.push_back(story.height);
      }
      file_.WriteDoubles("story/height", {heights.size()}, heights,
                         DescribeUnits(problem.units(), dimension::kLength));
    }
    WriteModelSummary(file_, problem.summary, problem.units());
    WritePeaks(file_, run);
    file_.WriteText("model_yaml", problem.model.text);
    WriteRunAttributes(file_, run);
    WriteSelectionAttributes(file_, run);
    file_.Commit();
  }

 private:
  io::Hdf5File file_;
  std::size_t chunk_rows_;
  std::set<std::string> groups_;
  std::vector<std::size_t> widths_;
  std::vector<io::Hdf5File::Rows> rows_;
};

}  // namespace

std::unique_ptr<ResultsWriter::Sink> OpenHdf5Sink(const std::string& path,
                                                  const std::vector<Series>& series,
                                                  std::size_t chunk_rows,
                                                  std::size_t expected_rows) {
  return std::make_unique<Hdf5Sink>(path, series, chunk_rows, expected_rows);
}

}  // namespace isolab::analysis
