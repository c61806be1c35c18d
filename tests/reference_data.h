// The reference data validation tests read, all inside the repository, so that a fresh clone
// validates itself: the El Centro 1940 record (ground_motions/elcentro_1940_ns.at2, public
// domain) and the Bouc-Wen benchmark excerpt (tests/data/boucwen, CC BY-SA 4.0). A test whose
// data are missing fails; it never skips.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace isolab::testing {

// A file of the source tree; throws (failing the test) when it is missing.
inline std::filesystem::path BundledPath(const std::string& relative) {
  const auto path = std::filesystem::path(ISOLAB_SOURCE_DIR) / relative;
  if (!std::filesystem::exists(path)) {
    throw std::runtime_error("reference data " + path.string() + " is missing from the checkout");
  }
  return path;
}

// El Centro 1940 NS (S00E), in g at 0.02 s with a(0) = 0 at t = 0: Chopra's record.
inline std::filesystem::path ElCentroPath() {
  return BundledPath("ground_motions/elcentro_1940_ns.at2");
}

// Rows of a numeric CSV with one header line (and '#' comment lines), as doubles; the first
// `skip_columns` columns (e.g. a test name) are left out.
inline std::vector<std::vector<double>> ReadNumericCsv(const std::filesystem::path& path,
                                                       int skip_columns = 0) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path.string());
  std::vector<std::vector<double>> rows;
  bool header = true;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {
      header = false;
      continue;
    }
    std::vector<double> row;
    std::stringstream fields(line);
    int column = 0;
    for (std::string field; std::getline(fields, field, ',');) {
      if (column++ >= skip_columns) row.push_back(std::stod(field));
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace isolab::testing
