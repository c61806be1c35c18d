#include "finite_options.h"

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "isolab/core/number.h"

namespace isolab::cli {
namespace {

// Whole bounds in full (2147483647, not 2.14748e+09), others in the shortest form.
std::string Bound(double value) {
  return value == std::floor(value) && std::abs(value) < 1e15 ? fmt::format("{:.0f}", value)
                                                              : fmt::format("{:g}", value);
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
  for (CLI::Option* option : app.get_options()) {
    if (option->get_type_name().rfind("FLOAT", 0) == 0) option->check(finite);
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
