// Numbers on the command line go through the same reader as numbers in files (core/number.h):
// `--scale nan` or `--rtol inf` is bad input, refused with exit 2 and the option's name.
#pragma once

#include <CLI/CLI.hpp>

namespace isolab::cli {

// Makes every floating-point option of `app` and of its commands refuse what ParseFiniteNumber
// refuses. Call once, after every command is registered and before parsing.
void RequireFiniteNumbers(CLI::App& app);

}  // namespace isolab::cli
