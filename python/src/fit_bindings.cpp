// isolab.fit: `isolab fit` (an assembly's parameters identified from cyclic tests by CMA-ES,
// cyclic/cyclic_fit.h) with the command line's options as keyword arguments; the result as
// `isolab fit --json` has it. It writes no model file.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "isolab/cyclic/cyclic_fit.h"
#include "search_options.h"

namespace py = pybind11;

namespace isolab::python {
namespace {

py::dict Fit(const std::vector<std::string>& data, const std::string& spec_path, unsigned seed,
             long budget, const std::vector<int>& cycles, const std::string& specimen,
             const std::string& force_unit, const std::string& length_unit, int threads, bool force,
             bool quiet) {
  cyclic::CyclicFitRequest request;
  request.data = data;
  request.spec_path = spec_path;
  request.cycles = cycles;
  request.specimen = specimen;
  request.force_unit = force_unit;
  request.length_unit = length_unit;
  request.search = SearchOptions("fit", seed, budget, threads);
  request.force = force;
  request.names = {"force_unit= and length_unit=", "cycles", "", "force="};
  cyclic::CyclicFitProblem problem = cyclic::PrepareCyclicFit(std::move(request));
  if (!quiet) {
    problem.request.search.progress = cyclic::PrintCyclicFitProgress;
  }
  cyclic::CyclicFitOutcome outcome;
  {
    py::gil_scoped_release release;
    outcome = cyclic::FitCyclicTests(problem);
  }
  return py::module_::import("json").attr("loads")(cyclic::CyclicFitJson(problem, outcome).dump());
}

}  // namespace

void BindFit(py::module_& module) {
  module.def("_fit", &Fit, py::arg("data"), py::arg("model"), py::arg("seed"), py::arg("budget"),
             py::arg("cycles"), py::arg("specimen"), py::arg("force_unit"), py::arg("length_unit"),
             py::arg("threads"), py::arg("force"), py::arg("quiet"));
}

}  // namespace isolab::python
