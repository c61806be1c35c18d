// isolab.Model: load a model file or build one from dicts; read and change its parameters.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>

#include "bindings.h"
#include "isolab/core/errors.h"
#include "model.h"
#include "yaml_conversion.h"

namespace py = pybind11;

namespace isolab::python {

// A tag for isolab.RunError, which the Python layer raises with the partial result.
struct RunFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

void BindErrors(py::module_& module) {
  py::register_exception<InputError>(module, "InputError", PyExc_ValueError).attr("__doc__") =
      "Bad input (a model, a record, an option): the message says where (file:line:column), "
      "which key, what was wrong and what was allowed.";
  py::register_exception<RunFailure>(module, "RunError", PyExc_RuntimeError).attr("__doc__") =
      "A run that stopped early (e.g. Newton did not converge); its `result` attribute holds the "
      "response up to the failure.";
}

namespace {

Model Load(const std::filesystem::path& path) { return Model::Load(path.string()); }

}  // namespace

void BindModel(py::module_& module) {
  py::class_<Model>(module, "Model",
                    "A model (the YAML model file's sections), checked by the model reader")
      .def_static("load", &Load, py::arg("path"),
                  "Reads a model file (YAML); raises InputError with the file, line and key.")
      .def_static(
          "from_dict",
          [](const py::dict& sections, const std::string& name) {
            return Model::FromTree(ToYaml(sections), name);
          },
          py::arg("sections"), py::arg("name") = "<dict>",
          "Builds a model from a dict with a model file's sections (units, isolation, "
          "structure, ...). It is written as YAML (Model.text) and read by the same reader as a "
          "file, so every error is the same InputError, naming `name`, the key path and the "
          "line of Model.text. Files it names (records) are relative to name's folder.")
      .def_property_readonly(
          "path", [](const Model& m) { return m.file().path; },
          "The file (or the name given to from_dict)")
      .def_property_readonly(
          "text", [](const Model& m) { return m.file().text; },
          "The YAML as read: the file's text, or the YAML written for a dict or a change")
      .def_property_readonly("description", [](const Model& m) { return m.file().description; })
      .def_property_readonly(
          "units",
          [](const Model& m) {
            const UnitSystem& u = m.file().units;
            return py::dict(py::arg("force") = u.force(), py::arg("length") = u.length(),
                            py::arg("time") = u.time());
          },
          "The model's units: {'force': 'kN', 'length': 'mm', 'time': 's'}")
      .def(
          "to_dict", [](const Model& m) { return FromYaml(m.tree()); },
          "The model's sections as a dict (what from_dict takes)")
      .def(
          "get",
          [](const Model& m, const std::string& key) {
            try {
              return FromYaml(m.Get(key));
            } catch (const std::out_of_range& error) {
              throw py::key_error(error.what());
            }
          },
          py::arg("key"),
          "The value at a key path: 'isolation.components[0].qd', or by a component's name "
          "'isolation.components.lrb.qd'. KeyError when there is none.")
      .def(
          "set",
          [](Model& m, const std::string& key, const py::handle& value) {
            try {
              m.Set(key, ToYaml(value, key));
            } catch (const std::out_of_range& error) {
              throw py::key_error(error.what());
            }
          },
          py::arg("key"), py::arg("value"),
          "Sets (or adds) the value at a key path and checks the model again; on InputError the "
          "model is unchanged. Quantities may carry units: m.set('isolation.components.lrb.qd', "
          "'40 kN').")
      .def("copy", [](const Model& m) { return Model(m); })
      .def("__repr__", [](const Model& m) {
        return "<isolab.Model " + m.file().path +
               (m.file().description.empty() ? "" : ": " + m.file().description) + ">";
      });
  module.def("load_model", &Load, py::arg("path"), "Reads a model file (Model.load)");
}

}  // namespace isolab::python
