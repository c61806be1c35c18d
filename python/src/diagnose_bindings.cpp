// isolab.diagnose: `isolab diagnose` (which physical effect a base model misses, from cyclic
// tests) with the command line's options as keyword arguments; the result as its JSON report has
// it (the effects, the steps with their evidence, the base and final models).
#include <fmt/format.h>
#include <pybind11/stl.h>

#include "bindings.h"
#include "component_list.h"
#include "isolab/core/errors.h"
#include "isolab/diagnosis/diagnose.h"
#include "isolab/diagnosis/discrepancy.h"
#include "isolab/diagnosis/effects.h"
#include "isolab/io/cyclic_test_file.h"
#include "isolab/model/fit_spec_file.h"

namespace py = pybind11;

namespace isolab::python {
namespace {

py::dict ModelDict(const diagnosis::FittedModel& model) {
  return py::dict(py::arg("e2") = model.fit.error.total, py::arg("bic") = model.bic,
                  py::arg("parameters") = model.parameters,
                  py::arg("components") = ComponentList(model.components, model.fit.mathematical));
}

py::dict Diagnose(const std::vector<std::string>& data, const std::string& base_path, unsigned seed,
                  long budget, const std::string& specimen, const std::string& force_unit,
                  const std::string& length_unit, bool quiet) {
  const model::FitSpec base = model::LoadFitSpec(base_path);
  io::CyclicTestSet set = io::ReadCyclicTests(data, {force_unit, length_unit}, base.units);
  const identification::FitData fit_data =
      diagnosis::AllCycles(std::move(set.tests), io::OneSpecimen(specimen, set.one_specimen));
  diagnosis::DiagnoseOptions options;
  options.seed = seed;
  options.budget = budget;
  if (!quiet) {
    options.progress = [](const std::string& line) { fmt::print(stderr, "  {}\n", line); };
  }
  diagnosis::Diagnosis result;
  try {
    py::gil_scoped_release release;
    result = diagnosis::Diagnose(base.components, fit_data, options);
  } catch (const std::invalid_argument& error) {
    throw InputError({base_path}, error.what());
  }
  py::list steps, effects;
  for (const auto& step : result.steps) {
    const std::string effect(diagnosis::EffectName(step.effect));
    effects.append(effect);
    steps.append(
        py::dict(py::arg("effect") = effect,
                 py::arg("evidence") = py::dict(py::arg("statistic") = step.evidence.statistic,
                                                py::arg("value") = step.evidence.value,
                                                py::arg("threshold") = step.evidence.threshold,
                                                py::arg("supported") = step.evidence.Supported(),
                                                py::arg("finding") = step.evidence.finding),
                 py::arg("e2_before") = step.e2_before, py::arg("e2_after") = step.e2_after,
                 py::arg("bic_before") = step.bic_before, py::arg("bic_after") = step.bic_after,
                 py::arg("added") = ComponentDict(step.added, step.added_parameters)));
  }
  if (result.steps.empty()) effects.append("none");
  py::dict report;
  report["samples"] = result.samples;
  report["noise_floor_e2"] = result.noise_floor;
  report["base"] = ModelDict(result.base);
  report["steps"] = steps;
  report["effects"] = effects;
  report["final"] = ModelDict(result.final_model);
  report["stop_reason"] = result.stop_reason;
  report["seconds"] = result.seconds;
  report["seed"] = seed;
  report["one_specimen"] = fit_data.one_specimen;
  return report;
}

}  // namespace

void BindDiagnose(py::module_& module) {
  module.def("_diagnose", &Diagnose, py::arg("data"), py::arg("base"), py::arg("seed"),
             py::arg("budget"), py::arg("specimen"), py::arg("force_unit"), py::arg("length_unit"),
             py::arg("quiet"));
}

}  // namespace isolab::python
