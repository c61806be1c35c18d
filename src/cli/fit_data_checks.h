// Checks `isolab fit` and `isolab diagnose` make before identifying anything: data too few for
// the parameters asked for cannot determine them, and the fit would report a meaningless e^2.
#pragma once

#include <string>
#include <vector>

#include "isolab/identification/fit.h"
#include "isolab/identification/parametrisation.h"

namespace isolab::cli {

// Throws InputError at `spec_path` when the samples to fit are fewer than the model's parameters
// (shape coordinates plus stiffnesses); `model` is the specification's parametrisation.
void RequireMoreSamplesThanParameters(const identification::FitData& data,
                                      const identification::ModelParametrisation& model,
                                      const std::string& spec_path);

}  // namespace isolab::cli
