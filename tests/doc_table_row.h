// A row of a docs table that a test prints as it measures: a page quotes the measured differences
// of some tests (docs/bearings.md, docs/bidirectional.md, docs/diagnosis.md), and
// scripts/doc_tables/test_printout.py reads these rows back so that scripts/check_docs.py checks
// the page's digits against the test's run. Numbers are written as the pages write them: a
// mantissa, then the exponent without a plus sign or leading zeros ("2.3e-4").
#pragma once

#include <cstdio>
#include <string>
#include <vector>

namespace isolab::testing {

// `value` in scientific notation with `decimals` digits after the point, short exponent.
inline std::string Scientific(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*e", decimals, value);
  std::string s = text;
  const auto e = s.find('e');
  std::string exponent = s.substr(e + 1);
  const bool negative = exponent[0] == '-';
  exponent.erase(0, exponent.find_first_not_of("+-0"));
  if (exponent.empty()) return s.substr(0, e);  // e+00: the mantissa alone
  return s.substr(0, e + 1) + (negative ? "-" : "") + exponent;
}

// `value` with `decimals` digits after the point.
inline std::string Fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

// `value` with `digits` significant digits, trailing zeros kept ("0.10").
inline std::string Significant(double value, int digits) {
  char text[64];
  std::snprintf(text, sizeof text, "%#.*g", digits, value);
  return text;
}

// Prints "| a | b | ... |" on a line of its own, flushed, so that it is not interleaved with
// GoogleTest's own lines.
inline void PrintTableRow(const std::vector<std::string>& cells) {
  std::string line = "|";
  for (const std::string& cell : cells) line += " " + cell + " |";
  std::printf("%s\n", line.c_str());
  std::fflush(stdout);
}

// A table's header and its separator line.
inline void PrintTableHeader(const std::vector<std::string>& columns) {
  PrintTableRow(columns);
  PrintTableRow(std::vector<std::string>(columns.size(), "---"));
}

}  // namespace isolab::testing
