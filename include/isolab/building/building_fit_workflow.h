// The building fit as `isolab fit --building` and isolab.fit(building=...) run it, one sequence
// for both: the fit to every motion, the cross-validation, or both with the folds' fits kept as
// the fitted model's model form (parameter_draws.h), so that its prediction bands carry the spread
// between fits to different motions and not only one fit's covariance.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "isolab/building/building_cross_validation.h"
#include "isolab/building/building_fit.h"

namespace isolab::building {

enum class BuildingFitMode {
  kFit,            // the fit to every motion; writes the model
  kCrossValidate,  // each motion held out in turn; writes no model
  kModelForm,      // both: the model with the folds' fits as its model form
};

struct BuildingFitOutcome {
  std::optional<BuildingFitResult> fit;  // kFit, kModelForm
  std::optional<CrossValidation> folds;  // kCrossValidate, kModelForm
};

// The checks of a held-out motion come first, so a refused model form costs no fit. The
// cross-validation's folds draw kCrossValidationDraws band sets (with `options.seed`); the model
// form's draw none. Throws what FitBuilding and CheckCrossValidation throw.
BuildingFitOutcome RunBuildingFit(const model::ModelFile& model,
                                  const std::vector<BuildingMotion>& motions,
                                  const BuildingFitSpec& spec,
                                  const identification::FitOptions& options, BuildingFitMode mode);

// The outcome as JSON (no final newline): CrossValidationJson for kCrossValidate, else
// BuildingFitJson with, for kModelForm, "model_form" (ModelFormJson).
std::string BuildingFitOutcomeJson(const BuildingFitOutcome& outcome, bool sequential,
                                   const std::string& output);

}  // namespace isolab::building
