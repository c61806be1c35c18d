#include "building_diagnose_command.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <filesystem>

#include "diagnosis_files.h"
#include "isolab/building/building_diagnosis.h"
#include "isolab/building/building_diagnosis_report.h"
#include "isolab/building/building_fit_inputs.h"
#include "isolab/core/errors.h"
#include "isolab/io/atomic_file.h"
#include "isolab/io/output_check.h"
#include "isolab/model/fitted_building_file.h"

namespace isolab::cli {
void RunBuildingDiagnoseCommand(const DiagnoseOptions& options, const SearchRanks& ranks,
                                std::ostream& out) {
  if (!options.force_unit.empty() || !options.length_unit.empty()) {
    throw InputError({"command line"},
                     "--force-unit and --length-unit apply to cyclic tests, not to --building "
                     "(shake-table motions carry their units in the column names)");
  }
  if (options.force) {
    throw InputError({"command line"}, "--force applies to cyclic tests, not to --building");
  }
  const building::BuildingData data{options.data,
                                    options.specimen,
                                    options.offsets,
                                    "",
                                    "",
                                    options.quiet || !ranks.reports(),
                                    "isolab diagnose --building",
                                    {}};
  building::BuildingFitInputs inputs = building::LoadBuildingFit(options.building, data);
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
  const std::vector<building::BuildingMotion> motions =
      building::ReadBuildingMotions(&inputs, data);

  identification::FitOptions fit;
  fit.seed = options.seed;
  fit.budget = options.budget;
  fit.threads = ranks.Threads(options.threads);
  fit.spread = ranks.spread();
  diagnosis::DiagnoseOptions settings;
  settings.seed = options.seed;
  settings.budget = options.budget;
  settings.threads = fit.threads;
  settings.spread = fit.spread;
  if (!options.quiet && ranks.reports()) {
    fmt::print(stderr, "  {} parameters, {} motions ({}), budget {} simulations a fit\n",
               inputs.spec.parameters.size(), motions.size(),
               inputs.spec.sequential ? "one specimen, in order" : "each from rest",
               options.budget);
    settings.progress = [](const std::string& line) { fmt::print(stderr, "  {}\n", line); };
  }
  const building::BuildingDiagnosis result =
      building::DiagnoseBuilding(inputs.model, motions, inputs.spec, fit, settings);
  if (!ranks.reports()) return;

  try {
    const std::string text = model::FittedBuildingText(
        result.Final(), fmt::format("diagnosed by isolab diagnose --building {} from {}",
                                    options.building, fmt::join(options.data, ", ")));
    io::WriteTextFileAtomically(context.model_file, [&](std::ostream& o) { o << text; });
  } catch (const InputError& error) {
    context.notes.push_back(fmt::format("the final model was not written: {}", error.what()));
    context.model_file.clear();
  }
  const diagnosis::DiagnosisReport report = building::BuildBuildingReport(result, context);
  const std::string text = building::BuildingDiagnosisJson(result, report) + "\n";
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
