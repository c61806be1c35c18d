// isolab.diagnose: `isolab diagnose` (which physical effect a base model misses, from cyclic
// tests) with the command line's options as keyword arguments. The result is the report the
// command line renders (diagnosis/report.h), as its JSON: the same object, parsed by the Python
// layer, so the candidates, explanations, verdict and identifiability are there too.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "isolab/analysis/test_data_checks.h"
#include "isolab/core/errors.h"
#include "isolab/diagnosis/diagnose.h"
#include "isolab/diagnosis/report.h"
#include "isolab/io/cyclic_test_file.h"
#include "isolab/model/fit_spec_file.h"

namespace py = pybind11;

namespace isolab::python {
namespace {

std::string Diagnose(const std::vector<std::string>& data, const std::string& base_path,
                     unsigned seed, long budget, const std::string& specimen,
                     const std::string& force_unit, const std::string& length_unit, int threads,
                     bool force, bool quiet) {
  const model::FitSpec base = model::LoadFitSpec(base_path);
  const bool units_given = !force_unit.empty() && !length_unit.empty();
  io::CyclicTestSet set = io::ReadCyclicTests(data, {force_unit, length_unit}, base.units);
  analysis::RequireUnits(set, units_given, "force_unit= and length_unit=");
  analysis::RequireFiniteSquares(set);
  const identification::FitData fit_data =
      diagnosis::AllCycles(std::move(set.tests), io::OneSpecimen(specimen, set.one_specimen));
  diagnosis::DiagnoseOptions options;
  options.seed = seed;
  options.budget = budget;
  options.threads = threads;
  if (!quiet) {
    options.progress = [](const std::string& line) { fmt::print(stderr, "  {}\n", line); };
  }
  diagnosis::ReportContext context;
  context.data_files = data;
  context.base_file = base_path;
  context.seed = seed;
  context.force_unit = base.units.force();
  context.length_unit = base.units.length();
  std::string json;
  try {
    const identification::ModelParametrisation parametrisation(base.components,
                                                               identification::ScalesOf(fit_data));
    analysis::RequireMoreSamplesThanParameters(fit_data, parametrisation, base_path);
    identification::FitOptions fit;
    fit.budget = budget;
    fit.threads = threads;
    analysis::RequireWorkWithin(analysis::EstimateFitWork(parametrisation, fit_data, fit),
                                analysis::kWorkLimit, force, "force=");
    py::gil_scoped_release release;
    const diagnosis::Diagnosis result = diagnosis::Diagnose(base.components, fit_data, options);
    json = diagnosis::RenderJson(diagnosis::BuildReport(result, fit_data, context));
  } catch (const InvalidParameter& error) {
    throw InputError({"diagnose"}, error.violation().Describe());
  } catch (const std::invalid_argument& error) {
    throw InputError({base_path}, error.what());
  }
  return json;
}

}  // namespace

void BindDiagnose(py::module_& module) {
  module.def("_diagnose", &Diagnose, py::arg("data"), py::arg("base"), py::arg("seed"),
             py::arg("budget"), py::arg("specimen"), py::arg("force_unit"), py::arg("length_unit"),
             py::arg("threads"), py::arg("force"), py::arg("quiet"));
}

}  // namespace isolab::python
