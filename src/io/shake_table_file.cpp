#include "isolab/io/shake_table_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <utility>

#include "isolab/core/errors.h"
#include "isolab/core/number.h"

namespace isolab::io {
namespace {

std::string Trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  const auto last = text.find_last_not_of(" \t\r");
  return first == std::string::npos ? "" : text.substr(first, last - first + 1);
}

std::vector<std::string> Split(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  for (std::string field; std::getline(stream, field, ',');) fields.push_back(Trim(field));
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

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
  std::ifstream in(path);
  if (!in) throw InputError({path}, "cannot open the shake-table data");
  ShakeTableData data;
  data.path_ = path;
  int time_column = -1, line_number = 0, header_line = 0;
  std::vector<std::string> names;
  for (std::string line; std::getline(in, line);) {
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
          throw InputError({path, line_number, column},
                           fmt::format("column '{}' has no unit (write it as a suffix, "
                                       "'{}_m_s2', or in brackets, '{} [m/s^2]')",
                                       fields[k], fields[k], fields[k]));
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
  return data;
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
    std::vector<double> values = columns_[j].values;
    for (double& v : values) v *= factor;
    return values;
  }
  std::string available;
  for (const ShakeTableColumn& c : columns_) {
    available += fmt::format("{}{}", available.empty() ? "" : ", ", c.name);
  }
  throw InputError({path_}, fmt::format("no channel '{}' (the file has: {})", name, available));
}

}  // namespace isolab::io
