// The time histories of a run, described once for every results format (HDF5 datasets, CSV
// columns) and every structure (layout.h): each series has a name (its HDF5 path), units, column
// names (none for a vector) and fills its values for one row of the response. The files' writers
// (results_file.h, results_writer.h) and the Python module's arrays use it.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "isolab/analysis/problem.h"
#include "isolab/analysis/response_peaks.h"
#include "isolab/integrators/response.h"
#include "isolab/model/output_selection.h"

namespace isolab::analysis {

// The arrays of a row that columns are read from: its per-dof, per-force-column and per-law-
// component arrays, and its scalars (RowScalar).
enum class RowArray : std::uint8_t {
  kDisplacement,
  kVelocity,
  kAcceleration,
  kAbsoluteAcceleration,
  kConnectionForce,
  kLawForce,
  kScalars,
};
inline constexpr std::size_t kRowArrays = static_cast<std::size_t>(RowArray::kScalars) + 1;
enum class RowScalar : int {
  kTime,
  kInputEnergy,
  kKineticEnergy,
  kDampingEnergy,
  kElasticEnergy,
  kHystereticEnergy,
};
inline constexpr std::size_t kRowScalars =
    static_cast<std::size_t>(RowScalar::kHystereticEnergy) + 1;

// A row's arrays by RowArray (its scalars copied into one).
class RowArrays {
 public:
  explicit RowArrays(const integrators::ResponseRow& row);
  RowArrays(const RowArrays&) = delete;
  RowArrays& operator=(const RowArrays&) = delete;
  const double* operator[](RowArray array) const {
    return arrays_[static_cast<std::size_t>(array)];
  }

 private:
  std::array<double, kRowScalars> scalars_;
  std::array<const double*, kRowArrays> arrays_;
};

// A column read off one array of the row: its entry `index` itself, or (sum) factor * (0.0 + the
// sum of coefficient * entry, term by term): the arithmetic of Structure::MemberDeformation and
// SlotDeformation, so that a deformation is the same to the bit.
struct ColumnSource {
  struct Term {
    int index = 0;
    double coefficient = 0.0;
  };
  RowArray array = RowArray::kDisplacement;
  int index = 0;            // an entry's
  bool sum = false;         // a sum of `terms` rather than an entry
  std::vector<Term> terms;  // a sum's; none: 0.0
  double factor = 1.0;      // a sum's

  double Value(const double* values) const {
    return sum ? factor * Sum(terms, values) : values[index];
  }
  static double Sum(std::span<const Term> terms, const double* values) {
    double sum = 0.0;
    for (const Term& term : terms) sum += term.coefficient * values[term.index];
    return sum;
  }
};

struct Series {
  std::string name;                  // "time", "displacement", "isolator/force", ...
  std::string units;                 // "" for none
  std::vector<std::string> columns;  // empty: a vector (one value per row)
  // Writes the width() values of `row` to `out`.
  std::function<void(const integrators::ResponseRow& row, double* out)> fill;
  // Where every column is read off the row: one per column (what `fill` computes), so that a
  // writer can gather a block of rows a column at a time (results_writer.h). Empty for a series
  // computed otherwise (the ground's acceleration, a resultant).
  std::vector<ColumnSource> sources;

  std::size_t width() const { return columns.empty() ? 1 : columns.size(); }
};

// The entries a row of a run of `structure` has in `array`.
std::size_t RowArrayWidth(RowArray array, const structure::Structure& structure);

// The array of the row that `series` is, whole and in order (every entry, one a column, none
// summed), if it is one: its rows may then be stored, or viewed, as that array's.
std::optional<RowArray> WholeArray(const Series& series, const structure::Structure& structure);

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
