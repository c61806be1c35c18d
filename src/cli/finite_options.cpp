#include "finite_options.h"

#include <string>

#include "isolab/core/number.h"

namespace isolab::cli {

void RequireFiniteNumbers(CLI::App& app) {
  const CLI::Validator finite(
      [](std::string& text) {
        std::string problem;
        return ParseFiniteNumber(text, &problem) ? std::string() : problem;
      },
      "");
  // CLI11 names the type of double, std::optional<double> and std::vector<double> options FLOAT,
  // followed by their checks ("FLOAT:FLOAT in [1e-14 - 0.09]": a range lets NaN through).
  for (CLI::Option* option : app.get_options()) {
    if (option->get_type_name().rfind("FLOAT", 0) == 0) option->check(finite);
  }
  for (CLI::App* command : app.get_subcommands({})) RequireFiniteNumbers(*command);
}

}  // namespace isolab::cli
