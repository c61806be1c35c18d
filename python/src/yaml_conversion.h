// Python values <-> YAML trees, so that a model built from dicts goes through the same reader
// (and the same located errors) as a model file.
#pragma once

#include <pybind11/pybind11.h>
#include <yaml-cpp/yaml.h>

namespace isolab::python {

// dict -> map, list/tuple -> sequence, bool, int, float (shortest text that reads back
// exactly), str, None -> null; numpy scalars as their Python values. Anything else: TypeError
// naming `path`; a dict or list inside itself, or nesting deeper than 64 levels: ValueError
// naming the key path.
YAML::Node ToYaml(pybind11::handle value, const std::string& path = "");

// Scalars become int, float, bool or str, whichever reads the whole text (YAML 1.2 core rules).
pybind11::object FromYaml(const YAML::Node& node);

}  // namespace isolab::python
