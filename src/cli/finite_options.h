// Numbers on the command line go through the same reader as numbers in files (core/number.h):
// `--scale nan` or `--rtol inf` is bad input, refused with exit 2 and the option's name. Ranges
// are said as the model reader says them ("must be > 0"): CLI11's own range checks print their
// bounds with %f, 309 digits for the largest double.
#pragma once

#include <CLI/CLI.hpp>

namespace isolab::cli {

// Makes every floating-point option of `app` and of its commands refuse what ParseFiniteNumber
// refuses, and every option that takes a value refuse an empty one (`-o ''` once wrote the default
// file). Call once, after every command is registered and before parsing.
void RequireFiniteNumbers(CLI::App& app);

// "--every: 0 (must be > 0)".
CLI::Validator Positive();
// "--rtol: 1 (must be in [1e-14, 0.09])".
CLI::Validator Between(double low, double high);

}  // namespace isolab::cli
