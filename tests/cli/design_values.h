// A design's design_values.csv (study/design_report.h), read for the tests that check it.
#pragma once

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace isolab::testing {

// {"bound/quantity/statistic": value}, e.g. "lower/D_M/elf".
inline std::map<std::string, double> ReadDesignValues(const std::filesystem::path& path) {
  std::map<std::string, double> values;
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // header: bound,quantity,unit,statistic,value
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::string bound, quantity, unit, statistic, value;
    std::getline(row, bound, ',');
    std::getline(row, quantity, ',');
    std::getline(row, unit, ',');
    std::getline(row, statistic, ',');
    std::getline(row, value, ',');
    values[bound + "/" + quantity + "/" + statistic] = std::stod(value);
  }
  return values;
}

}  // namespace isolab::testing
