#include "fit_command.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "building_fit_command.h"
#include "common_options.h"
#include "finite_options.h"
#include "heavy_commands.h"
#include "isolab/core/errors.h"
#include "isolab/cyclic/cyclic_fit.h"
#include "isolab/cyclic/testing_factors_text.h"
#include "isolab/hysteresis/law_parameters.h"
#include "isolab/io/output_check.h"
#include "search_ranks.h"
#include "specimen_option.h"

namespace isolab::cli {

void RegisterFitCommand(CLI::App& app, FitOptions& options) {
  CLI::App* command =
      app.add_subcommand(std::string(kFitCommand.name), std::string(kFitCommand.help));
  command
      ->add_option("data", options.data,
                   "CSV test data: test,time,displacement,force (with --building: shake-table "
                   "CSV files, one per motion)")
      ->required()
      ->check(CLI::ExistingFile);
  CLI::Option* model =
      command
          ->add_option("--model", options.spec, "Specification: component types and counts (YAML)")
          ->check(CLI::ExistingFile);
  command
      ->add_option("--building", options.building,
                   "Building fit specification (YAML): a building model and the parameters to "
                   "identify from shake-table motions by output error")
      ->check(CLI::ExistingFile)
      ->excludes(model);
  command
      ->add_option("--offsets", options.offsets,
                   "With --building: accelerometer offsets, pre-event (each channel less its mean "
                   "before the table moves; default) or none, as isolab shaketable takes them")
      ->check(CLI::IsMember({"pre-event", "none"}));
  AddSeedOption(command, &options.seed, "Seed; a fixed seed reproduces the fit exactly");
  command->add_option("--budget", options.budget, "Model evaluations (default 60000)")
      ->check(Between(100, 1e9));
  command
      ->add_option("--global-budget", options.global_budget,
                   "With --building: simulations of the global search (CMA-ES) before the "
                   "least-squares refinement; 0 refines from the specification's start (default: "
                   "half the budget, or one chunk of CMA-ES generations where that is more and "
                   "the budget allows it)")
      ->check(Between(0, 1e9));
  command->add_flag("--cross-validate", options.cross_validate,
                    "With --building and two motions or more: fit the building to all but one, "
                    "predict the one held out, each in turn; writes no model");
  command->add_flag("--model-form", options.model_form,
                    "With --building and two motions or more: fit every motion, then each motion "
                    "held out in turn, and write the model with those fits' spread, which its "
                    "prediction bands then carry beside the fit's own uncertainty");
  command->add_option("--cycles", options.cycles,
                      "Whole cycles to fit, 1-based, e.g. --cycles 3 as the paper fits HDRB tests "
                      "(default: every test's whole history)");
  AddSpecimenOption(command, &options.specimen);
  AddOutputOption(command, &options.output, "Fitted model file (YAML)");
  command->add_option("--force-unit", options.force_unit,
                      "Force unit of data files without a '# units:' line (with --length-unit)");
  command->add_option("--length-unit", options.length_unit,
                      "Length unit of data files without a '# units:' line (with --force-unit)");
  AddThreadsOption(command, &options.threads, kSearchThreadsDefault);
  command->add_flag("--force", options.force,
                    "Fit even when the work (evaluations x samples x laws) is beyond the limit");
  AddJsonFlag(command, &options.json, "Print the result as JSON");
  AddQuietFlag(command, &options.quiet);
}

namespace {

// The text `isolab fit` prints: e^2, the energy per fitted span, the parameters, the testing
// factors, what the data do not identify, and the notes.
void PrintCyclicFit(const cyclic::CyclicFitProblem& problem,
                    const cyclic::CyclicFitOutcome& outcome, const std::string& output,
                    std::ostream& out) {
  const identification::FitResult& result = outcome.result;
  const identification::FitData& data = problem.data;
  const model::FitSpec& spec = problem.spec;
  const auto [low, high] =
      std::minmax_element(result.error.per_test.begin(), result.error.per_test.end());
  fmt::print(out,
             "e^2 per test: {:.4g} % on average ({:.4g} to {:.4g} % over {} tests; the paper's sum "
             "{:.4g} %)\n{} ({:.1f} s)\n\n",
             100 * result.error.Mean(), 100 * *low, 100 * *high, data.tests.size(),
             100 * result.error.total, result.stop_reason, result.seconds);
  fmt::print(out, "{:<14} {:>12} {:>16} {:>16} {:>9} {:>10}\n", "test", "amplitude", "W_d measured",
             "W_d fitted", "diff", "e^2");
  std::size_t test_index = 0;
  for (const cyclic::CyclicFitEnergy& row : outcome.energy) {
    while (data.tests[test_index].name != row.test) ++test_index;
    fmt::print(out, "{:<14} {:>9.4g} {:<2} {:>16.6g} {:>16.6g} {:>8.2f}% {:>9.4f}%  ({})\n",
               row.test, row.amplitude, spec.units.length(), row.measured, row.fitted,
               100 * (row.fitted / row.measured - 1), 100 * result.error.per_test[test_index],
               row.cycle > 0 ? fmt::format("cycle {}", row.cycle) : "whole history");
  }
  fmt::print(out, "\n");
  for (std::size_t c = 0; c < spec.components.size(); ++c) {
    const auto type = spec.components[c].type;
    const auto keys = hysteresis::ParameterKeys(type, hysteresis::ParameterForm::kMathematical);
    fmt::print(out, "{:<8} {:<18}", spec.components[c].name, hysteresis::LawName(type));
    for (std::size_t k = 0; k < keys.size(); ++k) {
      fmt::print(out, " {}={:.6g}", keys[k], result.mathematical[c][k]);
    }
    fmt::print(out, "\n");
  }
  fmt::print(out, "\n{}", cyclic::TestingFactorsText(outcome.testing, spec.units));
  if (!outcome.findings.empty()) {
    fmt::print(out, "\nidentifiability:\n");
    for (const std::string& finding : outcome.findings) fmt::print(out, "  {}\n", finding);
  }
  for (const std::string& note : outcome.notes) fmt::print(out, "\nnote: {}", note);
  fmt::print(out, "{}\nfitted model: {}\n", outcome.notes.empty() ? "" : "\n", output);
}

void RunCyclicFit(const FitOptions& options, const SearchRanks& ranks, std::ostream& out) {
  if (options.spec.empty()) {
    throw InputError({"command line"},
                     "give --model (cyclic tests) or --building (shake-table "
                     "motions)");
  }
  if (!options.offsets.empty()) {
    throw InputError({"command line"}, "--offsets applies to --building, not to cyclic tests");
  }
  if (options.global_budget >= 0) {
    throw InputError({"command line"},
                     "--global-budget applies to --building, not to cyclic tests");
  }
  for (const auto& [given, option] : {std::pair{options.cross_validate, "--cross-validate"},
                                      std::pair{options.model_form, "--model-form"}}) {
    if (given) {
      throw InputError({"command line"},
                       fmt::format("{} applies to --building, not to cyclic tests", option));
    }
  }
  const std::string output =
      !options.output.empty()
          ? options.output
          : std::filesystem::path(options.spec).stem().string() + ".fitted.yaml";
  std::vector<std::string> inputs = options.data;
  inputs.push_back(options.spec);
  io::CheckOutputs(inputs, {output});
  cyclic::CyclicFitRequest request;
  request.data = options.data;
  request.spec_path = options.spec;
  request.cycles = options.cycles;
  request.specimen = options.specimen;
  request.force_unit = options.force_unit;
  request.length_unit = options.length_unit;
  request.search.seed = options.seed;
  request.search.budget = options.budget;
  request.search.threads = ranks.Threads(options.threads);
  request.search.spread = ranks.spread();
  request.force = options.force;
  cyclic::CyclicFitProblem problem = cyclic::PrepareCyclicFit(std::move(request));
  if (!options.quiet && ranks.reports()) {
    fmt::print(stderr,
               "isolab fit: {} tests ({}), {} shape coordinates and {} stiffnesses, budget {}\n  "
               "{}\n",
               problem.data.tests.size(),
               problem.one_specimen ? "one specimen, in order" : "independent specimens",
               problem.model->dimension(), problem.model->amplitude_count(), options.budget,
               problem.work.Describe(cyclic::kWorkLimit));
    problem.request.search.progress = cyclic::PrintCyclicFitProgress;
  }
  cyclic::CyclicFitOutcome outcome = cyclic::FitCyclicTests(problem);
  if (!ranks.reports()) return;
  cyclic::WriteCyclicFitModel(output, problem, outcome);
  if (options.json) {
    nlohmann::json json = cyclic::CyclicFitJson(problem, outcome);
    json["output"] = output;
    out << json.dump(2) << "\n";
    return;
  }
  PrintCyclicFit(problem, outcome, output, out);
}

}  // namespace

int RunFitCommand(const FitOptions& options, std::ostream& out) {
  return RunOnSearchRanks([&](const SearchRanks& ranks) {
    if (options.building.empty()) {
      RunCyclicFit(options, ranks, out);
    } else {
      RunBuildingFitCommand(options, ranks, out);
    }
  });
}

}  // namespace isolab::cli
