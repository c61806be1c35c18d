#include "isolab/io/model_file.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "yaml_reader.h"

namespace isolab::io {
namespace {

using hysteresis::Component;
using hysteresis::LawParameters;
using hysteresis::LawType;
using hysteresis::ParameterForm;

constexpr std::string_view kForceUnits[] = {"N", "kN", "MN", "lbf", "kip"};
constexpr std::string_view kLengthUnits[] = {"m", "cm", "mm", "in", "ft"};
constexpr std::string_view kTimeUnits[] = {"s", "ms"};

std::string ReadUnit(const YamlReader& reader, const YAML::Node& units, const std::string& path,
                     std::string_view key, std::span<const std::string_view> allowed) {
  const std::string child_path = ChildPath(path, key);
  const YAML::Node node = units[std::string(key)];
  if (!node.IsDefined()) return {};
  const std::string unit = reader.ReadString(node, child_path);
  if (std::find(allowed.begin(), allowed.end(), unit) == allowed.end()) {
    reader.Fail(node, child_path,
                fmt::format("'{}' is not a {} unit (expected one of: {})", unit, key,
                            fmt::join(allowed, ", ")));
  }
  return unit;
}

Units ReadUnits(const YamlReader& reader, const YAML::Node& root) {
  const YAML::Node node = reader.Require(root, "", "units");
  reader.RequireMap(node, "units");
  reader.CheckKeys(node, "units", {"force", "length", "time"});
  Units units;
  units.force = ReadUnit(reader, node, "units", "force", kForceUnits);
  units.length = ReadUnit(reader, node, "units", "length", kLengthUnits);
  const std::string time = ReadUnit(reader, node, "units", "time", kTimeUnits);
  if (units.force.empty()) reader.Require(node, "units", "force");
  if (units.length.empty()) reader.Require(node, "units", "length");
  if (!time.empty()) units.time = time;
  return units;
}

// The keys a component of this type may carry in either form, for "unknown key" hints.
std::vector<std::string_view> AllowedComponentKeys(LawType type) {
  std::vector<std::string_view> keys = {"name", "type"};
  for (const ParameterForm form : {ParameterForm::kMathematical, ParameterForm::kMechanical}) {
    for (const std::string_view key : hysteresis::ParameterKeys(type, form)) {
      if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
    }
  }
  return keys;
}

bool Contains(std::span<const std::string_view> keys, std::string_view key) {
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}

// Which form a component's keys are written in; both forms in one component is an error.
ParameterForm DetectForm(const YamlReader& reader, const YAML::Node& node, const std::string& path,
                         LawType type) {
  const auto math = hysteresis::ParameterKeys(type, ParameterForm::kMathematical);
  const auto mech = hysteresis::ParameterKeys(type, ParameterForm::kMechanical);
  std::string math_key, mech_key;
  for (const auto& entry : node) {
    const std::string key = entry.first.Scalar();  // CheckKeys made sure keys are scalars
    const bool in_math = Contains(math, key), in_mech = Contains(mech, key);
    if (in_math && !in_mech && math_key.empty()) math_key = key;
    if (in_mech && !in_math && mech_key.empty()) mech_key = key;
  }
  if (!math_key.empty() && !mech_key.empty()) {
    reader.Fail(
        node, path,
        fmt::format("mixes mathematical ({}) and mechanical ({}) parameters; give one form: "
                    "{} or {}",
                    math_key, mech_key, fmt::join(math, ", "), fmt::join(mech, ", ")));
  }
  return mech_key.empty() ? ParameterForm::kMathematical : ParameterForm::kMechanical;
}

Component ReadComponent(const YamlReader& reader, const YAML::Node& node, const std::string& path,
                        std::size_t index) {
  reader.RequireMap(node, path);
  const YAML::Node type_node = reader.Require(node, path, "type");
  const std::string type_name = reader.ReadString(type_node, ChildPath(path, "type"));
  const auto type = hysteresis::LawTypeFromName(type_name);
  if (!type) {
    std::vector<std::string_view> names;
    for (const LawType t : hysteresis::AllLawTypes()) names.push_back(hysteresis::LawName(t));
    const std::string_view nearest = NearestWord(type_name, names);
    reader.Fail(type_node, ChildPath(path, "type"),
                fmt::format("'{}' is not an element law{} (expected one of: {})", type_name,
                            nearest.empty() ? "" : fmt::format("; did you mean '{}'?", nearest),
                            fmt::join(names, ", ")));
  }
  reader.CheckKeys(node, path, AllowedComponentKeys(*type));

  const ParameterForm form = DetectForm(reader, node, path, *type);
  const auto keys = hysteresis::ParameterKeys(*type, form);
  std::vector<double> values(keys.size(), NAN);
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const YAML::Node value = node[std::string(keys[i])];
    if (value.IsDefined()) values[i] = reader.ReadNumber(value, ChildPath(path, keys[i]));
  }

  std::string name = fmt::format("c{}", index + 1);
  if (node["name"].IsDefined()) name = reader.ReadString(node["name"], ChildPath(path, "name"));

  try {
    return Component{name, LawParameters::Make(*type, form, values)};
  } catch (const InvalidParameter& error) {
    const ParameterViolation& violation = error.violation();
    const YAML::Node at = node[violation.key];
    if (at.IsDefined()) {
      throw InputError(reader.Locate(at), fmt::format("{}.{}", path, violation.Describe()));
    }
    reader.Fail(
        node, path,
        fmt::format("missing key '{}' ({}; {} in {} form takes {})", violation.key, violation.rule,
                    type_name, form == ParameterForm::kMathematical ? "mathematical" : "mechanical",
                    fmt::join(keys, ", ")));
  }
}

hysteresis::ParallelAssembly ReadIsolation(const YamlReader& reader, const YAML::Node& root) {
  const YAML::Node node = reader.Require(root, "", "isolation");
  reader.RequireMap(node, "isolation");
  reader.CheckKeys(node, "isolation", {"components"});
  const YAML::Node list = reader.Require(node, "isolation", "components");
  const std::string path = "isolation.components";
  reader.RequireSequence(list, path);
  if (list.size() == 0) reader.Fail(list, path, "the list is empty; give at least one component");
  std::vector<Component> components;
  for (std::size_t i = 0; i < list.size(); ++i) {
    components.push_back(ReadComponent(reader, list[i], IndexPath(path, i), i));
    for (std::size_t j = 0; j + 1 < components.size(); ++j) {
      if (components[j].name == components.back().name) {
        reader.Fail(
            list[i], IndexPath(path, i),
            fmt::format("name '{}' is already used by component {}", components[j].name, j));
      }
    }
  }
  return hysteresis::ParallelAssembly(std::move(components));
}

hysteresis::CyclicProtocol ReadCyclic(const YamlReader& reader, const YAML::Node& node) {
  const std::string path = "cyclic";
  reader.RequireMap(node, path);
  reader.CheckKeys(node, path, {"amplitude", "period", "cycles", "steps_per_cycle"});
  hysteresis::CyclicProtocol protocol;
  protocol.amplitude =
      reader.ReadNumber(reader.Require(node, path, "amplitude"), "cyclic.amplitude");
  if (node["period"]) protocol.period = reader.ReadNumber(node["period"], "cyclic.period");
  if (node["cycles"]) protocol.cycles = reader.ReadInteger(node["cycles"], "cyclic.cycles");
  if (node["steps_per_cycle"]) {
    protocol.steps_per_cycle =
        reader.ReadInteger(node["steps_per_cycle"], "cyclic.steps_per_cycle");
  }
  try {
    protocol.Validate();
  } catch (const InvalidParameter& error) {
    const YAML::Node at = node[error.violation().key];
    throw InputError(reader.Locate(at.IsDefined() ? at : node),
                     fmt::format("cyclic.{}", error.violation().Describe()));
  }
  return protocol;
}

}  // namespace

ModelFile LoadModelFile(const std::string& path) {
  const YamlReader reader(path);
  const YAML::Node root = reader.LoadFile();
  reader.RequireMap(root, "");
  reader.CheckKeys(root, "", {"description", "units", "isolation", "cyclic"});

  ModelFile model;
  model.path = path;
  if (root["description"])
    model.description = reader.ReadString(root["description"], "description");
  model.units = ReadUnits(reader, root);
  model.isolation = ReadIsolation(reader, root);
  if (root["cyclic"]) model.cyclic = ReadCyclic(reader, root["cyclic"]);
  return model;
}

}  // namespace isolab::io
