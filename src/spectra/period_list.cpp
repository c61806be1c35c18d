#include "isolab/spectra/period_list.h"

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <sstream>

#include "isolab/core/errors.h"
#include "isolab/core/number.h"
#include "isolab/spectra/elastic_spectrum.h"

namespace isolab::spectra {
namespace {

double ParseNumber(const std::string& option, const std::string& text, const std::string& token) {
  std::string problem;
  const std::optional<double> value = ParseFiniteNumber(token, &problem);
  if (!value) throw InputError({option}, fmt::format("{} (in '{}')", problem, text));
  return *value;
}

std::vector<std::string> Split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  for (std::string part; std::getline(in, part, separator);) {
    const auto first = part.find_first_not_of(" \t");
    const auto last = part.find_last_not_of(" \t");
    parts.push_back(first == std::string::npos ? "" : part.substr(first, last - first + 1));
  }
  if (!text.empty() && text.back() == separator) parts.push_back("");
  return parts;
}

}  // namespace

std::vector<double> ParseNumberList(const std::string& text, const std::string& option) {
  std::vector<double> values;
  for (const std::string& token : Split(text, ','))
    values.push_back(ParseNumber(option, text, token));
  if (values.empty()) throw InputError({option}, "an empty list");
  return values;
}

std::vector<double> ParsePeriods(const std::string& text, const std::string& option) {
  const std::string form = "(START:STOP:STEP in s, or a comma-separated list)";
  std::vector<double> periods;
  if (text.find(':') != std::string::npos) {
    const std::vector<std::string> parts = Split(text, ':');
    if (parts.size() != 3) throw InputError({option}, fmt::format("'{}' is not {}", text, form));
    const double start = ParseNumber(option, text, parts[0]);
    const double stop = ParseNumber(option, text, parts[1]);
    const double step = ParseNumber(option, text, parts[2]);
    if (!(step > 0.0)) {
      throw InputError({option}, fmt::format("'{}': STEP = {:g} must be > 0 {}", text, step, form));
    }
    if (!(stop >= start)) {
      throw InputError({option}, fmt::format("'{}': STOP = {:g} must be >= START = {:g} {}", text,
                                             stop, start, form));
    }
    const double count = std::floor((stop - start) / step + 1e-9) + 1;
    if (count > 100000) {
      throw InputError({option},
                       fmt::format("'{}' gives {:g} periods (at most 100000)", text, count));
    }
    for (int k = 0; k < static_cast<int>(count); ++k) {
      // 12 digits: 0.05 + 2 x 0.05 prints as 0.15, not 0.15000000000000002.
      periods.push_back(std::stod(fmt::format("{:.12g}", start + k * step)));
    }
  } else {
    periods = ParseNumberList(text, option);
  }
  for (const double period : periods) {
    if (!(period > 0.0 && period <= kMaxSpectrumPeriod)) {
      throw InputError({option},
                       fmt::format("'{}': period {:g} s must be > 0 and at most {:g} s {}", text,
                                   period, kMaxSpectrumPeriod, form));
    }
  }
  return periods;
}

}  // namespace isolab::spectra
