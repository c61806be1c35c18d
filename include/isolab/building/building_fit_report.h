// A building fit's result as its users read it: `isolab fit --building --json` prints it and
// isolab.fit(building=...) returns it parsed, one function, so that the two cannot drift.
#pragma once

#include <string>
#include <utility>

#include "isolab/building/building_cross_validation.h"
#include "isolab/building/building_fit.h"

namespace isolab::building {

// The 95 % interval of a fitted value from its coordinate's standard deviation (log: a factor).
std::pair<double, double> Interval95(const FittedParameter& p);

// One line of a building fit's progress on stderr (with its newline): a CMA-ES generation, or a
// least-squares iteration with its convergence measures against their tolerances.
std::string BuildingFitProgressLine(const identification::FitProgress& progress);

// The JSON object (indented by two, no final newline): "parameters" (name, start, value, sigma,
// log, interval_95, at_bound), "priors" (name, value, sigma, source: held, not fitted), "channels"
// (motion, channel, nrmse_start, nrmse), "not_separated", "identified_range", "objective_start",
// "objective", "samples", "effective_samples", "correlation_time", "evaluations" (both stages),
// "global_evaluations", "iterations" (of the refinement kept), "stop" ("converged", "stalled" or
// "budget": the refinement's), "decrement" and "step" (its convergence measures), "stop_reason",
// "seconds", "sequential" (the motions were one specimen) and "output" (where the fitted model
// went).
std::string BuildingFitJson(const BuildingFitResult& result, bool sequential,
                            const std::string& output);

// A cross-validation as `isolab fit --building --cross-validate --json` prints it and
// isolab.fit(building=..., cross_validate=True) returns it: "folds" (held_out, fitted_on,
// objective_fitted, objective_held_out, channels (channel, nrmse), stop, evaluations and, for
// shake-table motions, band (samples, widening beyond the fold's identified range, coverage and
// peak_inside of the isolator displacement and roof acceleration)) and "seconds".
std::string CrossValidationJson(const CrossValidation& outcome);

// Its text: one table row per held-out motion, then what the numbers mean.
std::string CrossValidationText(const CrossValidation& outcome);

// The model form of a fit to every motion (`fit`, its fitted model carrying the folds' fits):
// "fits" (fitted_on, held_out, values by parameter name, objective_held_out, stop) and
// "parameters" (name, value, sigma of the fit alone and sigma drawn with the model form, in the
// coordinate: ln p where log), as JSON (no final newline).
std::string ModelFormJson(const BuildingFitResult& fit, const CrossValidation& folds);

// Its text: one row per parameter, the fit to every motion, each fold's and the two sigmas.
std::string ModelFormText(const BuildingFitResult& fit, const CrossValidation& folds);

}  // namespace isolab::building
