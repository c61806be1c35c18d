// isolab.diagnose: `isolab diagnose` (which physical effect a base model misses, from cyclic
// tests) with the command line's options as keyword arguments. The result is the report the
// command line renders (diagnosis/report.h), as its JSON: the same object, parsed by the Python
// layer, so the candidates, explanations, verdict and identifiability are there too.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "isolab/core/errors.h"
#include "isolab/cyclic/cyclic_diagnosis.h"

namespace py = pybind11;

namespace isolab::python {
namespace {

std::string Diagnose(const std::vector<std::string>& data, const std::string& base_path,
                     unsigned seed, long budget, const std::string& specimen,
                     const std::string& force_unit, const std::string& length_unit, int threads,
                     bool force, bool quiet) {
  cyclic::CyclicDiagnosisRequest request;
  request.data = data;
  request.base_path = base_path;
  request.specimen = specimen;
  request.force_unit = force_unit;
  request.length_unit = length_unit;
  request.settings.seed = seed;
  request.settings.budget = budget;
  request.settings.threads = threads;
  request.force = force;
  request.names.units = "force_unit= and length_unit=";
  request.names.force = "force=";
  if (!quiet) {
    request.settings.progress = [](const std::string& line) { fmt::print(stderr, "  {}\n", line); };
  }
  try {
    const cyclic::CyclicDiagnosisProblem problem =
        cyclic::PrepareCyclicDiagnosis(std::move(request));
    diagnosis::ReportContext context;
    cyclic::NameCyclicDiagnosis(problem, &context);
    py::gil_scoped_release release;
    const diagnosis::Diagnosis result = cyclic::DiagnoseCyclicTests(problem);
    return diagnosis::RenderJson(diagnosis::BuildReport(result, problem.data, context));
  } catch (const InvalidParameter& error) {
    throw InputError({"diagnose"}, error.violation().Describe());
  }
}

}  // namespace

void BindDiagnose(py::module_& module) {
  module.def("_diagnose", &Diagnose, py::arg("data"), py::arg("base"), py::arg("seed"),
             py::arg("budget"), py::arg("specimen"), py::arg("force_unit"), py::arg("length_unit"),
             py::arg("threads"), py::arg("force"), py::arg("quiet"));
}

}  // namespace isolab::python
