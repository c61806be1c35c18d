// The CSV of a tabulated target spectrum (target_spectrum_file.h).
#include "isolab/io/target_spectrum_file.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <optional>
#include <system_error>
#include <vector>

#include "csv_fields.h"
#include "isolab/core/errors.h"
#include "isolab/core/number.h"
#include "isolab/core/text_file.h"

namespace isolab::io {

namespace {
constexpr std::size_t kMaxTargetRows = 10000;
}  // namespace

spectra::TabulatedSpectrum ReadTargetSpectrumCsv(const std::string& path) {
  std::error_code ignored;  // a directory opens as a stream on Linux and reads as empty
  if (std::filesystem::is_directory(path, ignored)) {
    throw InputError({path}, "is a directory, not a target spectrum");
  }
  TextLines in(path);
  if (!in.is_open()) {
    throw InputError({path},
                     fmt::format("cannot open the target spectrum ({})", std::strerror(errno)));
  }
  spectra::TabulatedSpectrum table;
  table.source = path;
  bool header = false;
  for (std::string line; in.Next(&line);) {
    const int line_number = in.line_number();
    line = Trim(line);
    if (line.empty() || line[0] == '#') continue;
    const std::vector<std::string> fields = Split(line);
    if (!header) {
      if (fields.size() != 2 || Lower(fields[0]) != "period_s" || Lower(fields[1]) != "sa_g") {
        throw InputError({path, line_number},
                         fmt::format("header '{}' (expected period_s,sa_g: the period in s and "
                                     "the pseudo-acceleration in g)",
                                     line));
      }
      header = true;
      continue;
    }
    if (fields.size() != 2) {
      throw InputError({path, line_number},
                       fmt::format("{} fields (expected 2: period_s,sa_g)", fields.size()));
    }
    const auto number = [&](std::size_t column, const char* name) {
      std::string problem;
      const std::optional<double> value = ParseFiniteNumber(fields[column], &problem);
      if (!value) throw InputError({path, line_number}, fmt::format("{}: {}", name, problem));
      return *value;
    };
    const double period = number(0, "period_s");
    const double sa = number(1, "sa_g");
    if (period < 0.0) {
      throw InputError({path, line_number}, fmt::format("period_s {:g} (expected >= 0)", period));
    }
    if (!table.periods.empty() && !(period > table.periods.back())) {
      throw InputError({path, line_number},
                       fmt::format("period_s {:g} does not increase from the previous row's "
                                   "{:g} (expected strictly increasing periods)",
                                   period, table.periods.back()));
    }
    if (sa < 0.0) {
      throw InputError({path, line_number}, fmt::format("sa_g {:g} (expected >= 0)", sa));
    }
    if (table.periods.size() == kMaxTargetRows) {
      throw InputError({path, line_number},
                       fmt::format("more than {} rows (a design spectrum is a few dozen points; "
                                   "a design evaluates it at every scaling period)",
                                   kMaxTargetRows));
    }
    table.periods.push_back(period);
    table.sa.push_back(sa);
  }
  if (!header) {
    throw InputError({path}, "no header (expected a line period_s,sa_g, then one row per period)");
  }
  if (table.periods.size() < 2) {
    throw InputError({path}, fmt::format("{} row(s) of period_s,sa_g (expected at least 2: Sa is "
                                         "interpolated between them)",
                                         table.periods.size()));
  }
  return table;
}

}  // namespace isolab::io
