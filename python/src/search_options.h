// The search settings isolab.fit and isolab.diagnose take as keywords (seed, budget, threads),
// checked as the command line checks its options.
#pragma once

#include "isolab/core/errors.h"
#include "isolab/identification/unit_cube_search.h"

namespace isolab::python {

// Throws InputError naming `function` ("fit", "diagnose") for a setting out of range.
inline identification::FitOptions SearchOptions(const char* function, unsigned seed, long budget,
                                                int threads, long global_budget = -1) {
  identification::FitOptions fit;
  fit.seed = seed;
  fit.budget = budget;
  fit.threads = threads;
  fit.global_budget = global_budget;
  try {
    fit.Validate();
  } catch (const InvalidParameter& error) {
    throw InputError({function}, error.violation().Describe());
  }
  return fit;
}

}  // namespace isolab::python
