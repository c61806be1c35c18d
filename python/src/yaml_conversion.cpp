#include "yaml_conversion.h"

#include <fmt/format.h>

#include <charconv>
#include <string>

namespace py = pybind11;

namespace isolab::python {
namespace {

std::string Child(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

}  // namespace

YAML::Node ToYaml(py::handle value, const std::string& path) {
  if (value.is_none()) return YAML::Node(YAML::NodeType::Null);
  // bool before int: a Python bool is an int.
  if (py::isinstance<py::bool_>(value)) return YAML::Node(value.cast<bool>() ? "true" : "false");
  if (py::isinstance<py::str>(value)) return YAML::Node(value.cast<std::string>());
  if (py::isinstance<py::dict>(value)) {
    YAML::Node map(YAML::NodeType::Map);
    for (const auto& [key, item] : value.cast<py::dict>()) {
      const std::string name = py::str(key).cast<std::string>();
      map[name] = ToYaml(item, Child(path, name));
    }
    return map;
  }
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    YAML::Node sequence(YAML::NodeType::Sequence);
    std::size_t i = 0;
    for (const py::handle item : value) {
      sequence.push_back(ToYaml(item, fmt::format("{}[{}]", path, i++)));
    }
    return sequence;
  }
  // Integers (Python's and numpy's) have __index__; other numbers __float__.
  if (py::hasattr(value, "__index__")) {
    return YAML::Node(
        py::str(py::int_(py::reinterpret_borrow<py::object>(value))).cast<std::string>());
  }
  if (py::hasattr(value, "__float__")) {
    return YAML::Node(
        fmt::format("{}", py::float_(py::reinterpret_borrow<py::object>(value)).cast<double>()));
  }
  throw py::type_error(
      fmt::format("{}: a {} cannot go into a model (dict, list, str, number, "
                  "bool or None)",
                  path.empty() ? "model" : path,
                  py::str(value.get_type().attr("__name__")).cast<std::string>()));
}

py::object FromYaml(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Map: {
      py::dict dict;
      for (const auto& item : node) dict[py::str(item.first.Scalar())] = FromYaml(item.second);
      return dict;
    }
    case YAML::NodeType::Sequence: {
      py::list list;
      for (const auto& item : node) list.append(FromYaml(item));
      return list;
    }
    case YAML::NodeType::Scalar: {
      const std::string& text = node.Scalar();
      if (node.Tag() != "!") {  // plain, not quoted
        long integer = 0;
        auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), integer);
        if (error == std::errc() && end == text.data() + text.size()) return py::int_(integer);
        double number = 0.0;
        if (YAML::convert<double>::decode(node, number)) return py::float_(number);
        bool flag = false;
        if (YAML::convert<bool>::decode(node, flag)) return py::bool_(flag);
      }
      return py::str(text);
    }
    default:
      return py::none();
  }
}

}  // namespace isolab::python
