// isolab.fit: `isolab fit` (an assembly's parameters identified from cyclic tests by CMA-ES)
// with the command line's options as keyword arguments; the result as `isolab fit --json` has it.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <optional>

#include "bindings.h"
#include "component_list.h"
#include "isolab/core/errors.h"
#include "isolab/identification/fit.h"
#include "isolab/identification/parametrisation.h"
#include "isolab/io/cyclic_test_file.h"
#include "isolab/model/fit_spec_file.h"

namespace py = pybind11;

namespace isolab::python {
namespace {

py::dict Fit(const std::vector<std::string>& data, const std::string& spec_path, unsigned seed,
             long budget, const std::vector<int>& cycles, const std::string& specimen,
             const std::string& force_unit, const std::string& length_unit, bool quiet) {
  const model::FitSpec spec = model::LoadFitSpec(spec_path);
  io::CyclicTestSet set = io::ReadCyclicTests(data, {force_unit, length_unit}, spec.units);
  const bool one_specimen = io::OneSpecimen(specimen, set.one_specimen);
  identification::FitData fit_data;
  try {
    fit_data = identification::SelectCycles(std::move(set.tests), cycles, one_specimen);
  } catch (const std::invalid_argument& error) {
    throw InputError({"cycles"}, error.what());
  }
  std::optional<identification::ModelParametrisation> model;
  try {
    model.emplace(spec.components, identification::ScalesOf(fit_data));
  } catch (const std::invalid_argument& error) {
    throw InputError({spec.path}, error.what());
  }
  identification::FitOptions options;
  options.seed = seed;
  options.budget = budget;
  if (!quiet) {
    options.progress = [](const identification::FitProgress& p) {
      fmt::print(stderr, "  {} generation {:5d}, {:8d} evaluations, best e^2 = {:.6g} %\n",
                 p.polishing ? "polish    " : "CMA-ES    ", p.generation, p.evaluations,
                 100 * p.best);
    };
  }
  identification::FitResult result;
  {
    py::gil_scoped_release release;
    result = identification::Fit(*model, fit_data, options);
  }
  py::dict json;
  json["e2"] = result.error.total;
  py::dict per_test;
  for (std::size_t i = 0; i < fit_data.tests.size(); ++i) {
    per_test[py::str(fit_data.tests[i].name)] = result.error.per_test[i];
  }
  json["e2_per_test"] = per_test;
  json["components"] = ComponentList(spec.components, result.mathematical);
  json["units"] =
      py::dict(py::arg("force") = spec.units.force(), py::arg("length") = spec.units.length());
  json["evaluations"] = result.evaluations;
  json["restarts"] = result.restarts;
  json["seconds"] = result.seconds;
  json["seed"] = seed;
  json["one_specimen"] = one_specimen;
  return json;
}

}  // namespace

void BindFit(py::module_& module) {
  module.def("_fit", &Fit, py::arg("data"), py::arg("model"), py::arg("seed"), py::arg("budget"),
             py::arg("cycles"), py::arg("specimen"), py::arg("force_unit"), py::arg("length_unit"),
             py::arg("quiet"));
}

}  // namespace isolab::python
