// A fitted model's prediction with its parameters' uncertainty: parameter sets drawn from the
// normal distribution of their coordinates that the fit reported (model_file.h's `uncertainty`,
// written by `isolab fit --building`), each run under the measured table motion; what comes out is
// the spread of the predicted histories (the 5th and 95th percentiles at every sample), of the
// peaks and of the NRMSE against the measurements.
#pragma once

#include <string>
#include <vector>

#include "isolab/analysis/building_response.h"
#include "isolab/analysis/parameter_draws.h"

namespace isolab::analysis {

struct PredictionBand {
  int samples = 0;  // parameter sets run
  int refused = 0;  // drawn sets that broke a law's rules or whose run failed, left out
  Signal isolator_p5, isolator_p95;  // the slab's displacement relative to the table
  Signal roof_p5, roof_p95;          // the roof's absolute acceleration
  Percentiles peak_isolator_displacement, peak_roof_acceleration;
  Percentiles nrmse_isolator_displacement, nrmse_roof_acceleration;
};

// Draws `samples` parameter sets (>= 2) with `seed` and runs each (one motion, from rest). Throws
// InputError when the model carries no uncertainty or names a parameter it lacks.
PredictionBand PredictBand(const model::ModelFile& model, const BuildingMotion& motion, int samples,
                           unsigned seed);

}  // namespace isolab::analysis
