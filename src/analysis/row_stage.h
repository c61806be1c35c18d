// A results writer's rows between the integrator and the file. Each row, the arrays of the row
// that series read off (Series::sources) are copied whole into staging blocks: each array from
// which the series read, a term a value, at least half as many values as it holds. A series that
// reads an array not staged, or is computed otherwise (the ground's acceleration, a resultant),
// is filled from the row. When a block of rows is written, a series that is one staged array
// whole, in order (a one-direction building's displacements, velocities, accelerations) is that
// array's staging block itself, and the other staged series are gathered from the staging blocks
// a column at a time over every row of the block: runs of consecutive entries copied, sums of
// terms (deformations) evaluated as ColumnSource::Value does, to the bit. A row then costs a few
// copies of whole arrays rather than a call and a loop per series (a five-story building's 63
// values a row took about 1,140 instructions through `fill`, and take about 650 here).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "isolab/analysis/result_series.h"
#include "isolab/structure/structure.h"
#include "results_writer.h"

namespace isolab::analysis {

class RowStage {
 public:
  // For `series` of a run of `structure`, `rows` rows at a time. The series must outlive the
  // stage (their fill is called). Throws std::logic_error for a series with sources that are not
  // one per column.
  RowStage(std::span<const Series> series, const structure::Structure& structure, std::size_t rows);

  // Room for `rows` rows, keeping those kept so far.
  void Resize(std::size_t rows);
  // Keeps `row` as row `at` (< the rows there is room for).
  void Keep(const integrators::ResponseRow& row, std::size_t at);
  // Gathers the series' rows 0 .. rows - 1 from the rows kept.
  void Gather(std::size_t rows);
  // Zeros every series' rows from `rows` on (a last chunk's padding).
  void Pad(std::size_t rows);
  // Series `series`' rows, row-major, room for as many as Resize gave (after Gather).
  std::span<const double> Rows(std::size_t series) const;

 private:
  struct Staged {  // one array of the row, whole
    RowArray array;
    std::size_t width;
    ResultsWriter::Block rows;
  };
  struct Copy {  // entries first .. first + count - 1 of a staged array to consecutive columns
    std::uint32_t series, column, staged, first, count;
  };
  struct Sum {  // factor * (0.0 + the sum of terms_[begin, end)) of a staged array
    std::uint32_t series, column, staged, begin, end;
    double factor;
  };

  std::size_t StagedIndex(RowArray array, const structure::Structure& structure);

  std::span<const Series> series_;
  std::vector<Staged> staged_;
  std::vector<int> whole_;                    // per series: the staged array it is whole, or -1
  std::vector<ResultsWriter::Block> blocks_;  // per series not whole: its rows
  std::vector<std::uint32_t> computed_;       // series filled by `fill` as rows are kept
  std::vector<Copy> copies_;
  std::vector<Sum> sums_;
  std::vector<ColumnSource::Term> terms_;
};

}  // namespace isolab::analysis
