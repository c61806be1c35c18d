// isolab.cyclic: `isolab cyclic` on one model at one amplitude, the loop as numpy views.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <memory>

#include "arrays.h"
#include "bindings.h"
#include "isolab/core/errors.h"
#include "isolab/hysteresis/cyclic_test.h"
#include "isolab/hysteresis/law_parameters.h"
#include "model.h"

namespace py = pybind11;

namespace isolab::python {
namespace {

struct CyclicRun {
  hysteresis::CyclicResult result;
  std::vector<std::string> components;
  io::UnitSystem units;
};

std::shared_ptr<CyclicRun> Cyclic(const Model& model, std::optional<double> amplitude,
                                  std::optional<double> period, std::optional<int> cycles,
                                  std::optional<int> steps_per_cycle) {
  const io::ModelFile& file = model.file();
  if (file.isolation.size() == 0) {
    throw InputError({file.path}, "no isolation section: nothing to test cyclically");
  }
  hysteresis::CyclicProtocol protocol = file.cyclic.value_or(hysteresis::CyclicProtocol{});
  if (!amplitude && !file.cyclic) {
    throw InputError({file.path}, "no amplitude: give amplitude= or a 'cyclic:' section");
  }
  if (amplitude) protocol.amplitude = *amplitude;
  if (period) protocol.period = *period;
  if (cycles) protocol.cycles = *cycles;
  if (steps_per_cycle) protocol.steps_per_cycle = *steps_per_cycle;
  try {
    protocol.Validate();
  } catch (const InvalidParameter& error) {
    throw InputError({"cyclic"}, error.violation().Describe());
  }
  auto run = std::make_shared<CyclicRun>(CyclicRun{{}, {}, file.units});
  for (const auto& component : file.isolation.components())
    run->components.push_back(component.name);
  py::gil_scoped_release release;
  run->result = hysteresis::RunCyclicTest(file.isolation, protocol);
  return run;
}

}  // namespace

void BindCyclic(py::module_& module) {
  py::class_<CyclicRun, std::shared_ptr<CyclicRun>>(
      module, "CyclicResult",
      "A cyclic test's loop (read-only numpy views, model units) and its cycles")
      .def_property_readonly("time",
                             [](const std::shared_ptr<CyclicRun>& r) {
                               const auto& v = r->result.loop.time;
                               return View(py::cast(r), v.data(), py::ssize_t(v.size()));
                             })
      .def_property_readonly("displacement",
                             [](const std::shared_ptr<CyclicRun>& r) {
                               const auto& v = r->result.loop.displacement;
                               return View(py::cast(r), v.data(), py::ssize_t(v.size()));
                             })
      .def_property_readonly("force",
                             [](const std::shared_ptr<CyclicRun>& r) {
                               const auto& v = r->result.loop.force;
                               return View(py::cast(r), v.data(), py::ssize_t(v.size()));
                             })
      .def_property_readonly(
          "component_force",
          [](const std::shared_ptr<CyclicRun>& r) {
            const auto& v = r->result.loop.component_force;
            const py::ssize_t width = py::ssize_t(r->components.size());
            return View(py::cast(r), v.data(), py::ssize_t(v.size()) / width, width);
          },
          "samples x components; columns: components")
      .def_readonly("components", &CyclicRun::components)
      .def_property_readonly("units",
                             [](const CyclicRun& r) {
                               return py::dict(py::arg("force") = r.units.force(),
                                               py::arg("length") = r.units.length(),
                                               py::arg("time") = r.units.time());
                             })
      .def_property_readonly("protocol",
                             [](const CyclicRun& r) {
                               const auto& p = r.result.protocol;
                               return py::dict(py::arg("amplitude") = p.amplitude,
                                               py::arg("period") = p.period,
                                               py::arg("cycles") = p.cycles,
                                               py::arg("steps_per_cycle") = p.steps_per_cycle);
                             })
      .def_property_readonly(
          "cycles",
          [](const CyclicRun& r) {
            py::list cycles;
            for (const auto& cycle : r.result.cycles) {
              py::list components;
              for (std::size_t c = 0; c < r.components.size(); ++c) {
                components.append(
                    py::dict(py::arg("name") = r.components[c],
                             py::arg("dissipated") = cycle.components[c].dissipated,
                             py::arg("slider_at_peak") = cycle.components[c].slider_at_peak));
              }
              cycles.append(py::dict(
                  py::arg("cycle") = cycle.index, py::arg("dissipated") = cycle.dissipated,
                  py::arg("peak_force") = cycle.peak_force, py::arg("components") = components));
            }
            return cycles;
          },
          "Per cycle, as `isolab cyclic --json`: cycle, dissipated, peak_force, components");
  module.def("_cyclic", &Cyclic, py::arg("model"), py::arg("amplitude") = py::none(),
             py::arg("period") = py::none(), py::arg("cycles") = py::none(),
             py::arg("steps_per_cycle") = py::none());
}

}  // namespace isolab::python
