#include "isolab/io/record.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <span>
#include <stdexcept>
#include <string_view>

#include "isolab/core/errors.h"
#include "isolab/core/number.h"
#include "isolab/core/text_file.h"
#include "isolab/core/units.h"
#include "record_header.h"

namespace isolab::io {
namespace {

// A record's lines: one buffer holding them all, and a view of each into it (a vector's storage,
// unlike a short string's, stays where it is when the struct is moved).
struct RecordLines {
  RecordLines() = default;
  RecordLines(const RecordLines&) = delete;  // a copy's views would be the original's
  RecordLines(RecordLines&&) = default;
  std::vector<char> text;
  std::vector<std::string_view> lines;
};

RecordLines ReadLines(const std::string& path) {
  // A directory opens as a stream on Linux and reads as an empty file.
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored)) {
    throw InputError({path}, "is a directory, not a record");
  }
  TextLines in(path);
  if (!in.is_open())
    throw InputError({path}, fmt::format("cannot open ({})", std::strerror(errno)));
  RecordLines read;
  std::vector<std::size_t> ends;  // of each line in the text: views are taken once it stops growing
  for (std::string_view line; in.Next(&line);) {
    read.text.insert(read.text.end(), line.begin(), line.end());
    ends.push_back(read.text.size());
  }
  read.lines.reserve(ends.size());
  std::size_t start = 0;
  for (const std::size_t end : ends) {
    read.lines.emplace_back(read.text.data() + start, end - start);
    start = end;
  }
  return read;
}

// White space as the C locale's isspace has it, without a call per character.
bool IsBlank(char c) { return c == ' ' || (c >= '\t' && c <= '\r'); }

// Numbers of one line, split on white space and commas; an error names file, line and token.
void ParseNumbers(const std::string& path, int line_number, std::string_view line,
                  std::vector<double>* out) {
  const char* at = line.data();
  const char* const end = at + line.size();
  const auto separator = [](char c) { return IsBlank(c) || c == ','; };
  while (true) {
    while (at != end && separator(*at)) ++at;
    if (at == end) return;
    // A plain finite number ends where its token does (no separator is part of a number), so it
    // is read without finding the token's end first; anything else is ParseFiniteNumber's.
    std::size_t length = 0;
    const std::optional<double> plain =
        ReadPlainFiniteNumber(std::string_view(at, static_cast<std::size_t>(end - at)), &length);
    if (plain && (at + length == end || separator(at[length]))) {
      out->push_back(*plain);
      at += length;
      continue;
    }
    const char* token_end = at;
    while (token_end != end && !separator(*token_end)) ++token_end;
    std::string problem;
    const std::optional<double> checked =
        ParseFiniteNumber(std::string_view(at, static_cast<std::size_t>(token_end - at)), &problem);
    if (!checked) throw InputError({path, line_number}, problem);
    out->push_back(*checked);
    at = token_end;
  }
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

// A declared sample count: 64 bits, and a located error beyond them.
std::int64_t HeaderCount(const std::string& path, std::size_t line, std::string_view digits) {
  std::int64_t count = 0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), count);
  if (error != std::errc() || end != digits.data() + digits.size()) {
    throw InputError({path, static_cast<int>(line + 1)},
                     fmt::format("'{}' points is out of range (in the header)", digits));
  }
  return count;
}

// Longer header lines are not a record's: refused before anything scans them.
constexpr std::size_t kMaxHeaderLine = 4096;
// The lines where a header is sought.
constexpr std::size_t kHeaderLines = 12;

void CheckHeaderLineLengths(const std::string& path, std::span<const std::string_view> lines) {
  for (std::size_t i = 0; i < std::min(lines.size(), kHeaderLines); ++i) {
    if (lines[i].size() > kMaxHeaderLine) {
      throw InputError({path, static_cast<int>(i + 1)},
                       fmt::format("a line of {} characters where the record's header is sought "
                                   "(header lines have at most {}): is this a record?",
                                   lines[i].size(), kMaxHeaderLine));
    }
  }
}

struct Layout {
  std::string format;
  std::size_t first_data_line = 0;     // index into lines
  std::optional<std::int64_t> points;  // declared sample count
  double dt = 0.0;
  bool two_columns = false;
};

// The header's sampling step, which must be > 0: a step of 0 would read as none declared, and a
// step given beside the file would then stand in for the header's silently.
double HeaderStep(const std::string& path, std::size_t line, const std::string& text) {
  const double dt = HeaderNumber(path, line, text);
  if (!(dt > 0.0)) {
    throw InputError({path, static_cast<int>(line + 1)},
                     fmt::format("the header's sampling step DT = {} must be > 0", text));
  }
  return dt;
}

std::optional<Layout> PeerLayout(const std::string& path, std::span<const std::string_view> lines) {
  Layout layout;
  bool found = false;
  for (std::size_t i = 0; i < std::min(lines.size(), kHeaderLines); ++i) {
    const std::string_view line = lines[i];
    std::optional<HeaderSampling> sampling = FindNptsDt(line);
    if (!sampling) sampling = FindOldestSampling(line);
    if (sampling) {
      layout.points = HeaderCount(path, i, sampling->points);
      layout.dt = HeaderStep(path, i, std::string(sampling->step));
      layout.first_data_line = i + 1;
      if (layout.format.empty()) layout.format = "PEER AT2";
      found = true;
    } else if ((sampling = FindPeknoldSampling(line))) {
      layout.points = HeaderCount(path, i, sampling->points);
      layout.dt = HeaderStep(path, i, std::string(sampling->step));
      layout.format = "Peknold AT2";
      found = true;
    } else if (ContainsIgnoringCase(line, "begin data")) {
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

// The units headers name, in isolab's notation.
constexpr std::string_view kAccelerationUnits[] = {"g",      "m/s^2",  "cm/s^2",
                                                   "mm/s^2", "in/s^2", "ft/s^2"};

// An acceleration unit as headers spell it ("G", "CM/SEC/SEC", "cm/s2", "FT/S**2", "gal") in
// isolab's notation ("cm/s^2"), or empty when it is no acceleration unit isolab knows.
std::string AccelerationUnit(std::string_view written) {
  std::string unit;
  for (std::size_t i = 0; i < written.size(); ++i) {
    if (written.substr(i, 2) == "**") {
      unit += '^';
      ++i;
    } else {
      unit += static_cast<char>(std::tolower(static_cast<unsigned char>(written[i])));
    }
  }
  // Seconds spelled "sec", squares spelled "s2".
  std::string notation;
  std::size_t start = 0;
  while (start <= unit.size()) {
    std::size_t end = unit.find_first_of("/*", start);
    if (end == std::string::npos) end = unit.size();
    std::string factor = unit.substr(start, end - start);
    if (factor.rfind("sec", 0) == 0) factor.replace(0, 3, "s");
    if (factor == "s2") factor = "s^2";
    notation += factor;
    if (end < unit.size()) notation += unit[end];
    start = end + 1;
  }
  double si = 0.0;
  try {
    si = UnitSystem("N", "m", "s").Convert(1.0, notation, dimension::kAcceleration);
  } catch (const std::invalid_argument&) {
    return {};
  }
  for (const std::string_view known : kAccelerationUnits) {
    const double known_si = UnitSystem("N", "m", "s").Convert(1.0, known, dimension::kAcceleration);
    if (std::abs(si - known_si) <= 1e-12 * known_si) return std::string(known);
  }
  return notation;
}

// The units the header states, in isolab's notation, or empty when it states none. Only a units
// statement counts (a "g" in a description does not); a statement naming no unit isolab knows,
// and two statements that disagree, are refused at their lines.
std::string HeaderUnits(const std::string& path, std::span<const std::string_view> lines,
                        std::size_t first, std::size_t end, bool csv) {
  std::string units;
  std::size_t units_line = 0;
  for (std::size_t i = first; i < end; ++i) {
    const std::optional<UnitsStatement> statement =
        csv ? FindCsvUnits(lines[i]) : FindUnitsStatement(lines[i]);
    if (!statement) continue;
    const std::string unit = AccelerationUnit(statement->unit);
    if (unit.empty()) {
      throw InputError({path, static_cast<int>(i + 1)},
                       fmt::format("the units statement '{}' names no acceleration unit isolab "
                                   "knows (expected g, m/s^2, cm/s^2 or gal, mm/s^2, in/s^2, "
                                   "ft/s^2)",
                                   statement->statement));
    }
    if (!units.empty() && unit != units) {
      throw InputError({path, static_cast<int>(i + 1)},
                       fmt::format("the header states its units twice and differently: {} on "
                                   "line {} and {} here",
                                   units, units_line + 1, unit));
    }
    units = unit;
    units_line = i;
  }
  return units;
}

// A CSV record's times are read in seconds: a time column in another unit (ms, min) would
// stretch or shrink the record silently, so it is refused at the header.
void CheckCsvTimeUnit(const std::string& path, int line, std::string_view header) {
  const std::optional<UnitsStatement> time = FindCsvUnits(header.substr(0, header.find(',')));
  if (!time || time->unit.empty()) return;
  bool seconds = false;
  try {
    seconds = UnitSystem("kN", "m", "s").Convert(1.0, time->unit, dimension::kTime) == 1.0;
  } catch (const std::invalid_argument&) {
  }
  if (!seconds) {
    throw InputError({path, line}, fmt::format("the time column is in '{}': a record's times must "
                                               "be in seconds (convert them)",
                                               time->unit));
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
  const RecordLines read = ReadLines(path);
  const std::vector<std::string_view>& lines = read.lines;
  Record record;
  record.path = path;

  CheckHeaderLineLengths(path, lines);
  std::optional<Layout> layout = PeerLayout(path, lines);
  std::string header, header_units;
  if (layout) {
    for (std::size_t i = 0; i < layout->first_data_line; ++i) header.append(lines[i]).append("\n");
    header_units = HeaderUnits(path, lines, 0, layout->first_data_line, false);
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
      header = std::string(lines[first]);
      layout->format = "CSV";
      layout->first_data_line = first + 1;
      layout->two_columns = std::count(header.begin(), header.end(), ',') >= 1;
      header_units = HeaderUnits(path, lines, first, first + 1, true);
      if (layout->two_columns) CheckCsvTimeUnit(path, static_cast<int>(first + 1), header);
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
  numbers.reserve(lines.size());  // a value a line at least in most records
  int last_data_line = 0;
  for (std::size_t i = layout->first_data_line; i < lines.size(); ++i) {
    // Numbers hold no n: only a line with one can be the END DATA line.
    const bool has_n =
        lines[i].find('n') != std::string::npos || lines[i].find('N') != std::string::npos;
    if (has_n && ContainsIgnoringCase(lines[i], "end data")) {
      break;
    }
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
  if (layout->points && static_cast<std::int64_t>(record.values.size()) != *layout->points) {
    throw InputError({path, last_data_line},
                     fmt::format("the header declares {} points but the file holds {}",
                                 *layout->points, record.values.size()));
  }
  record.units = UnitsOf(path, header_units, options, &record.units_source);
  return record;
}

std::string DescribeScale(const AppliedRecord& record) {
  return record.scaled_to.empty()
             ? fmt::format("scale {:g}", record.scale)
             : fmt::format("scale {:.6g} to {}", record.scale, record.scaled_to);
}

ScaledRecord ScaleRecord(const Record& record, double scale, const UnitSystem& units,
                         const std::string& scale_given_by) {
  double factor = 0.0;
  try {
    factor = units.Convert(scale, record.units, dimension::kAcceleration);
  } catch (const std::invalid_argument& error) {
    throw InputError({record.path}, fmt::format("units '{}': {}", record.units, error.what()));
  }
  ScaledRecord scaled;
  scaled.values.reserve(record.values.size());
  for (const double a : record.values) scaled.values.push_back(a * factor);
  RequireFiniteScaledRecord(scaled.values, scale, record.path, {scale_given_by});
  scaled.pga = record.Peak() * std::abs(factor);
  return scaled;
}

void RequireFiniteScaledRecord(std::span<const double> scaled, double scale,
                               const std::string& path, const SourceLocation& scale_at,
                               const std::string& key) {
  if (std::all_of(scaled.begin(), scaled.end(), [](double a) { return std::isfinite(a); })) {
    return;
  }
  // An option names the scale already ("--scale: 1e+308: ..."); a model's line names its key.
  const std::string scale_is =
      key.empty() ? fmt::format("{:g}", scale) : fmt::format("{}scale {:g}", key, scale);
  throw InputError(scale_at, fmt::format("{}: the record {} scaled by it is not a finite number "
                                         "(a scale this large overflows)",
                                         scale_is, path));
}

double Record::Peak() const {
  double peak = 0.0;
  for (const double value : values) peak = std::max(peak, std::abs(value));
  return peak;
}

}  // namespace isolab::io
