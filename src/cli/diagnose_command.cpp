#include "diagnose_command.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <stdexcept>

#include "building_diagnose_command.h"
#include "common_options.h"
#include "diagnosis_files.h"
#include "finite_options.h"
#include "heavy_commands.h"
#include "isolab/core/errors.h"
#include "isolab/cyclic/cyclic_diagnosis.h"
#include "isolab/cyclic/test_data_checks.h"
#include "isolab/diagnosis/diagnose.h"
#include "isolab/diagnosis/report.h"
#include "isolab/io/cyclic_test_file.h"
#include "isolab/io/output_check.h"
#include "isolab/model/fit_spec_file.h"
#include "isolab/model/fitted_model_file.h"
#include "search_ranks.h"
#include "specimen_option.h"

namespace isolab::cli {
namespace {

// The final model as a model file; a component the fit left a simpler law is written as that law
// (identification::SimplifyComponents), with a note. Returns the notes.
std::vector<std::string> WriteFinalModel(const std::string& path, const DiagnoseOptions& options,
                                         const model::FitSpec& base,
                                         const diagnosis::Diagnosis& result,
                                         const identification::FitData& data) {
  model::FittedModel model;
  model.comment.push_back(fmt::format("Diagnosed by isolab diagnose from {} (base {}, seed {}).",
                                      fmt::join(options.data, ", "), options.base, options.seed));
  std::string effects;
  for (const auto& step : result.steps) {
    effects += fmt::format("{}{}", effects.empty() ? "" : ", ", diagnosis::EffectName(step.effect));
  }
  model.comment.push_back(
      fmt::format("Effects added: {}; e^2 = {:.6g} % (base {:.6g} %); the residual is {}.",
                  effects.empty() ? "none" : effects, 100 * result.final_model.fit.error.total,
                  100 * result.base.fit.error.total, diagnosis::VerdictName(result.verdict.kind)));
  model.description = fmt::format("Diagnosed from {}", fmt::join(options.data, ", "));
  model.specification = options.base;
  model.units = base.units;
  model.range = identification::RangeOf(data);
  model.components = result.final_model.components;
  std::vector<std::string> names;
  std::vector<hysteresis::LawType> types;
  for (const auto& c : model.components) names.push_back(c.name), types.push_back(c.type);
  model.mathematical = result.final_model.fit.mathematical;
  std::vector<std::string> notes =
      identification::SimplifyComponents(names, &types, &model.mathematical);
  for (std::size_t c = 0; c < types.size(); ++c) model.components[c].type = types[c];
  for (const std::string& note : notes) model.comment.push_back(note + ".");
  model::WriteFittedModel(path, model);
  return notes;
}

}  // namespace

void RegisterDiagnoseCommand(CLI::App& app, DiagnoseOptions& options) {
  CLI::App* command =
      app.add_subcommand(std::string(kDiagnoseCommand.name), std::string(kDiagnoseCommand.help));
  command
      ->add_option("data", options.data,
                   "CSV test data: test,time,displacement,force (with --building: shake-table "
                   "motions)")
      ->required()
      ->check(CLI::ExistingFile);
  CLI::Option* base =
      command
          ->add_option("--base", options.base,
                       "Base model: component types, bounds optional (as isolab fit --model)")
          ->check(CLI::ExistingFile);
  CLI::Option* building =
      command
          ->add_option("--building", options.building,
                       "Building fit specification (as isolab fit --building): diagnose the "
                       "isolation of a building from its shake-table motions")
          ->check(CLI::ExistingFile)
          ->excludes(base);
  base->excludes(building);
  command
      ->add_option("--offsets", options.offsets,
                   "With --building: accelerometer offsets, pre-event (each channel less its "
                   "mean before the motion) or none")
      ->check(CLI::IsMember({"pre-event", "none"}));
  command->add_option("--out", options.out,
                      "Report stem: writes OUT.md, OUT.json, OUT.model.yaml, OUT.residual.csv "
                      "and OUT.residual.png (default: <first data file>.diagnosis)");
  AddSeedOption(command, &options.seed, "Seed; a fixed seed reproduces the diagnosis");
  AddSpecimenOption(command, &options.specimen);
  command->add_option("--budget", options.budget, "Model evaluations per fit (default 12000)")
      ->check(Between(100, 1e8));
  command->add_option("--force-unit", options.force_unit,
                      "Force unit of data files without a '# units:' line (with --length-unit)");
  command->add_option("--length-unit", options.length_unit,
                      "Length unit of data files without a '# units:' line (with --force-unit)");
  AddThreadsOption(command, &options.threads, kSearchThreadsDefault);
  command->add_flag("!--no-plot", options.plot, "Do not plot the residual");
  command->add_flag("--force", options.force,
                    "Diagnose even when one fit's work (evaluations x samples x laws) is beyond "
                    "the limit");
  AddJsonFlag(command, &options.json, "Print the report as JSON instead of a summary");
  AddQuietFlag(command, &options.quiet);
}

namespace {

void Diagnose(const DiagnoseOptions& options, const SearchRanks& ranks, std::ostream& out) {
  if (!options.building.empty()) return RunBuildingDiagnoseCommand(options, ranks, out);
  if (options.base.empty()) {
    throw InputError({"command line"},
                     "give --base (cyclic tests) or --building (a building's shake-table motions)");
  }
  if (!options.offsets.empty()) {
    throw InputError({"command line"}, "--offsets applies to --building, not to cyclic tests");
  }
  // The files first, so that a refused output costs no diagnosis.
  diagnosis::ReportContext context;
  const DiagnosisFiles files =
      DiagnosisFiles::Plan(options.out, options.data.front(), options.plot, &context);
  std::vector<std::string> inputs = options.data;
  inputs.push_back(options.base);
  io::CheckOutputs(inputs, files.outputs);

  cyclic::CyclicDiagnosisRequest request;
  request.data = options.data;
  request.base_path = options.base;
  request.specimen = options.specimen;
  request.force_unit = options.force_unit;
  request.length_unit = options.length_unit;
  request.settings.seed = options.seed;
  request.settings.budget = options.budget;
  request.settings.threads = ranks.Threads(options.threads);
  request.settings.spread = ranks.spread();
  request.force = options.force;
  const bool quiet = options.quiet || !ranks.reports();
  if (!quiet) {
    request.settings.progress = [](const std::string& line) { fmt::print(stderr, "  {}\n", line); };
  }
  const cyclic::CyclicDiagnosisProblem problem = cyclic::PrepareCyclicDiagnosis(std::move(request));
  const model::FitSpec& base = problem.base;
  const identification::FitData& data = problem.data;
  cyclic::NameCyclicDiagnosis(problem, &context);
  if (!quiet) {
    fmt::print(stderr, "isolab diagnose: {} tests ({}), base {}\n  base fit's {}\n",
               data.tests.size(),
               data.one_specimen ? "one specimen, in order" : "independent specimens", options.base,
               problem.work.Describe(cyclic::kWorkLimit));
  }
  const diagnosis::Diagnosis result = cyclic::DiagnoseCyclicTests(problem);
  if (!ranks.reports()) return;

  // The model first: a model isolab would refuse is a note in the report, not a lost diagnosis.
  try {
    for (std::string& note : WriteFinalModel(context.model_file, options, base, result, data)) {
      context.notes.push_back(std::move(note));
    }
  } catch (const InputError& error) {
    context.notes.push_back(fmt::format("the final model was not written: {}", error.what()));
    context.model_file.clear();
  }
  const diagnosis::DiagnosisReport report = diagnosis::BuildReport(result, data, context);
  const std::string json = diagnosis::RenderJson(report);
  files.Write(report, json,
              fmt::format("{}: the final residual is {}",
                          std::filesystem::path(options.data.front()).filename().string(),
                          diagnosis::VerdictName(result.verdict.kind)),
              options.quiet || options.json);
  if (options.json) {
    out << json;
    return;
  }
  out << diagnosis::RenderSummary(report) << files.Where(context);
}

}  // namespace

int RunDiagnoseCommand(const DiagnoseOptions& options, std::ostream& out) {
  return RunOnSearchRanks([&](const SearchRanks& ranks) { Diagnose(options, ranks, out); });
}

}  // namespace isolab::cli
