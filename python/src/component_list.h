// Fitted components as the command line's JSON lists them: name, type and the mathematical
// parameters by key.
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "isolab/hysteresis/law_parameters.h"
#include "isolab/identification/parametrisation.h"

namespace isolab::python {

inline pybind11::dict ParameterDict(hysteresis::LawType type, const std::vector<double>& values) {
  const auto keys = hysteresis::ParameterKeys(type, hysteresis::ParameterForm::kMathematical);
  pybind11::dict parameters;
  for (std::size_t k = 0; k < keys.size(); ++k) {
    parameters[pybind11::str(std::string(keys[k]))] = values[k];
  }
  return parameters;
}

inline pybind11::dict ComponentDict(const identification::ComponentSpec& component,
                                    const std::vector<double>& mathematical) {
  return pybind11::dict(pybind11::arg("name") = component.name,
                        pybind11::arg("type") = std::string(hysteresis::LawName(component.type)),
                        pybind11::arg("parameters") = ParameterDict(component.type, mathematical));
}

inline pybind11::list ComponentList(const std::vector<identification::ComponentSpec>& components,
                                    const std::vector<std::vector<double>>& mathematical) {
  pybind11::list list;
  for (std::size_t c = 0; c < components.size(); ++c) {
    list.append(ComponentDict(components[c], mathematical[c]));
  }
  return list;
}

}  // namespace isolab::python
