// Shake-table measurements of a building from CSV: a header of named columns, each with its unit,
// then one row per sample. A column's unit is a suffix of its name or follows it in brackets:
//   time_s,table_acceleration_m_s2,table_displacement_m,a1_m_s2,...,d1_m,...
//   time [s],table_acceleration [g],a1 (cm/s^2),d1 [mm],...
// (suffixes: _s, _m, _cm, _mm, _in, _m_s2, _cm_s2, _mm_s2, _in_s2, _g). Lines starting with '#'
// are comments. Errors name the file, line and column: a column without a unit, one channel
// given twice in different units, a value that is not a finite number, a time that does not
// increase or breaks the uniform step (a gap, or a time more than 0.01 of a step off the grid),
// a channel asked for in the wrong dimension, an acceleration above 10 g or a displacement beyond
// 10 m (a corrupt value), a missing channel (with the columns the file has).
#pragma once

#include <string>
#include <vector>

#include "isolab/core/units.h"

namespace isolab::io {

struct ShakeTableColumn {
  std::string name;            // without its unit: "a1", "table_acceleration"
  std::string unit;            // "m/s^2", "m", "s", "g", ...
  std::vector<double> values;  // as in the file
};

class ShakeTableData {
 public:
  // Throws InputError.
  static ShakeTableData Read(const std::string& path);

  const std::string& path() const { return path_; }
  const std::vector<double>& time() const { return time_; }  // seconds
  const std::vector<ShakeTableColumn>& columns() const { return columns_; }
  bool Has(const std::string& name) const;

  // A channel in `into`'s units, checked to be of `dimension`. Throws InputError naming the
  // column (header line) when it is missing or of another dimension.
  std::vector<double> Channel(const std::string& name, Dimension dimension,
                              const UnitSystem& into) const;

 private:
  std::string path_;
  std::vector<double> time_;
  std::vector<ShakeTableColumn> columns_;  // every column but time
  std::vector<int> header_columns_;        // 1-based column of each entry of columns_
  std::vector<int> sample_lines_;          // the file's line of each sample
  int header_line_ = 0;

  void CheckUniformStep(int column) const;  // throws InputError at the first uneven sample
};

}  // namespace isolab::io
