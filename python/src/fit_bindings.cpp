// isolab.fit: `isolab fit` (an assembly's parameters identified from cyclic tests by CMA-ES)
// with the command line's options as keyword arguments, and its checks (units, magnitudes,
// samples, work); the result as `isolab fit --json` has it.
#include <fmt/format.h>
#include <pybind11/stl.h>

#include <optional>

#include "bindings.h"
#include "component_list.h"
#include "isolab/analysis/test_data_checks.h"
#include "isolab/core/errors.h"
#include "isolab/identification/fit.h"
#include "isolab/identification/identifiability.h"
#include "isolab/identification/parametrisation.h"
#include "isolab/io/cyclic_test_file.h"
#include "isolab/model/fit_spec_file.h"
#include "search_options.h"

namespace py = pybind11;

namespace isolab::python {
namespace {

py::dict Fit(const std::vector<std::string>& data, const std::string& spec_path, unsigned seed,
             long budget, const std::vector<int>& cycles, const std::string& specimen,
             const std::string& force_unit, const std::string& length_unit, int threads, bool force,
             bool quiet) {
  const model::FitSpec spec = model::LoadFitSpec(spec_path);
  const bool units_given = !force_unit.empty() && !length_unit.empty();
  io::CyclicTestSet set = io::ReadCyclicTests(data, {force_unit, length_unit}, spec.units);
  analysis::RequireUnits(set, units_given, "force_unit= and length_unit=");
  analysis::RequireFiniteSquares(set);
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
  analysis::RequireMoreSamplesThanParameters(fit_data, *model, spec.path);
  identification::FitOptions options = SearchOptions("fit", seed, budget, threads);
  analysis::RequireWorkWithin(analysis::EstimateFitWork(*model, fit_data, options),
                              analysis::kWorkLimit, force, "force=");
  if (!quiet) {
    options.progress = [](const identification::FitProgress& p) {
      fmt::print(stderr, "  {} generation {:5d}, {:8d} evaluations, best e^2 = {:.6g} %\n",
                 p.polishing ? "polish    " : "CMA-ES    ", p.generation, p.evaluations,
                 100 * p.best);
    };
  }
  identification::FitResult result;
  try {
    py::gil_scoped_release release;
    result = identification::Fit(*model, fit_data, options);
  } catch (const std::invalid_argument& error) {
    throw InputError({data.front()}, error.what());
  }
  py::dict json;
  json["e2"] = result.error.total;
  json["e2_mean"] = result.error.Mean();
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
  json["stop"] = result.stop == identification::FitStop::kConverged ? "converged" : "budget";
  json["stop_reason"] = result.stop_reason;
  json["identifiability"] =
      identification::AssessIdentifiability(*model, fit_data, result).Findings();
  json["seed"] = seed;
  json["one_specimen"] = one_specimen;
  return json;
}

}  // namespace

void BindFit(py::module_& module) {
  module.def("_fit", &Fit, py::arg("data"), py::arg("model"), py::arg("seed"), py::arg("budget"),
             py::arg("cycles"), py::arg("specimen"), py::arg("force_unit"), py::arg("length_unit"),
             py::arg("threads"), py::arg("force"), py::arg("quiet"));
}

}  // namespace isolab::python
