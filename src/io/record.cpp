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
#include <stdexcept>

#include "isolab/core/errors.h"
#include "isolab/core/number.h"
#include "isolab/io/units.h"

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
    std::string problem;
    const std::optional<double> value = ParseFiniteNumber(token, &problem);
    if (!value) throw InputError({path, line_number}, problem);
    out->push_back(*value);
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
  std::string problem;
  const std::optional<double> value = ParseFiniteNumber(text, &problem);
  if (!value) throw InputError({path, static_cast<int>(line + 1)}, problem + " (in the header)");
  return *value;
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

// Size of an acceleration unit in m/s^2; InputError naming who gave it when it is none.
double AccelerationSi(const std::string& path, const std::string& unit, const std::string& who) {
  try {
    return UnitSystem("N", "m", "s").Convert(1.0, unit, dimension::kAcceleration);
  } catch (const std::invalid_argument& error) {
    throw InputError(
        {path}, fmt::format("{}: {} (g, m/s^2, cm/s^2, mm/s^2, in/s^2, gal)", who, error.what()));
  }
}

// The units the values are in: the header's, or the ones given where the header names none. A
// header and a given unit that disagree are refused (a gal record read as m/s^2 is 100 times too
// strong).
std::string UnitsOf(const std::string& path, const std::string& header_units,
                    const RecordOptions& options, std::string* source) {
  if (!options.units.empty()) {
    const double given = AccelerationSi(path, options.units, options.units_given_by);
    if (!header_units.empty()) {
      const double declared = AccelerationSi(path, header_units, "the header");
      if (std::abs(given - declared) > 1e-9 * declared) {
        throw InputError(
            {path},
            fmt::format("its header gives the units as {} but {} gives {}: they disagree "
                        "(a factor of {:.4g}); remove the units given or correct the record",
                        header_units, options.units_given_by, options.units, given / declared));
      }
      *source = "header";
      return header_units;
    }
    *source = options.units_given_by;
    return options.units;
  }
  if (header_units.empty()) {
    throw InputError({path},
                     "the record's units are not in its header: give them (g, m/s^2, "
                     "cm/s^2, in/s^2)");
  }
  *source = "header";
  return header_units;
}

// The sampling step: the file's, or the one given where the file has none; both and different is
// an error.
double StepOf(const std::string& path, double file_dt, const std::string& file_says,
              const RecordOptions& options) {
  if (file_dt > 0.0) {
    if (options.dt > 0.0 && std::abs(options.dt - file_dt) > 1e-6 * file_dt) {
      throw InputError({path}, fmt::format("{} a step of {:g} s but {} gives {:g} s: they "
                                           "disagree; remove the step given or correct the record",
                                           file_says, file_dt, options.dt_given_by, options.dt));
    }
    return file_dt;
  }
  if (!(options.dt > 0.0)) {
    throw InputError({path}, "the sampling step is unknown: give dt for a single-column record");
  }
  return options.dt;
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

  double file_dt = layout->dt;  // the step the file declares (header) or shows (times)
  if (layout->two_columns) {
    const double t0 = numbers[0];
    for (std::size_t k = 0; k < numbers.size() / 2; ++k)
      record.values.push_back(numbers[2 * k + 1]);
    if (record.values.size() < 2) throw InputError({path}, "the record has fewer than two samples");
    file_dt = (numbers[numbers.size() - 2] - t0) / static_cast<double>(record.values.size() - 1);
    for (std::size_t k = 1; k < record.values.size(); ++k) {
      const double expected = t0 + k * file_dt;
      // Printed times are rounded (0.00333 at 300 Hz): a hundredth of a step is uniform enough.
      if (std::abs(numbers[2 * k] - expected) > 1e-2 * file_dt) {
        throw InputError({path}, fmt::format("time {} of sample {} breaks the uniform step {}; "
                                             "resample the record to a constant step",
                                             numbers[2 * k], k + 1, file_dt));
      }
    }
    if (t0 != 0.0) throw InputError({path}, fmt::format("the record starts at t = {}, not 0", t0));
  } else {
    record.values = std::move(numbers);
  }
  record.dt =
      StepOf(path, file_dt, layout->two_columns ? "its times give" : "its header gives", options);
  if (layout->points && static_cast<long>(record.values.size()) != *layout->points) {
    throw InputError({path, last_data_line},
                     fmt::format("the header declares {} points but the file holds {}",
                                 *layout->points, record.values.size()));
  }
  record.units = UnitsOf(path, UnitsFromHeader(header), options, &record.units_source);
  return record;
}

double Record::Peak() const {
  double peak = 0.0;
  for (const double value : values) peak = std::max(peak, std::abs(value));
  return peak;
}

}  // namespace isolab::io
