// The time histories of a run, described once for every results format (HDF5 datasets, CSV
// columns): each series has a name (its HDF5 path), units, column names (none for a vector) and
// its values row by row. Private to io: results_file.h is the interface.
#pragma once

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include "isolab/io/hdf5_file.h"
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

// Rows of a row-major response matrix, copied whole.
inline Series Matrix(std::string name, std::string units, std::vector<std::string> columns,
                     const integrators::RowMatrix& matrix) {
  return {
      std::move(name), std::move(units), std::move(columns),
      [&matrix](int row, double* out) { std::copy_n(matrix.row(row).data(), matrix.cols(), out); },
      matrix.data()};
}

// One value per row.
template <typename Value>
Series Vector(std::string name, std::string units, Value value) {
  return {
      std::move(name), std::move(units), {}, [value](int row, double* out) { *out = value(row); }};
}

// Every series of a run's results, in file order (layout in results_file.h).
std::vector<Series> ResultSeries(const RunDescription& run);

// Every series' first `rows` rows as a dataset (with its groups, units and columns).
void WriteSeriesHdf5(Hdf5File& file, const std::vector<Series>& series, int rows);

// The two formats (results_file.h); WriteResultsFile chooses.
void WriteResultsHdf5(const std::string& path, const RunDescription& run);
void WriteResultsCsv(const std::string& path, const RunDescription& run);

}  // namespace isolab::io
