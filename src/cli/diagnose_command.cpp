#include "diagnose_command.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <stdexcept>

#include "diagnosis_report.h"
#include "finite_options.h"
#include "fit_data_checks.h"
#include "isolab/core/errors.h"
#include "isolab/diagnosis/diagnose.h"
#include "isolab/io/atomic_file.h"
#include "isolab/io/cyclic_test_file.h"
#include "isolab/io/output_check.h"
#include "isolab/model/fit_spec_file.h"
#include "isolab/model/fitted_model_file.h"
#include "specimen_option.h"

namespace isolab::cli {
namespace {

void WriteText(const std::string& path, const std::string& text) {
  io::WriteTextFileAtomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace

void RegisterDiagnoseCommand(CLI::App& app, DiagnoseOptions& options) {
  CLI::App* command = app.add_subcommand(
      "diagnose",
      "Fit a base isolator model to cyclic tests, name the effects it lacks, add them and refit");
  command->add_option("data", options.data, "CSV test data: test,time,displacement,force")
      ->required()
      ->check(CLI::ExistingFile);
  command
      ->add_option("--base", options.base,
                   "Base model: component types, bounds optional (as isolab fit --model)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--out", options.out,
                      "Report stem: writes OUT.md, OUT.json and OUT.model.yaml "
                      "(default: <first data file>.diagnosis)");
  command->add_option("--seed", options.seed, "Seed; a fixed seed reproduces the diagnosis");
  AddSpecimenOption(command, &options.specimen);
  command->add_option("--budget", options.budget, "Model evaluations per fit (default 12000)")
      ->check(Between(100, 1e8));
  command->add_option("--force-unit", options.force_unit, "Force unit of the data (default kN)");
  command->add_option("--length-unit", options.length_unit, "Length unit of the data (default mm)");
  command->add_flag("--json", options.json, "Print the report as JSON instead of a summary");
  command->add_flag("-q,--quiet", options.quiet, "No progress on stderr");
}

void RunDiagnoseCommand(const DiagnoseOptions& options, std::ostream& out) {
  const model::FitSpec base = model::LoadFitSpec(options.base);
  const std::string stem =
      !options.out.empty()
          ? options.out
          : std::filesystem::path(options.data.front()).replace_extension().string() + ".diagnosis";
  std::vector<std::string> inputs = options.data;
  inputs.push_back(options.base);
  io::CheckOutputs(inputs, {stem + ".model.yaml", stem + ".json", stem + ".md"});
  io::CyclicTestSet set =
      io::ReadCyclicTests(options.data, {options.force_unit, options.length_unit}, base.units);
  const identification::FitData data = diagnosis::AllCycles(
      std::move(set.tests), io::OneSpecimen(options.specimen, set.one_specimen));

  try {
    RequireMoreSamplesThanParameters(
        data, identification::ModelParametrisation(base.components, identification::ScalesOf(data)),
        options.base);
  } catch (const std::invalid_argument& error) {
    throw InputError({options.base}, error.what());
  }

  diagnosis::DiagnoseOptions settings;
  settings.seed = options.seed;
  settings.budget = options.budget;
  if (!options.quiet) {
    fmt::print(stderr, "isolab diagnose: {} tests ({}), base {}\n", data.tests.size(),
               data.one_specimen ? "one specimen, in order" : "independent specimens",
               options.base);
    settings.progress = [](const std::string& line) { fmt::print(stderr, "  {}\n", line); };
  }
  diagnosis::Diagnosis result;
  try {
    result = diagnosis::Diagnose(base.components, data, settings);
  } catch (const std::invalid_argument& error) {
    throw InputError({options.base}, error.what());
  }

  DiagnosisContext context{options.data, options.base, stem + ".model.yaml", options.seed,
                           base.units};

  model::FittedModel model;
  model.comment.push_back(fmt::format("Diagnosed by isolab diagnose from {} (base {}, seed {}).",
                                      fmt::join(options.data, ", "), options.base, options.seed));
  std::string effects;
  for (const auto& step : result.steps) {
    effects += fmt::format("{}{}", effects.empty() ? "" : ", ", diagnosis::EffectName(step.effect));
  }
  model.comment.push_back(fmt::format(
      "Effects added: {}; e^2 = {:.6g} % (base {:.6g} %).", effects.empty() ? "none" : effects,
      100 * result.final_model.fit.error.total, 100 * result.base.fit.error.total));
  model.description = fmt::format("Diagnosed from {}", fmt::join(options.data, ", "));
  model.specification = options.base;
  model.units = base.units;
  model.components = result.final_model.components;
  model.mathematical = result.final_model.fit.mathematical;
  // Every text first, then the files: a failure while composing leaves none behind.
  const nlohmann::json json = DiagnosisJson(result, data, context);
  const std::string markdown = DiagnosisMarkdown(result, data, context);
  model::WriteFittedModel(context.model_file, model);
  WriteText(stem + ".json", json.dump(2) + "\n");
  WriteText(stem + ".md", markdown);

  if (options.json) {
    out << json.dump(2) << "\n";
    return;
  }
  fmt::print(out, "base e^2 = {:.4g} %   noise floor {:.4g} %\n", 100 * result.base.fit.error.total,
             100 * result.noise_floor);
  if (result.steps.empty()) fmt::print(out, "effect: none\n");
  for (std::size_t k = 0; k < result.steps.size(); ++k) {
    const auto& s = result.steps[k];
    fmt::print(out,
               "step {}: {:<32} evidence {:.4g} (threshold {:.3g})   e^2 {:.4g} % -> {:.4g} %\n",
               k + 1, diagnosis::EffectName(s.effect), s.evidence.value, s.evidence.threshold,
               100 * s.e2_before, 100 * s.e2_after);
  }
  fmt::print(out, "stopped: {}\n", result.stop_reason);
  fmt::print(out, "report: {}.md, {}.json; final model: {} ({:.1f} s)\n", stem, stem,
             context.model_file, result.seconds);
}

}  // namespace isolab::cli
