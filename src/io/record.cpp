#include "isolab/io/record.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <optional>
#include <regex>

#include "isolab/core/errors.h"

namespace isolab::io {
namespace {

std::string Lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

std::vector<std::string> Lines(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError({path}, fmt::format("cannot open ({})", std::strerror(errno)));
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
  }
  return lines;
}

// Numbers of one line, split on white space and commas; an error names file, line and token.
void ParseNumbers(const std::string& path, int line_number, const std::string& line,
                  std::vector<double>* out) {
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (std::isspace(static_cast<unsigned char>(line[i])) || line[i] == ','))
      ++i;
    if (i >= line.size()) break;
    std::size_t end = i;
    while (end < line.size() && !std::isspace(static_cast<unsigned char>(line[end])) &&
           line[end] != ',')
      ++end;
    const std::string token = line.substr(i, end - i);
    double value = 0.0;
    const char* begin = token.data();
    if (*begin == '+') ++begin;
    const auto [last, error] = std::from_chars(begin, token.data() + token.size(), value);
    if (error != std::errc() || last != token.data() + token.size()) {
      throw InputError({path, line_number}, fmt::format("'{}' is not a number", token));
    }
    if (!std::isfinite(value)) {
      throw InputError({path, line_number}, fmt::format("'{}' is not a finite value", token));
    }
    out->push_back(value);
    i = end;
  }
}

// Units named in a header, matched as whole tokens (so "gal" is not g and "mm/s^2" is not m/s^2),
// in the spellings PEER and others use. Empty when none or more than one kind is named.
std::string UnitsFromHeader(const std::string& header) {
  static const std::regex token(R"([a-z0-9/^*.]+)");
  const std::string text = Lower(header);
  std::string found;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), token);
       it != std::sregex_iterator(); ++it) {
    std::string unit = it->str();
    while (!unit.empty() && unit.back() == '.') unit.pop_back();
    std::string canonical;
    if (unit == "g") {
      canonical = "g";
    } else if (unit == "gal" || unit == "cm/s/s" || unit == "cm/s^2" || unit == "cm/sec/sec" ||
               unit == "cm/s2" || unit == "cm/sec^2") {
      canonical = "cm/s^2";
    } else if (unit == "mm/s/s" || unit == "mm/s^2" || unit == "mm/s2") {
      canonical = "mm/s^2";
    } else if (unit == "m/s/s" || unit == "m/s^2" || unit == "m/s2" || unit == "m/sec^2") {
      canonical = "m/s^2";
    } else if (unit == "in/s/s" || unit == "in/s^2" || unit == "in/s2" || unit == "in/sec^2") {
      canonical = "in/s^2";
    }
    if (canonical.empty() || canonical == found) continue;
    if (!found.empty()) return {};  // two different units named: ambiguous
    found = canonical;
  }
  return found;
}

// A header number: Fortran's D exponent accepted, the whole token used, else a located error.
double HeaderNumber(const std::string& path, std::size_t line, std::string text) {
  std::replace(text.begin(), text.end(), 'D', 'E');
  std::replace(text.begin(), text.end(), 'd', 'E');
  double value = 0.0;
  const char* begin = text.data() + (!text.empty() && text[0] == '+' ? 1 : 0);
  const auto [last, error] = std::from_chars(begin, text.data() + text.size(), value);
  if (error != std::errc() || last != text.data() + text.size() || !std::isfinite(value)) {
    throw InputError({path, static_cast<int>(line + 1)},
                     fmt::format("'{}' in the header is not a number", text));
  }
  return value;
}

struct Layout {
  std::string format;
  std::size_t first_data_line = 0;  // index into lines
  std::optional<long> points;       // declared sample count
  double dt = 0.0;
  bool two_columns = false;
};

std::optional<Layout> PeerLayout(const std::string& path, const std::vector<std::string>& lines) {
  static const std::regex npts_dt(R"(NPTS\s*=\s*(\d+)\s*,?\s*DT\s*=\s*([0-9.eEdD+-]+))",
                                  std::regex::icase);
  static const std::regex old_style(R"(^\s*(\d+)\s+([0-9.eEdD+-]+)\s+NPTS\s*,\s*DT)",
                                    std::regex::icase);
  static const std::regex peknold(R"((\d+)\s+points at equal spacing of\s+([0-9.eEdD+-]+)\s*sec)",
                                  std::regex::icase);
  Layout layout;
  bool found = false;
  for (std::size_t i = 0; i < std::min<std::size_t>(lines.size(), 12); ++i) {
    std::smatch match;
    if (std::regex_search(lines[i], match, npts_dt) ||
        std::regex_search(lines[i], match, old_style)) {
      layout.points = static_cast<long>(HeaderNumber(path, i, match[1]));
      layout.dt = HeaderNumber(path, i, match[2]);
      layout.first_data_line = i + 1;
      if (layout.format.empty()) layout.format = "PEER AT2";
      found = true;
    } else if (std::regex_search(lines[i], match, peknold)) {
      layout.points = static_cast<long>(HeaderNumber(path, i, match[1]));
      layout.dt = HeaderNumber(path, i, match[2]);
      layout.format = "Peknold AT2";
      found = true;
    } else if (Lower(lines[i]).find("begin data") != std::string::npos) {
      layout.first_data_line = i + 1;
    }
  }
  if (!found) return std::nullopt;
  return layout;
}

}  // namespace

Record ReadRecord(const std::string& path, const RecordOptions& options) {
  const std::vector<std::string> lines = Lines(path);
  Record record;
  record.path = path;

  std::optional<Layout> layout = PeerLayout(path, lines);
  std::string header;
  if (layout) {
    for (std::size_t i = 0; i < layout->first_data_line; ++i) header += lines[i] + "\n";
  } else {
    // Columns: a header line with letters makes it CSV, else count the numbers of the first line.
    layout.emplace();
    std::size_t first = 0;
    while (first < lines.size() && lines[first].find_first_not_of(" \t") == std::string::npos)
      ++first;
    if (first == lines.size()) throw InputError({path}, "the record is empty");
    const bool has_letters =
        std::any_of(lines[first].begin(), lines[first].end(),
                    [](unsigned char c) { return std::isalpha(c) && c != 'e' && c != 'E'; });
    if (has_letters) {
      header = lines[first];
      layout->format = "CSV";
      layout->first_data_line = first + 1;
      layout->two_columns = std::count(header.begin(), header.end(), ',') >= 1;
    } else {
      std::vector<double> numbers;
      ParseNumbers(path, static_cast<int>(first + 1), lines[first], &numbers);
      layout->first_data_line = first;
      layout->two_columns = numbers.size() == 2;
      layout->format = layout->two_columns ? "two-column" : "single-column";
      if (numbers.size() > 2) {
        throw InputError({path, static_cast<int>(first + 1)},
                         fmt::format("{} values on the first line and no header: cannot tell the "
                                     "format (expected 'time value' or one value per line)",
                                     numbers.size()));
      }
    }
  }
  record.format = layout->format;
  record.description = header;

  std::vector<double> numbers;
  int last_data_line = 0;
  for (std::size_t i = layout->first_data_line; i < lines.size(); ++i) {
    if (Lower(lines[i]).find("end data") != std::string::npos) break;
    const std::size_t before = numbers.size();
    ParseNumbers(path, static_cast<int>(i + 1), lines[i], &numbers);
    if (numbers.size() > before) last_data_line = static_cast<int>(i + 1);
    if (layout->two_columns && numbers.size() != before && numbers.size() - before != 2) {
      throw InputError({path, static_cast<int>(i + 1)},
                       "expected two values, time and acceleration");
    }
  }
  if (numbers.empty()) throw InputError({path}, "the record has no samples");

  if (layout->two_columns) {
    const double t0 = numbers[0];
    for (std::size_t k = 0; k < numbers.size() / 2; ++k)
      record.values.push_back(numbers[2 * k + 1]);
    if (record.values.size() < 2) throw InputError({path}, "the record has fewer than two samples");
    record.dt = (numbers[numbers.size() - 2] - t0) / static_cast<double>(record.values.size() - 1);
    for (std::size_t k = 1; k < record.values.size(); ++k) {
      const double expected = t0 + k * record.dt;
      // Printed times are rounded (0.00333 at 300 Hz): a hundredth of a step is uniform enough.
      if (std::abs(numbers[2 * k] - expected) > 1e-2 * record.dt) {
        throw InputError({path}, fmt::format("time {} of sample {} breaks the uniform step {}; "
                                             "resample the record to a constant step",
                                             numbers[2 * k], k + 1, record.dt));
      }
    }
    if (t0 != 0.0) throw InputError({path}, fmt::format("the record starts at t = {}, not 0", t0));
  } else {
    record.values = std::move(numbers);
    record.dt = layout->dt > 0.0 ? layout->dt : options.dt;
    if (!(record.dt > 0.0)) {
      throw InputError({path}, "the sampling step is unknown: give dt for a single-column record");
    }
  }
  if (layout->points && static_cast<long>(record.values.size()) != *layout->points) {
    throw InputError({path, last_data_line},
                     fmt::format("the header declares {} points but the file holds {}",
                                 *layout->points, record.values.size()));
  }

  record.units = options.units.empty() ? UnitsFromHeader(header) : options.units;
  if (record.units.empty()) {
    throw InputError({path},
                     "the record's units are not in its header: give them (g, m/s^2, "
                     "cm/s^2, in/s^2)");
  }
  return record;
}

}  // namespace isolab::io
