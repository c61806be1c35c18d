// Access to ../shared/reference and ../shared/ground_motions, which CI has beside the checkout but
// a user's clone may not: tests that need them skip with a message when they are absent.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace isolab::testing {

inline std::filesystem::path SharedPath(const std::string& relative) {
  return std::filesystem::path(ISOLAB_SOURCE_DIR) / ".." / "shared" / relative;
}

// Rows of a numeric CSV with one header line (and '#' comment lines), as doubles; the first
// `skip_columns` columns (e.g. a test name) are left out.
inline std::vector<std::vector<double>> ReadNumericCsv(const std::filesystem::path& path,
                                                       int skip_columns = 0) {
  std::ifstream in(path);
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

// Skips the current test when a shared reference file is missing.
#define ISOLAB_REQUIRE_SHARED(path)                                                       \
  if (!std::filesystem::exists(path)) {                                                   \
    GTEST_SKIP() << "reference data " << (path).string() << " is absent (../shared/ not " \
                 << "beside this checkout)";                                              \
  }
