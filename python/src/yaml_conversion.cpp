#include "yaml_conversion.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <string>
#include <vector>

namespace py = pybind11;

namespace isolab::python {
namespace {

std::string Child(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

// A model file's sections nest five or six levels; far more is a mistake, and each level costs
// a C++ stack frame here and in the YAML writer, so a deep enough dict would overflow the stack.
constexpr std::size_t kMaxDepth = 64;

std::string Named(const std::string& path) { return path.empty() ? "the model" : path; }

// The dicts and lists being converted, outermost first, with their key paths: a container met
// again inside itself is a cycle, which would otherwise recurse without end.
struct Ancestors {
  std::vector<std::pair<PyObject*, std::string>> open;
};

YAML::Node Convert(py::handle value, const std::string& path, Ancestors* ancestors);

YAML::Node ConvertContainer(py::handle value, const std::string& path, Ancestors* ancestors) {
  const auto found = std::find_if(ancestors->open.begin(), ancestors->open.end(),
                                  [&](const auto& entry) { return entry.first == value.ptr(); });
  if (found != ancestors->open.end()) {
    throw py::value_error(fmt::format(
        "{}: refers back to {} (a dict or list inside itself): a model is a tree of dicts and "
        "lists",
        Named(path), Named(found->second)));
  }
  if (ancestors->open.size() >= kMaxDepth) {
    throw py::value_error(fmt::format(
        "{}: nested deeper than {} dicts and lists (a model's sections nest a few levels)",
        Named(path), kMaxDepth));
  }
  ancestors->open.emplace_back(value.ptr(), path);
  YAML::Node node;
  if (py::isinstance<py::dict>(value)) {
    node = YAML::Node(YAML::NodeType::Map);
    for (const auto& [key, item] : value.cast<py::dict>()) {
      const std::string name = py::str(key).cast<std::string>();
      node[name] = Convert(item, Child(path, name), ancestors);
    }
  } else {
    node = YAML::Node(YAML::NodeType::Sequence);
    std::size_t i = 0;
    for (const py::handle item : value) {
      node.push_back(Convert(item, fmt::format("{}[{}]", path, i++), ancestors));
    }
  }
  ancestors->open.pop_back();
  return node;
}

YAML::Node Convert(py::handle value, const std::string& path, Ancestors* ancestors) {
  if (value.is_none()) return YAML::Node(YAML::NodeType::Null);
  // bool before int: a Python bool is an int.
  if (py::isinstance<py::bool_>(value)) return YAML::Node(value.cast<bool>() ? "true" : "false");
  if (py::isinstance<py::str>(value)) return YAML::Node(value.cast<std::string>());
  if (py::isinstance<py::dict>(value) || py::isinstance<py::list>(value) ||
      py::isinstance<py::tuple>(value)) {
    return ConvertContainer(value, path, ancestors);
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

}  // namespace

YAML::Node ToYaml(py::handle value, const std::string& path) {
  Ancestors ancestors;
  return Convert(value, path, &ancestors);
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
