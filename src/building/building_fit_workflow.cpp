#include "isolab/building/building_fit_workflow.h"

#include <nlohmann/json.hpp>

#include "isolab/building/building_fit_report.h"

namespace isolab::building {

BuildingFitOutcome RunBuildingFit(const model::ModelFile& model,
                                  const std::vector<BuildingMotion>& motions,
                                  const BuildingFitSpec& spec,
                                  const identification::FitOptions& options, BuildingFitMode mode) {
  BuildingFitOutcome outcome;
  if (mode == BuildingFitMode::kCrossValidate) {
    outcome.folds =
        CrossValidate(model, motions, spec, options, kCrossValidationDraws, options.seed);
    return outcome;
  }
  if (mode == BuildingFitMode::kModelForm) {
    CheckCrossValidation(model, motions, spec, "the model form");
  }
  outcome.fit = FitBuilding(model, motions, spec, options);
  if (mode == BuildingFitMode::kModelForm) {
    outcome.folds = CrossValidate(model, motions, spec, options, 0, options.seed);
    AddModelForm(*outcome.folds, &outcome.fit->fitted);
  }
  return outcome;
}

std::string BuildingFitOutcomeJson(const BuildingFitOutcome& outcome, bool sequential,
                                   const std::string& output) {
  if (!outcome.fit) return CrossValidationJson(*outcome.folds);
  if (!outcome.folds) return BuildingFitJson(*outcome.fit, sequential, output);
  nlohmann::json json = nlohmann::json::parse(BuildingFitJson(*outcome.fit, sequential, output));
  json["model_form"] = nlohmann::json::parse(ModelFormJson(*outcome.fit, *outcome.folds));
  return json.dump(2);
}

}  // namespace isolab::building
