#include "building_diagnose_command.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "building_fit_inputs.h"
#include "diagnosis_files.h"
#include "isolab/analysis/building_diagnosis.h"
#include "isolab/core/errors.h"
#include "isolab/io/atomic_file.h"
#include "isolab/io/output_check.h"
#include "isolab/model/fitted_building_file.h"

namespace isolab::cli {
namespace {

// "ica50: d1 0.113, a6 0.185; lac100: ..."
std::string ChannelList(const analysis::BuildingFitResult& fit) {
  std::string text, motion;
  for (const analysis::ChannelFit& c : fit.channels) {
    const bool next = c.motion != motion;
    text += fmt::format("{}{}{} {:.3f}", text.empty() ? "" : (next ? "; " : ", "),
                        next ? c.motion + ": " : "", c.channel, c.nrmse);
    motion = c.motion;
  }
  return text;
}

// The building's part of the story, for the head of the report.
std::vector<std::string> BuildingLines(const analysis::BuildingDiagnosis& result) {
  std::vector<std::string> lines;
  lines.push_back(fmt::format(
      "The building, fitted by output error with its own isolation ({} parameters): mean NRMSE^2 "
      "{:.4g} -> {:.4g}; NRMSE per channel: {}",
      result.base_parameters, result.base.objective_start, result.base.objective,
      ChannelList(result.base)));
  lines.push_back(
      "The isolator's loops below are reconstructed per bearing from the measured absolute "
      "accelerations and the fitted building's masses, against the slab's measured "
      "displacement");
  if (result.refit) {
    lines.push_back(
        fmt::format("Refitted with the diagnosed isolation ({} parameters): NRMSE per channel: {}",
                    result.refit_parameters, ChannelList(*result.refit)));
  }
  lines.push_back(fmt::format("Building: {}", result.conclusion));
  return lines;
}

nlohmann::json FitJson(const analysis::BuildingFitResult& fit) {
  nlohmann::json json;
  json["objective_start"] = fit.objective_start;
  json["objective"] = fit.objective;
  json["effective_samples"] = fit.effective_samples;
  for (const analysis::FittedParameter& p : fit.parameters) {
    json["parameters"].push_back({{"name", p.name}, {"value", p.value}, {"sigma", p.sigma}});
  }
  for (const analysis::ChannelFit& c : fit.channels) {
    json["channels"].push_back({{"motion", c.motion},
                                {"channel", c.channel},
                                {"nrmse_start", c.nrmse_start},
                                {"nrmse", c.nrmse}});
  }
  return json;
}

}  // namespace

void RunBuildingDiagnoseCommand(const DiagnoseOptions& options, std::ostream& out) {
  if (!options.force_unit.empty() || !options.length_unit.empty()) {
    throw InputError({"command line"},
                     "--force-unit and --length-unit apply to cyclic tests, not to --building "
                     "(shake-table motions carry their units in the column names)");
  }
  if (options.force) {
    throw InputError({"command line"}, "--force applies to cyclic tests, not to --building");
  }
  const BuildingData data{options.data,
                          options.specimen,
                          options.offsets,
                          "",
                          "",
                          options.quiet,
                          "isolab diagnose --building"};
  BuildingFitInputs inputs = LoadBuildingFit(options.building, data);
  if (inputs.file.force_driven) {
    throw InputError({options.building},
                     "input: force: diagnose a force-driven test's displacement and force as a "
                     "cyclic test (isolab diagnose --base)");
  }
  diagnosis::ReportContext context;
  context.data_files = options.data;
  context.base_file = options.building;
  context.seed = options.seed;
  context.force_unit = inputs.model.units.force();
  context.length_unit = inputs.model.units.length();
  const DiagnosisFiles files =
      DiagnosisFiles::Plan(options.out, options.data.front(), options.plot, &context);
  io::CheckOutputs(inputs.files, files.outputs);
  const std::vector<analysis::BuildingMotion> motions = ReadBuildingMotions(&inputs, data);

  identification::FitOptions fit;
  fit.seed = options.seed;
  fit.budget = options.budget;
  fit.threads = options.threads;
  diagnosis::DiagnoseOptions settings;
  settings.seed = options.seed;
  settings.budget = options.budget;
  settings.threads = options.threads;
  if (!options.quiet) {
    fmt::print(stderr, "  {} parameters, {} motions ({}), budget {} simulations a fit\n",
               inputs.spec.parameters.size(), motions.size(),
               inputs.spec.sequential ? "one specimen, in order" : "each from rest",
               options.budget);
    settings.progress = [](const std::string& line) { fmt::print(stderr, "  {}\n", line); };
  }
  const analysis::BuildingDiagnosis result =
      analysis::DiagnoseBuilding(inputs.model, motions, inputs.spec, fit, settings);

  context.notes = BuildingLines(result);
  try {
    const std::string text = model::FittedBuildingText(
        result.Final(), fmt::format("diagnosed by isolab diagnose --building {} from {}",
                                    options.building, fmt::join(options.data, ", ")));
    io::WriteTextFileAtomically(context.model_file, [&](std::ostream& o) { o << text; });
  } catch (const InputError& error) {
    context.notes.push_back(fmt::format("the final model was not written: {}", error.what()));
    context.model_file.clear();
  }
  const diagnosis::DiagnosisReport report =
      diagnosis::BuildReport(result.isolator, result.loops, context);
  nlohmann::json json = nlohmann::json::parse(diagnosis::RenderJson(report));
  json["building"] = {{"base", FitJson(result.base)},   {"added", result.added},
                      {"confirmed", result.confirmed},  {"bic_base", result.bic_base},
                      {"bic_refit", result.bic_refit},  {"effective_samples", result.samples},
                      {"conclusion", result.conclusion}};
  if (result.refit) json["building"]["refit"] = FitJson(*result.refit);
  const std::string text = json.dump(2) + "\n";
  files.Write(report, text,
              fmt::format("{}: isolator loops from the fitted building",
                          std::filesystem::path(options.data.front()).filename().string()),
              options.quiet || options.json);
  if (options.json) {
    out << text;
    return;
  }
  out << diagnosis::RenderSummary(report) << files.Where(context);
}

}  // namespace isolab::cli
