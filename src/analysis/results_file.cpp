#include "isolab/analysis/results_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>

#include "isolab/analysis/parameter_draws.h"
#include "isolab/analysis/solve.h"
#include "isolab/core/errors.h"
#include "isolab/io/atomic_file.h"
#include "results_sink.h"
#include "results_writer.h"

namespace isolab::analysis {
namespace {

enum class Format { kHdf5, kCsv };

Format FormatOf(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".h5" || extension == ".hdf5") return Format::kHdf5;
  if (extension == ".csv") return Format::kCsv;
  throw InputError({path}, fmt::format("unknown results file type '{}' (the extension chooses: "
                                       ".h5 or .hdf5 for HDF5, .csv for CSV)",
                                       extension));
}

}  // namespace

void CheckResultsPath(const std::string& path) {
  FormatOf(path);
  io::CheckOutputPath(path);
}

bool IsCsvPath(const std::string& path) { return FormatOf(path) == Format::kCsv; }

void WriteResultsFile(const std::string& path, const RunDescription& run,
                      const integrators::ResponseHistory& history) {
  RunDescription rows_as_they_are = run;
  rows_as_they_are.selection.every = history.output_every;
  // The rows are in memory already: so is the file, written out at once (results_writer.h).
  ResultsWriter writer(path, rows_as_they_are, 0, ResultsWriter::Mode::kHeld);
  for (int row = 0; row < history.rows_written; ++row) writer.Observe(history.Row(row));
  writer.Finish(*run.summary, *run.peaks);
}

HeldResultsFile::HeldResultsFile(const std::string& path, const RunDescription& run)
    : writer_(std::make_unique<ResultsWriter>(path, run, 0, ResultsWriter::Mode::kHeld)) {}

HeldResultsFile::~HeldResultsFile() = default;
HeldResultsFile::HeldResultsFile(HeldResultsFile&&) noexcept = default;
HeldResultsFile& HeldResultsFile::operator=(HeldResultsFile&&) noexcept = default;

void HeldResultsFile::Observe(const integrators::ResponseRow& row) { writer_->Observe(row); }

void HeldResultsFile::Write(const RunDescription& run) {
  writer_->Finish(run);
  writer_.reset();
}

std::vector<std::string> RunWarnings(const RunDescription& run) {
  std::vector<std::string> warnings = run.problem->summary.warnings;
  const std::string bearing =
      IsolatorDisplacementWarning(run.peaks->isolator_displacement.value, run.problem->units());
  if (!bearing.empty()) warnings.push_back(bearing);
  if (run.problem->model.identified_range) {
    const std::string range = IdentifiedRangeWarning(
        *run.problem->model.identified_range, run.peaks->isolator_displacement.value,
        run.peaks->isolator_velocity.value, run.problem->units());
    if (!range.empty()) warnings.push_back(range + PriorsBeyondRangeText(run.problem->model));
  }
  const structure::AxialLoads& axial = run.problem->structure.axial_loads();
  const ResponsePeaks& peaks = *run.peaks;
  for (std::size_t j = 0; j < peaks.first_uplift_times.size(); ++j) {
    if (peaks.first_uplift_times[j] < 0.0) continue;
    warnings.push_back(fmt::format(
        "isolator {} uplifted (axial load N <= 0, least {:.4g} {}) first at t = {:.6g} {}, for "
        "{:.4g} {} in all: it carried no shear meanwhile",
        axial.bearings[j].name, peaks.axial_load_minima[j].value, run.problem->units().force(),
        peaks.first_uplift_times[j], run.problem->units().time(), peaks.uplift_durations[j],
        run.problem->units().time()));
  }
  for (std::size_t i = 0; i < peaks.first_stop_times.size(); ++i) {
    if (peaks.first_stop_times[i] < 0.0) continue;
    const std::array<double, 4>& used = peaks.capacity_used[i];
    std::string surfaces;
    for (std::size_t k = 0; k < 4; ++k) {
      if (used[k] < 1.0 - 1e-9) continue;
      surfaces += fmt::format("{}{}", surfaces.empty() ? "" : ", ", k + 1);
    }
    warnings.push_back(fmt::format(
        "isolator {}: a triple pendulum surface reached its restrainer (its displacement "
        "capacity d_i; surfaces {}) first at t = {:.6g} {}: the bearing stiffens there",
        run.problem->layout.isolators[i].name, surfaces, peaks.first_stop_times[i],
        run.problem->units().time()));
  }
  const double error = run.summary->energy_balance_error;
  if (run.summary->ok() && error > kEnergyBalanceWarning) {
    warnings.push_back(fmt::format(
        "the energy balance closes to {:.3g} of the input energy only (more than {:g}): the step "
        "is coarse for this response; refine dt",
        error, kEnergyBalanceWarning));
  }
  return warnings;
}

}  // namespace isolab::analysis
