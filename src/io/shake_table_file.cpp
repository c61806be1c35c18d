#include "isolab/io/shake_table_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <utility>

#include "csv_fields.h"
#include "isolab/core/errors.h"
#include "isolab/core/number.h"
#include "isolab/core/text_file.h"

namespace isolab::io {
namespace {

// Unit suffixes of column names, longest first so "_m_s2" is not read as "_s2".
constexpr std::pair<const char*, const char*> kSuffixes[] = {
    {"_cm_s2", "cm/s^2"}, {"_mm_s2", "mm/s^2"}, {"_in_s2", "in/s^2"}, {"_m_s2", "m/s^2"},
    {"_cm", "cm"},        {"_mm", "mm"},        {"_in", "in"},        {"_m", "m"},
    {"_s", "s"},          {"_g", "g"},
};

// "name [unit]", "name (unit)" or "name_suffix"; an empty unit when there is none.
std::pair<std::string, std::string> NameAndUnit(const std::string& header) {
  const auto open = header.find_first_of("[(");
  if (open != std::string::npos) {
    const auto close = header.find_first_of("])", open);
    const std::string unit = Trim(
        header.substr(open + 1, close == std::string::npos ? std::string::npos : close - open - 1));
    return {Trim(header.substr(0, open)), unit};
  }
  for (const auto& [suffix, unit] : kSuffixes) {
    const std::string s = suffix;
    if (header.size() > s.size() && header.compare(header.size() - s.size(), s.size(), s) == 0) {
      return {header.substr(0, header.size() - s.size()), unit};
    }
  }
  return {header, ""};
}

}  // namespace

ShakeTableData ShakeTableData::Read(const std::string& path) {
  TextLines in(path);
  if (!in.is_open()) throw InputError({path}, "cannot open the shake-table data");
  ShakeTableData data;
  data.path_ = path;
  int time_column = -1, line_number = 0, header_line = 0;
  std::vector<std::string> names;
  for (std::string line; in.Next(&line);) {
    ++line_number;
    line = Trim(line);
    if (line.empty() || line[0] == '#') continue;
    const std::vector<std::string> fields = Split(line);
    if (header_line == 0) {
      header_line = line_number;
      data.header_line_ = line_number;
      for (std::size_t k = 0; k < fields.size(); ++k) {
        const int column = static_cast<int>(k) + 1;
        auto [name, unit] = NameAndUnit(fields[k]);
        if (unit.empty()) {
          // The example in the column's own kind: the time in seconds, a channel in m/s^2.
          const bool time = Lower(fields[k]) == "time";
          throw InputError({path, line_number, column},
                           fmt::format("column '{}' has no unit (write it as a suffix, "
                                       "'{}_{}', or in brackets, '{} [{}]')",
                                       fields[k], fields[k], time ? "s" : "m_s2", fields[k],
                                       time ? "s" : "m/s^2"));
        }
        for (std::size_t j = 0; j < data.columns_.size(); ++j) {
          if (data.columns_[j].name == name) {
            throw InputError(
                {path, line_number, column},
                fmt::format("channel '{}' appears twice, in {} (column {}) and in {}: "
                            "which one is meant?",
                            name, data.columns_[j].unit, data.header_columns_[j], unit));
          }
        }
        if (name == "time") {
          if (time_column >= 0) {
            throw InputError({path, line_number, column}, "a second time column");
          }
          try {
            if (UnitSystem("kN", "m", "s").Convert(1.0, unit, dimension::kTime) != 1.0) {
              throw std::invalid_argument("time must be in seconds");
            }
          } catch (const std::invalid_argument& error) {
            throw InputError({path, line_number, column},
                             fmt::format("time in '{}': {}", unit, error.what()));
          }
          time_column = static_cast<int>(k);
        } else {
          data.columns_.push_back({name, unit, {}});
          data.header_columns_.push_back(column);
        }
        names.push_back(name);
      }
      if (time_column < 0) {
        throw InputError({path, line_number}, "no time column (expected e.g. 'time_s')");
      }
      continue;
    }
    if (fields.size() != names.size()) {
      throw InputError({path, line_number},
                       fmt::format("{} values for {} columns", fields.size(), names.size()));
    }
    std::size_t channel = 0;
    for (std::size_t k = 0; k < fields.size(); ++k) {
      std::string problem;
      const std::optional<double> parsed = ParseFiniteNumber(fields[k], &problem);
      if (!parsed) {
        throw InputError({path, line_number, static_cast<int>(k) + 1},
                         fmt::format("column '{}': {}", names[k], problem));
      }
      const double value = *parsed;
      if (static_cast<int>(k) == time_column) {
        if (!data.time_.empty() && !(value > data.time_.back())) {
          throw InputError({path, line_number, static_cast<int>(k) + 1},
                           fmt::format("time {} does not increase (the previous sample is at {})",
                                       value, data.time_.back()));
        }
        data.time_.push_back(value);
        data.sample_lines_.push_back(line_number);
      } else {
        data.columns_[channel++].values.push_back(value);
      }
    }
  }
  if (header_line == 0) throw InputError({path}, "the file is empty (expected a header line)");
  if (data.time_.size() < 2) {
    throw InputError({path, line_number},
                     fmt::format("{} samples: too short for a history", data.time_.size()));
  }
  data.CheckUniformStep(time_column + 1);
  return data;
}

// The table record written from these data must be one `isolab run` reads: evenly spaced
// samples, each within a hundredth of a step of the uniform grid (record.cpp's rule; printed
// times are rounded). A gap or a lost sample is named at its own line first, against the median
// step, which a few bad steps do not move.
void ShakeTableData::CheckUniformStep(int column) const {
  const std::size_t n = time_.size();
  std::vector<double> steps(n - 1);
  for (std::size_t k = 1; k < n; ++k) steps[k - 1] = time_[k] - time_[k - 1];
  std::nth_element(steps.begin(), steps.begin() + steps.size() / 2, steps.end());
  const double median = steps[steps.size() / 2];
  for (std::size_t k = 1; k < n; ++k) {
    const double step = time_[k] - time_[k - 1];
    if (std::abs(step - median) > 0.5 * median) {
      throw InputError({path_, sample_lines_[k], column},
                       fmt::format("time {} follows {}: a step of {:g} s where the samples are "
                                   "{:g} s apart (the median step); the samples must be evenly "
                                   "spaced: resample them, or cut the file at the gap",
                                   time_[k], time_[k - 1], step, median));
    }
  }
  const double dt = (time_.back() - time_.front()) / static_cast<double>(n - 1);
  for (std::size_t k = 1; k < n; ++k) {
    const double expected = time_.front() + static_cast<double>(k) * dt;
    if (std::abs(time_[k] - expected) > 1e-2 * dt) {
      throw InputError({path_, sample_lines_[k], column},
                       fmt::format("time {} is {:.3g} steps off the uniform step {:g} s (at most "
                                   "0.01 of a step): resample the data to a constant step",
                                   time_[k], std::abs(time_[k] - expected) / dt, dt));
    }
  }
}

bool ShakeTableData::Has(const std::string& name) const {
  return std::any_of(columns_.begin(), columns_.end(),
                     [&](const ShakeTableColumn& c) { return c.name == name; });
}

std::vector<double> ShakeTableData::Channel(const std::string& name, Dimension dimension,
                                            const UnitSystem& into) const {
  for (std::size_t j = 0; j < columns_.size(); ++j) {
    if (columns_[j].name != name) continue;
    double factor = 0.0;
    try {
      factor = into.Convert(1.0, columns_[j].unit, dimension);
    } catch (const std::invalid_argument& error) {
      throw InputError({path_, header_line_, header_columns_[j]},
                       fmt::format("channel '{}' is in {}, which is not a unit of {}", name,
                                   columns_[j].unit, DescribeDimension(dimension)));
    }
    // One corrupt cell (1e300) would pass as data and decide the displacement reference and the
    // peaks. No shake table moves a building by 10 m or shakes it at 10 g.
    const double si = UnitSystem("kN", "m", "s").Convert(1.0, columns_[j].unit, dimension);
    const double limit = dimension == dimension::kAcceleration ? 10.0 * 9.80665
                         : dimension == dimension::kLength     ? 10.0
                                                               : HUGE_VAL;
    std::vector<double> values = columns_[j].values;
    for (std::size_t k = 0; k < values.size(); ++k) {
      if (std::abs(values[k] * si) > limit) {
        throw InputError(
            {path_, sample_lines_[k], header_columns_[j]},
            fmt::format("channel '{}' = {:g} {} ({} the {} of any shake-table test: a corrupt "
                        "value?)",
                        name, values[k], columns_[j].unit,
                        dimension == dimension::kAcceleration ? "above 10 g," : "beyond 10 m,",
                        dimension == dimension::kAcceleration ? "accelerations" : "displacements"));
      }
      values[k] *= factor;
    }
    return values;
  }
  std::string available;
  for (const ShakeTableColumn& c : columns_) {
    available += fmt::format("{}{}", available.empty() ? "" : ", ", c.name);
  }
  throw InputError({path_}, fmt::format("no channel '{}' (the file has: {})", name, available));
}

}  // namespace isolab::io
