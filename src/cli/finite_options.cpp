#include "finite_options.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>

#include "isolab/core/number.h"

namespace isolab::cli {
namespace {

// Whole bounds in full (2147483647, not 2.14748e+09), others in the shortest form.
std::string Bound(double value) {
  return value == std::floor(value) && std::abs(value) < 1e15 ? fmt::format("{:.0f}", value)
                                                              : fmt::format("{:g}", value);
}

// CLI11 reads integers in the base their prefix gives (strtoll base 0): "010" as 8 and "0x10" as
// 16, so a seed padded with a zero silently drew another record. A whole number is decimal digits
// with an optional minus sign (none on a count that cannot be negative) and no leading zero, and
// fits in 64 bits (an unsigned value past them was saturated, a negative one wrapped).
std::string WholeNumberProblem(const std::string& text, bool is_unsigned) {
  const bool negative = text.starts_with('-');
  const std::string_view digits = std::string_view(text).substr(negative ? 1 : 0);
  const bool decimal = !digits.empty() && std::all_of(digits.begin(), digits.end(), [](char c) {
    return c >= '0' && c <= '9';
  }) && (digits.size() == 1 || digits[0] != '0');
  if (!decimal) {
    return fmt::format("'{}' is not a whole number in decimal digits (no leading zero)", text);
  }
  if (negative && is_unsigned) return fmt::format("{} (must be a whole number >= 0)", text);
  std::int64_t signed_value = 0;
  std::uint64_t unsigned_value = 0;
  const std::errc error =
      is_unsigned ? std::from_chars(digits.data(), digits.data() + digits.size(), unsigned_value).ec
                  : std::from_chars(text.data(), text.data() + text.size(), signed_value).ec;
  if (error != std::errc()) return fmt::format("{} (too large a whole number)", text);
  return {};
}

}  // namespace

void RequireFiniteNumbers(CLI::App& app) {
  const CLI::Validator finite(
      [](std::string& text) {
        std::string problem;
        return ParseFiniteNumber(text, &problem) ? std::string() : problem;
      },
      "");
  const CLI::Validator non_empty(
      [](std::string& text) {
        return text.empty() ? std::string("an empty value (give one, or leave the option out)")
                            : std::string();
      },
      "");
  // CLI11 names the type of double, std::optional<double> and std::vector<double> options FLOAT,
  // followed by their checks ("FLOAT:FLOAT in [1e-14 - 0.09]": a range lets NaN through).
  const auto whole = [](bool is_unsigned) {
    return CLI::Validator(
        [is_unsigned](std::string& text) { return WholeNumberProblem(text, is_unsigned); }, "");
  };
  for (CLI::Option* option : app.get_options()) {
    const std::string type = option->get_type_name();
    if (type.rfind("FLOAT", 0) == 0) option->check(finite);
    if (type.rfind("INT", 0) == 0) option->check(whole(false));
    if (type.rfind("UINT", 0) == 0) option->check(whole(true));
    if (option->get_items_expected_min() > 0) option->check(non_empty);
  }
  for (CLI::App* command : app.get_subcommands({})) RequireFiniteNumbers(*command);
}

CLI::Validator Positive() {
  return CLI::Validator(
      [](std::string& text) {
        std::string problem;  // not a finite number: said as RequireFiniteNumbers says it
        const std::optional<double> value = ParseFiniteNumber(text, &problem);
        if (!value) return problem;
        return *value > 0.0 ? std::string() : fmt::format("{} (must be > 0)", text);
      },
      "> 0");
}

CLI::Validator Between(double low, double high) {
  return CLI::Validator(
      [low, high](std::string& text) {
        std::string problem;
        const std::optional<double> value = ParseFiniteNumber(text, &problem);
        if (!value) return problem;
        return *value >= low && *value <= high
                   ? std::string()
                   : fmt::format("{} (must be in [{}, {}])", text, Bound(low), Bound(high));
      },
      fmt::format("in [{}, {}]", Bound(low), Bound(high)));
}

}  // namespace isolab::cli
