// The HDF5 results layout (results_file.h, docs/results.md).
#include <fmt/format.h>

#include <set>

#include "isolab/analysis/run_analysis.h"
#include "isolab/io/hdf5_file.h"
#include "isolab/io/record_attributes.h"
#include "results_sink.h"
#include "run_attributes.h"

namespace isolab::analysis {
namespace {

void WriteModelSummary(io::Hdf5File& file, const ModelSummary& m, const UnitSystem& units) {
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

void WriteRunAttributes(io::Hdf5File& file, const RunDescription& run) {
  const AnalysisSetup& setup = *run.setup;
  const integrators::RunSummary& summary = *run.summary;
  const UnitSystem& units = run.model->units;
  const double g = units.Convert(1.0, "g", dimension::kAcceleration);
  WriteProgramAttributes(file, run.version, run.model->path, units);
  io::WriteRecordAttributes(file, setup.record, g);
  WriteIntegratorAttributes(file, *run.analysis, setup.grid.dt, summary);
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

// Each peak as a scalar with its units, time and (where it has one) index.
void WritePeaks(io::Hdf5File& file, const RunDescription& run) {
  const AnalysisSetup& setup = *run.setup;
  const ResponsePeaks& peaks = *run.peaks;
  const UnitSystem& units = run.model->units;
  file.CreateGroup("peaks");
  for (const NamedPeak& p : FilePeaks(setup, peaks)) {
    const std::string path = fmt::format("peaks/{}", p.name);
    file.WriteDoubles(path, {}, std::span<const double>(&p.peak->value, 1),
                      DescribeUnits(units, p.dimension));
    file.WriteAttribute(path, "time", p.peak->time);
    if (p.peak->index >= 0) file.WriteIntegerAttribute(path, "index", p.peak->index);
  }
  if (!setup.layout.stories.empty()) {
    file.WriteAttribute("peaks/story_drift", "ratio", peaks.story_drift_ratio);
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
  file.WriteStringsAttribute("/", "output_levels", RecordedLevels(selection, *run.setup));
}

class Hdf5Sink final : public ResultsWriter::Sink {
 public:
  Hdf5Sink(const std::string& path, const std::vector<Series>& series, std::size_t expected_rows)
      : file_(path) {
    groups_ = CreateSeriesGroups(file_, series);
    for (const Series& s : series) {
      widths_.push_back(s.width());
      rows_.push_back(file_.CreateRows(s.name, s.columns.size(), s.units, expected_rows));
      if (!s.columns.empty()) file_.WriteStringsAttribute(s.name, "columns", s.columns);
    }
  }

  void Write(std::span<const std::vector<double>> blocks, std::size_t rows) override {
    for (std::size_t s = 0; s < rows_.size(); ++s) {
      rows_[s].Append(std::span<const double>(blocks[s].data(), rows * widths_[s]));
    }
  }

  void Finish(const RunDescription& run) override {
    rows_.clear();  // every dataset closed before the commit
    const AnalysisSetup& setup = *run.setup;
    if (!setup.layout.stories.empty()) {
      if (!groups_.contains("story")) file_.CreateGroup("story");
      file_.WriteDoubles("story/height", {setup.layout.story_heights.size()},
                         setup.layout.story_heights,
                         DescribeUnits(run.model->units, dimension::kLength));
    }
    WriteModelSummary(file_, setup.summary, run.model->units);
    WritePeaks(file_, run);
    file_.WriteText("model_yaml", run.model->text);
    WriteRunAttributes(file_, run);
    WriteSelectionAttributes(file_, run);
    file_.Commit();
  }

 private:
  io::Hdf5File file_;
  std::set<std::string> groups_;
  std::vector<std::size_t> widths_;
  std::vector<io::Hdf5File::Rows> rows_;
};

}  // namespace

std::unique_ptr<ResultsWriter::Sink> OpenHdf5Sink(const std::string& path,
                                                  const std::vector<Series>& series,
                                                  std::size_t expected_rows) {
  return std::make_unique<Hdf5Sink>(path, series, expected_rows);
}

}  // namespace isolab::analysis
