// The testing factors `isolab fit` reports from the tests' own cycles
// (identification/testing_factors.h): a table for the terminal, the comment the fitted model
// carries (a `modification` entry ready for a bearing given by its Qd and Kd), and JSON.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "isolab/core/units.h"
#include "isolab/identification/testing_factors.h"

namespace isolab::cyclic {

std::string TestingFactorsText(const identification::TestingFactors& factors,
                               const UnitSystem& units);

// Lines for the fitted model's header comment; empty when no test has three cycles.
std::vector<std::string> TestingFactorsComment(const identification::TestingFactors& factors,
                                               const UnitSystem& units);

nlohmann::json TestingFactorsJson(const identification::TestingFactors& factors);

}  // namespace isolab::cyclic
