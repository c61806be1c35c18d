// isolab.cyclic: `isolab cyclic` on one model, each loop as numpy views; with a path or an orbit,
// the model driven along it (cyclic/model_replay.h), each run as a dict of numpy arrays.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <memory>

#include "arrays.h"
#include "bindings.h"
#include "isolab/core/errors.h"
#include "isolab/cyclic/cyclic_campaign.h"
#include "isolab/cyclic/model_replay.h"
#include "isolab/hysteresis/cyclic_test.h"
#include "isolab/hysteresis/law_parameters.h"
#include "isolab/identification/synthetic_tests.h"
#include "isolab/io/cyclic_test_file.h"
#include "isolab/io/output_check.h"
#include "isolab/model/model_file.h"
#include "model.h"

namespace py = pybind11;

namespace isolab::python {
namespace {

struct CyclicRun {
  hysteresis::CyclicResult result;
  std::vector<std::string> components;
  UnitSystem units;
};

// One result per period and amplitude (periods outer), as `isolab cyclic` runs them; with
// `test_data`, the loops also written as cyclic test data (noise and seed as --noise, --seed).
std::vector<std::shared_ptr<CyclicRun>> Cyclic(
    const Model& model, const std::vector<double>& amplitudes, const std::vector<double>& periods,
    std::optional<int> cycles, std::optional<int> steps_per_cycle, bool sequential,
    const std::string& test_data, double noise, unsigned seed) {
  const model::ModelFile& file = model.file();
  if (!(noise >= 0.0 && noise <= 1.0)) throw InputError({"noise"}, "must be in [0, 1]");
  cyclic::CyclicRequest request{amplitudes, periods,  cycles,      steps_per_cycle,
                                sequential, "cyclic", "amplitude="};
  if (!test_data.empty()) {  // as `isolab cyclic --test-data`: never over the model's own files
    std::vector<std::string> inputs = file.included_files;
    if (!file.path.empty()) inputs.push_back(file.path);
    io::CheckOutputs(inputs, {test_data});
  }
  std::vector<hysteresis::CyclicResult> loops;
  {
    py::gil_scoped_release release;
    loops = cyclic::RunCyclicCampaign(file, request);
  }
  if (!test_data.empty()) {
    std::vector<identification::CyclicTestData> tests =
        cyclic::TestsFromLoops(loops, periods.size() > 1);
    identification::AddForceNoise(&tests, noise, seed);
    io::WriteCyclicTests(test_data, tests, file.units, sequential);
  }
  std::vector<std::string> components;
  for (const auto& component : file.isolation.components()) components.push_back(component.name);
  std::vector<std::shared_ptr<CyclicRun>> runs;
  for (hysteresis::CyclicResult& loop : loops) {
    runs.push_back(std::make_shared<CyclicRun>(CyclicRun{std::move(loop), components, file.units}));
  }
  return runs;
}

py::array Vectors(const std::vector<hysteresis::Vec2>& values, bool plan) {
  py::array_t<double> array(plan ? std::vector<py::ssize_t>{py::ssize_t(values.size()), 2}
                                 : std::vector<py::ssize_t>{py::ssize_t(values.size())});
  double* data = array.mutable_data();
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (plan) {
      data[2 * k] = values[k].x, data[2 * k + 1] = values[k].y;
    } else {
      data[k] = values[k].x;
    }
  }
  return array;
}

py::dict ReplayDict(const std::string& model, const cyclic::ReplayResult& r,
                    const UnitSystem& units) {
  py::dict out;
  out["model"] = model;
  out["path"] = r.name;
  out["plan"] = r.plan;
  out["units"] = py::dict(py::arg("force") = units.force(), py::arg("length") = units.length(),
                          py::arg("time") = units.time());
  out["time"] = py::array_t<double>(py::ssize_t(r.time.size()), r.time.data());
  out["displacement"] = Vectors(r.displacement, r.plan);
  out["force"] = Vectors(r.force, r.plan);
  out["components"] = r.components;
  const std::size_t m = r.components.size();
  py::list components;
  for (std::size_t c = 0; c < m; ++c) {
    std::vector<hysteresis::Vec2> force;
    for (std::size_t k = 0; k < r.time.size(); ++k) force.push_back(r.component_force[k * m + c]);
    components.append(Vectors(force, r.plan));
  }
  out["component_force"] = components;
  out["dissipated"] = py::array_t<double>(py::ssize_t(r.dissipated.size()), r.dissipated.data());
  out["peak_displacement"] = r.peak_displacement;
  out["peak_force"] = r.peak_force;
  if (!r.measured.empty()) out["measured"] = Vectors(r.measured, r.plan);
  if (r.comparison) {
    out["comparison"] =
        py::dict(py::arg("e2") = r.comparison->e2, py::arg("nrmse") = r.comparison->nrmse,
                 py::arg("error_over_range") = r.comparison->error_over_range,
                 py::arg("peak_measured") = r.comparison->peak_measured,
                 py::arg("peak_modelled") = r.comparison->peak_modelled);
  }
  py::list cycles;
  for (const auto& c : r.cycles) {
    cycles.append(py::dict(
        py::arg("cycle") = c.index, py::arg("dissipated") = c.dissipated,
        py::arg("peak_force") = c.peak_force,
        py::arg("displacement_at_end") =
            std::vector<double>{c.displacement_at_end.x, c.displacement_at_end.y},
        py::arg("force_at_end") = std::vector<double>{c.force_at_end.x, c.force_at_end.y}));
  }
  out["cycles"] = cycles;
  return out;
}

// A model (or a plan model file's path) along paths from files, or round orbits; one dict per
// run, as `isolab cyclic --path/--orbit --json` lists them, with the histories as arrays.
py::list Replay(const py::object& model, const cyclic::ReplayRequest& request) {
  const model::ModelFile file = py::isinstance<Model>(model) ? model.cast<const Model&>().file()
                                                             : model::LoadModelFile(py::str(model));
  std::vector<cyclic::ReplayRun> runs;
  {
    py::gil_scoped_release release;
    runs = cyclic::ReplayModel(file, request, cyclic::OptionStyle::kPython);
  }
  py::list dicts;
  for (const cyclic::ReplayRun& run : runs) {
    dicts.append(ReplayDict(run.model, run.result, run.units));
  }
  return dicts;
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
  module.def("_cyclic", &Cyclic, py::arg("model"), py::arg("amplitudes"), py::arg("periods"),
             py::arg("cycles"), py::arg("steps_per_cycle"), py::arg("sequential"),
             py::arg("test_data"), py::arg("noise"), py::arg("seed"));
  module.def(
      "_replay",
      [](const py::object& model, const std::vector<std::string>& paths, const std::string& orbit,
         const std::vector<double>& amplitudes, const std::vector<double>& periods,
         std::optional<int> cycles, std::optional<int> steps_per_cycle, const std::string& isolator,
         bool uncoupled, const std::string& force_unit, const std::string& length_unit) {
        return Replay(model, {paths, orbit, amplitudes, periods, cycles, steps_per_cycle, isolator,
                              uncoupled, force_unit, length_unit});
      },
      py::arg("model"), py::arg("paths"), py::arg("orbit"), py::arg("amplitudes"),
      py::arg("periods"), py::arg("cycles"), py::arg("steps_per_cycle"), py::arg("isolator"),
      py::arg("uncoupled"), py::arg("force_unit"), py::arg("length_unit"));
}

}  // namespace isolab::python
