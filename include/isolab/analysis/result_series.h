// The time histories of a run, described once for every results format (HDF5 datasets, CSV
// columns) and every structure (layout.h): each series has a name (its HDF5 path), units, column
// names (none for a vector) and fills its values for one row of the response. The files' writers
// (results_file.h, results_writer.h) and the Python module's arrays use it.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "isolab/analysis/problem.h"
#include "isolab/analysis/response_peaks.h"
#include "isolab/integrators/response.h"
#include "isolab/model/output_selection.h"

namespace isolab::analysis {

struct Series {
  std::string name;                  // "time", "displacement", "isolator/force", ...
  std::string units;                 // "" for none
  std::vector<std::string> columns;  // empty: a vector (one value per row)
  // Writes the width() values of `row` to `out`.
  std::function<void(const integrators::ResponseRow& row, double* out)> fill;

  std::size_t width() const { return columns.empty() ? 1 : columns.size(); }
};

// The selection's levels as indices into the layout's levels (ascending, no repeats; every level
// when none are selected): 0 is the base (an SDOF's mass) when the structure stands on one, else
// floor 1; k is floor k; kRoofLevel the top. Throws InputError({key}, ...) for a level the
// structure does not have.
std::vector<int> SelectedLevels(const model::OutputSelection& selection,
                                const structure::Layout& layout, const std::string& key);

// Throws InputError({key}, ...) for a quantity the selection names that the structure cannot
// record: `isolator` without an isolation layer (a fixed base), `story` without stories (an SDOF).
// Asked for, they would leave the file without the histories its attributes name.
void CheckQuantitiesExist(const model::OutputSelection& selection, const structure::Layout& layout,
                          const std::string& key);

// What a selection writes, for the files' description of it: the quantities' names and the
// selected levels' names (both empty when it is summary-only).
std::vector<std::string> RecordedQuantities(const model::OutputSelection& selection);
std::vector<std::string> RecordedLevels(const model::OutputSelection& selection,
                                        const Problem& problem);

// The series `selection` records of a run of `problem`, in file order (layout in results_file.h);
// none when it is summary-only. Throws InputError({"output.levels"}, ...) for a level the
// structure does not have.
std::vector<Series> ResultSeries(const Problem& problem, const model::OutputSelection& selection);

}  // namespace isolab::analysis
