// A fitted model's prediction with its parameters' uncertainty: parameter sets drawn from the
// normal distribution of their coordinates that the fit reported (model_file.h's `uncertainty`,
// written by `isolab fit --building`), each run under the measured table motion; what comes out is
// the spread of the predicted histories (the 5th and 95th percentiles at every sample), of the
// peaks and of the NRMSE against the measurements.
#pragma once

#include <string>
#include <vector>

#include "isolab/analysis/parameter_draws.h"
#include "isolab/building/building_response.h"

namespace isolab::building {

struct PredictionBand {
  int samples = 0;        // parameter sets run
  int refused = 0;        // drawn sets that broke a law's rules or whose run failed, left out
  double widening = 1.0;  // beyond the identified range (BandWidening); 1 within it
  std::string contents;   // what the draws hold (BandContents)
  Signal isolator_p5, isolator_p95;  // the slab's displacement relative to the table
  Signal roof_p5, roof_p95;          // the roof's absolute acceleration
  analysis::Percentiles peak_isolator_displacement, peak_roof_acceleration;
  analysis::Percentiles nrmse_isolator_displacement, nrmse_roof_acceleration;
  // How far the band holds the measurements: the share of the measured samples inside
  // [p5, p95] at their time, and whether the measured peak lies within the peaks' 5-95 % range
  // (both within 1e-4 of the measured history's RMS).
  // A band of parameter uncertainty alone says nothing of the model's error, so a low coverage
  // is what a model lacking something shows.
  double isolator_coverage = 0.0, roof_coverage = 0.0;
  double measured_peak_isolator = 0.0, measured_peak_roof = 0.0;
  bool isolator_peak_inside = false, roof_peak_inside = false;
};

// One sentence on the band's coverage for the text's first lines: the shares and the peaks,
// each peak said inside or outside with the range, and what a low coverage means.
std::string CoverageSentence(const PredictionBand& band, const std::string& length_unit,
                             const std::string& acceleration_unit);

// Draws `samples` parameter sets (>= 2) with `seed` and runs each (one motion, from rest). Throws
// InputError when the model carries no uncertainty or names a parameter it lacks.
// `substeps` integration steps per measured sample, as the fit ran (building_fit.h).
PredictionBand PredictBand(const model::ModelFile& model, const BuildingMotion& motion, int samples,
                           unsigned seed, int substeps = 1);

}  // namespace isolab::building
