// The time histories of a run, described once for every results format (HDF5 datasets, CSV
// columns, the Python module's arrays): each series has a name (its HDF5 path), units, column
// names (none for a vector) and its values row by row.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "isolab/io/results_file.h"

namespace isolab::io {

struct Series {
  std::string name;                  // "time", "displacement", "isolator/force", ...
  std::string units;                 // "" for none
  std::vector<std::string> columns;  // empty: a vector (one value per row)
  // Writes the width() values of output row `row` to `out`.
  std::function<void(int row, double* out)> fill;
  // The rows themselves, row-major, when they are stored so (a response matrix): writers may
  // read them from here instead of copying them through `fill`.
  const double* rows = nullptr;

  std::size_t width() const { return columns.empty() ? 1 : columns.size(); }
};

// Every series of a run's results, in file order (layout in results_file.h). The series refer to
// `run`'s response and setup, which must outlive them.
std::vector<Series> ResultSeries(const RunDescription& run);

}  // namespace isolab::io
