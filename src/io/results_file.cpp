#include "isolab/io/results_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "isolab/core/errors.h"
#include "isolab/io/atomic_file.h"
#include "results_writers.h"

namespace isolab::io {
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
  CheckOutputPath(path);
}

void WriteResultsFile(const std::string& path, const RunDescription& run) {
  if (FormatOf(path) == Format::kCsv) {
    WriteResultsCsv(path, run);
  } else {
    WriteResultsHdf5(path, run);
  }
}

std::vector<std::string> RunWarnings(const RunDescription& run) {
  std::vector<std::string> warnings = run.setup->summary.warnings;
  const std::string bearing =
      IsolatorDisplacementWarning(run.peaks->isolator_displacement.value, run.model->units);
  if (!bearing.empty()) warnings.push_back(bearing);
  return warnings;
}

}  // namespace isolab::io
