// The spectrum's lists as text, read one way for the command line and for Python:
// "START:STOP:STEP" (STOP included when the steps reach it) or "a,b,c" for periods, "a,b,c" for
// damping ratios and ductilities.
#pragma once

#include <string>
#include <vector>

namespace isolab::spectra {

// Periods in s, each > 0, at most 100000 of them. Throws InputError naming `option`.
std::vector<double> ParsePeriods(const std::string& text, const std::string& option);

// A comma-separated list of finite numbers, not empty. Throws InputError naming `option`.
std::vector<double> ParseNumberList(const std::string& text, const std::string& option);

}  // namespace isolab::spectra
