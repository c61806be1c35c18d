#include "building_fit_command.h"

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <fmt/ranges.h>

#include <filesystem>

#include "isolab/building/building_fit.h"
#include "isolab/building/building_fit_inputs.h"
#include "isolab/building/building_fit_report.h"
#include "isolab/building/building_fit_workflow.h"
#include "isolab/core/errors.h"
#include "isolab/io/atomic_file.h"
#include "isolab/io/output_check.h"
#include "isolab/model/fitted_building_file.h"

namespace isolab::cli {
namespace {

void RefuseCyclicOptions(const FitOptions& options) {
  for (const auto& [given, option] :
       {std::pair{!options.cycles.empty(), "--cycles"}, std::pair{options.force, "--force"}}) {
    if (given) {
      throw InputError({"command line"},
                       fmt::format("{} applies to cyclic tests, not to --building", option));
    }
  }
}

}  // namespace

void RunBuildingFitCommand(const FitOptions& options, const SearchRanks& ranks, std::ostream& out) {
  RefuseCyclicOptions(options);
  const building::BuildingData data{options.data,
                                    options.specimen,
                                    options.offsets,
                                    options.force_unit,
                                    options.length_unit,
                                    options.quiet || !ranks.reports(),
                                    "isolab fit --building",
                                    {}};
  building::BuildingFitInputs inputs = building::LoadBuildingFit(options.building, data);
  const model::ModelFile& model = inputs.model;
  if (options.cross_validate && options.model_form) {
    throw InputError({"command line"},
                     "--cross-validate and --model-form: --model-form already fits each motion "
                     "held out (and reports its held-out error); give one of the two");
  }
  if (options.cross_validate && !options.output.empty()) {
    throw InputError({"command line"},
                     "--cross-validate writes no model (each held-out fit is a step of the "
                     "check): -o does not apply; fit all the motions without it for the model");
  }
  const building::BuildingFitMode mode =
      options.cross_validate ? building::BuildingFitMode::kCrossValidate
      : options.model_form   ? building::BuildingFitMode::kModelForm
                             : building::BuildingFitMode::kFit;
  const std::string output =
      !options.output.empty()
          ? options.output
          : std::filesystem::path(options.building).stem().string() + ".fitted.yaml";
  if (!options.cross_validate) io::CheckOutputs(inputs.files, {output});
  const std::vector<building::BuildingMotion> motions =
      building::ReadBuildingMotions(&inputs, data);
  const building::BuildingFitSpec& spec = inputs.spec;

  identification::FitOptions fit;
  fit.seed = options.seed;
  fit.budget = options.budget;
  fit.threads = ranks.Threads(options.threads);
  fit.spread = ranks.spread();
  fit.global_budget = options.global_budget;
  if (!options.quiet && ranks.reports()) {
    fmt::print(stderr, "  {} parameters, {} motions ({}), budget {} simulations\n",
               spec.parameters.size(), motions.size(),
               spec.sequential ? "one specimen, in order" : "each from rest", options.budget);
    fit.progress = [](const identification::FitProgress& p) {
      fmt::print(stderr, "{}", building::BuildingFitProgressLine(p));
    };
  }
  building::BuildingFitOutcome outcome;
  try {
    outcome = building::RunBuildingFit(model, motions, spec, fit, mode);
  } catch (const InvalidParameter& error) {
    // The search's settings are this command's options: said by their names.
    std::string text = error.violation().Describe();
    if (text.rfind("global_budget", 0) != 0) throw;
    text.replace(0, 13, "--global-budget");
    throw InputError({"command line"}, text);
  }
  if (!ranks.reports()) return;
  if (!outcome.fit) {
    out << (options.json ? building::BuildingFitOutcomeJson(outcome, spec.sequential, "") + "\n"
                         : building::CrossValidationText(*outcome.folds));
    return;
  }
  const building::BuildingFitResult& result = *outcome.fit;
  const std::string text = model::FittedBuildingText(
      result.fitted, fmt::format("identified by isolab fit --building {} from {}", options.building,
                                 fmt::join(options.data, ", ")));
  io::WriteTextFileAtomically(output, [&](std::ostream& o) { o << text; });

  if (options.json) {
    out << building::BuildingFitOutcomeJson(outcome, spec.sequential, output) << "\n";
    return;
  }
  fmt::print(out, "mean NRMSE^2 over {} channels: {:.4g} -> {:.4g}\n{} ({:.1f} s)\n\n",
             result.channels.size(), result.objective_start, result.objective, result.stop_reason,
             result.seconds);
  fmt::print(out, "| parameter | start | fitted | 95 % interval |\n|---|---|---|---|\n");
  for (const building::FittedParameter& p : result.parameters) {
    const auto [low, high] = building::Interval95(p);
    fmt::print(out, "| {} | {:.4g} | {:.4g} | {:.4g} to {:.4g}{} |\n", p.name, p.start, p.value,
               low, high, p.at_bound ? " (at the range's end)" : "");
  }
  for (const model::ParameterPrior& prior : result.fitted.uncertainty->priors) {
    fmt::print(out, "| {} | prior | {:.4g} | held: sigma {:.3g} in ln p ({}) |\n", prior.name,
               prior.value, prior.sigma, prior.source);
  }
  fmt::print(out, "\n| motion | channel | NRMSE start | NRMSE fitted |\n|---|---|---|---|\n");
  for (const building::ChannelFit& c : result.channels) {
    fmt::print(out, "| {} | {} | {:.3f} | {:.3f} |\n", c.motion, c.channel, c.nrmse_start, c.nrmse);
  }
  fmt::print(out,
             "\nThe residual is correlated over {:.3g} {}: its {:.0f} samples are worth {:.0f} "
             "independent ones, and the intervals count them so.\n",
             result.correlation_time, model.units.time(), result.samples, result.effective_samples);
  for (const building::CorrelatedParameters& pair : result.not_separated) {
    fmt::print(out,
               "not separately identified: {} and {} (correlation {:.3f}): the data fix a "
               "combination of the two\n",
               pair.a, pair.b, pair.correlation);
  }
  if (outcome.folds) out << building::ModelFormText(result, *outcome.folds);
  fmt::print(out, "fitted model: {}\n", output);
}

}  // namespace isolab::cli
