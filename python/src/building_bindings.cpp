// isolab.fit and isolab.diagnose with building=: `isolab fit --building` and `isolab diagnose
// --building` with the command line's options as keyword arguments. The specification, the model
// and the motions are read by the library's building-fit inputs, and the result is the JSON the
// command line prints with --json, built by the same library function (building_fit_report.h,
// building_diagnosis_report.h), for the Python layer to parse. The options of the cyclic tests
// only are refused in python/isolab/__init__.py before these are called.
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <optional>

#include "bindings.h"
#include "isolab/building/building_cross_validation.h"
#include "isolab/building/building_diagnosis.h"
#include "isolab/building/building_diagnosis_report.h"
#include "isolab/building/building_fit.h"
#include "isolab/building/building_fit_inputs.h"
#include "isolab/building/building_fit_report.h"
#include "isolab/building/building_fit_workflow.h"
#include "isolab/core/errors.h"
#include "isolab/io/atomic_file.h"
#include "isolab/io/output_check.h"
#include "isolab/model/fitted_building_file.h"
#include "search_options.h"

namespace py = pybind11;

namespace isolab::python {
namespace {

// The data options, refused (where they do not apply) under the names the Python user typed.
building::BuildingData Data(const std::vector<std::string>& data, const std::string& function,
                            const std::string& specimen, const std::string& offsets,
                            const std::string& force_unit, const std::string& length_unit,
                            bool quiet) {
  building::BuildingData read{data,
                              specimen,
                              offsets,
                              force_unit,
                              length_unit,
                              quiet,
                              fmt::format("isolab.{}(building=...)", function),
                              {function, "offsets=", "force_unit=", "length_unit="}};
  return read;
}

std::string FitBuilding(const std::vector<std::string>& data, const std::string& spec_path,
                        const std::string& output, unsigned seed, long budget, long global_budget,
                        const std::string& specimen, const std::string& offsets,
                        const std::string& force_unit, const std::string& length_unit, int threads,
                        bool cross_validate, bool model_form, bool quiet) {
  const building::BuildingData read =
      Data(data, "fit", specimen, offsets, force_unit, length_unit, quiet);
  building::BuildingFitInputs inputs = building::LoadBuildingFit(spec_path, read);
  // Where the command line writes it: beside the working directory, named after the spec.
  const std::string path =
      !output.empty() ? output : std::filesystem::path(spec_path).stem().string() + ".fitted.yaml";
  if (!cross_validate) io::CheckOutputs(inputs.files, {path});
  const std::vector<building::BuildingMotion> motions =
      building::ReadBuildingMotions(&inputs, read);
  const building::BuildingFitSpec& spec = inputs.spec;
  identification::FitOptions fit = SearchOptions("fit", seed, budget, threads, global_budget);
  if (!quiet) {
    fmt::print(stderr, "  {} parameters, {} motions ({}), budget {} simulations\n",
               spec.parameters.size(), motions.size(),
               spec.sequential ? "one specimen, in order" : "each from rest", budget);
    fit.progress = [](const identification::FitProgress& p) {
      fmt::print(stderr, "{}", building::BuildingFitProgressLine(p));
    };
  }
  const building::BuildingFitMode mode = cross_validate ? building::BuildingFitMode::kCrossValidate
                                         : model_form   ? building::BuildingFitMode::kModelForm
                                                        : building::BuildingFitMode::kFit;
  building::BuildingFitOutcome outcome;
  {
    py::gil_scoped_release release;
    outcome = building::RunBuildingFit(inputs.model, motions, spec, fit, mode);
  }
  if (!outcome.fit) return building::BuildingFitOutcomeJson(outcome, spec.sequential, "");
  const std::string text = model::FittedBuildingText(
      outcome.fit->fitted, fmt::format("identified by isolab.fit(building={}) from {}", spec_path,
                                       fmt::join(data, ", ")));
  io::WriteTextFileAtomically(path, [&](std::ostream& o) { o << text; });
  return building::BuildingFitOutcomeJson(outcome, spec.sequential, path);
}

std::string DiagnoseBuilding(const std::vector<std::string>& data, const std::string& spec_path,
                             unsigned seed, long budget, const std::string& specimen,
                             const std::string& offsets, int threads, bool quiet) {
  const building::BuildingData read = Data(data, "diagnose", specimen, offsets, "", "", quiet);
  building::BuildingFitInputs inputs = building::LoadBuildingFit(spec_path, read);
  if (inputs.file.force_driven) {
    throw InputError({spec_path},
                     "input: force: diagnose a force-driven test's displacement and force as a "
                     "cyclic test (isolab.diagnose(data, base))");
  }
  const std::vector<building::BuildingMotion> motions =
      building::ReadBuildingMotions(&inputs, read);
  const identification::FitOptions fit = SearchOptions("diagnose", seed, budget, threads);
  diagnosis::DiagnoseOptions settings;
  settings.seed = seed;
  settings.budget = budget;
  settings.threads = threads;
  if (!quiet) {
    fmt::print(stderr, "  {} parameters, {} motions ({}), budget {} simulations a fit\n",
               inputs.spec.parameters.size(), motions.size(),
               inputs.spec.sequential ? "one specimen, in order" : "each from rest", budget);
    settings.progress = [](const std::string& line) { fmt::print(stderr, "  {}\n", line); };
  }
  std::optional<building::BuildingDiagnosis> result;
  {
    py::gil_scoped_release release;
    result = building::DiagnoseBuilding(inputs.model, motions, inputs.spec, fit, settings);
  }
  // As the cyclic diagnosis from Python: the report without its files (the command line's).
  diagnosis::ReportContext context;
  context.data_files = data;
  context.base_file = spec_path;
  context.seed = seed;
  context.force_unit = inputs.model.units.force();
  context.length_unit = inputs.model.units.length();
  return building::BuildingDiagnosisJson(*result, building::BuildBuildingReport(*result, context));
}

}  // namespace

void BindBuilding(py::module_& module) {
  module.def("_fit_building", &FitBuilding, py::arg("data"), py::arg("building"), py::arg("output"),
             py::arg("seed"), py::arg("budget"), py::arg("global_budget"), py::arg("specimen"),
             py::arg("offsets"), py::arg("force_unit"), py::arg("length_unit"), py::arg("threads"),
             py::arg("cross_validate"), py::arg("model_form"), py::arg("quiet"));
  module.def("_diagnose_building", &DiagnoseBuilding, py::arg("data"), py::arg("building"),
             py::arg("seed"), py::arg("budget"), py::arg("specimen"), py::arg("offsets"),
             py::arg("threads"), py::arg("quiet"));
}

}  // namespace isolab::python
