// A bearing type's property modification factors (property_modification.h):
//
//   modification:                      # in isolation, or in a plan isolator entry
//     lrb:                             # a component's name
//       qd: {testing: [0.95, 1.1], ageing: [1.0, 1.15], specification: [0.85, 1.15]}
//       kd: {min: 0.9, max: 1.2}       # or the combined factors as the engineer states them
//
// Each pair is [min, max] with 0 < min <= 1 <= max; a factor not given is [1, 1].
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <string>
#include <vector>

#include "model_sections.h"

namespace isolab::model {

FactorPair CombineFactors(const FactorPair& testing, const FactorPair& ageing,
                          const FactorPair& specification) {
  return {(1.0 - kAgeingAdjustment * (1.0 - ageing.min)) * testing.min * specification.min,
          (1.0 + kAgeingAdjustment * (ageing.max - 1.0)) * testing.max * specification.max};
}

FactorPair PropertyFactors::Combined() const {
  return stated ? *stated : CombineFactors(testing, ageing, specification);
}

namespace {

void CheckMin(const YamlReader& reader, const YAML::Node& node, const std::string& path,
              double value) {
  if (!(value > 0.0 && value <= 1.0)) {
    reader.Fail(node, path,
                fmt::format("min = {:g} (a min factor must be > 0 and <= 1: it lowers or keeps "
                            "the nominal value)",
                            value));
  }
}

void CheckMax(const YamlReader& reader, const YAML::Node& node, const std::string& path,
              double value) {
  if (!(value >= 1.0)) {
    reader.Fail(node, path,
                fmt::format("max = {:g} (a max factor must be >= 1: it raises or keeps the "
                            "nominal value)",
                            value));
  }
}

FactorPair ReadPair(const YamlReader& reader, const YAML::Node& node, const std::string& path) {
  if (!node.IsSequence() || node.size() != 2) {
    reader.Fail(node, path, "expected a pair [min, max]");
  }
  FactorPair pair{reader.ReadNumber(node[0], path), reader.ReadNumber(node[1], path)};
  CheckMin(reader, node[0], path, pair.min);
  CheckMax(reader, node[1], path, pair.max);
  return pair;
}

}  // namespace

std::vector<PropertyFactors> ReadModification(const YamlReader& reader, const YAML::Node& node,
                                              const std::string& path,
                                              const hysteresis::ParallelAssembly& laws,
                                              const YAML::Node& components) {
  reader.RequireMap(node, path);
  std::vector<std::string> names;
  for (const hysteresis::Component& c : laws.components()) names.push_back(c.name);
  std::vector<PropertyFactors> properties;
  for (const auto& entry : node) {
    const std::string name = entry.first.Scalar();
    const std::string component_path = ChildPath(path, name);
    const auto found = std::find(names.begin(), names.end(), name);
    if (found == names.end()) {
      reader.Fail(entry.first, component_path,
                  fmt::format("no component is named '{}' (the bearing's components: {})", name,
                              fmt::join(names, ", ")));
    }
    const std::size_t index = static_cast<std::size_t>(found - names.begin());
    const hysteresis::LawType type = laws.components()[index].parameters.type();
    const YAML::Node component = components[index];
    reader.RequireMap(entry.second, component_path);
    for (const auto& property : entry.second) {
      const std::string key = property.first.Scalar();
      const std::string key_path = ChildPath(component_path, key);
      const auto is_parameter = [type](const std::string& k) {
        for (const auto form :
             {hysteresis::ParameterForm::kMathematical, hysteresis::ParameterForm::kMechanical}) {
          const auto keys = hysteresis::ParameterKeys(type, form);
          if (std::find(keys.begin(), keys.end(), k) != keys.end()) return true;
        }
        return false;
      };
      if (!is_parameter(key) || !component[key]) {
        // Only the law's parameters the component states can be scaled: those are listed.
        std::vector<std::string> given;
        for (const auto& k : component) {
          if (is_parameter(k.first.Scalar())) given.push_back(k.first.Scalar());
        }
        // A pendulum's period is its radius given another way: geometry, which testing, ageing
        // and the environment do not vary.
        const std::string why =
            key == "period" && type == hysteresis::LawType::kFrictionPendulum
                ? "'period' sets the pendulum's radius, its geometry, which property modification "
                  "factors do not vary"
                : fmt::format("'{}' is not a parameter {} gives", key, name);
        reader.Fail(property.first, key_path,
                    fmt::format("{} (it gives: {})", why, fmt::join(given, ", ")));
      }
      PropertyFactors factors;
      factors.component = index;
      factors.component_name = name;
      factors.key = key;
      factors.location = reader.Locate(property.second);
      const YAML::Node value = property.second;
      reader.RequireMap(value, key_path);
      if (value["min"] || value["max"]) {
        reader.CheckKeys(value, key_path, {"min", "max"});
        FactorPair stated;
        stated.min = reader.ReadNumber(reader.Require(value, key_path, "min"), key_path + ".min");
        stated.max = reader.ReadNumber(reader.Require(value, key_path, "max"), key_path + ".max");
        CheckMin(reader, value["min"], key_path + ".min", stated.min);
        CheckMax(reader, value["max"], key_path + ".max", stated.max);
        factors.stated = stated;
      } else {
        reader.CheckKeys(value, key_path, {"testing", "ageing", "specification"});
        if (value.size() == 0) {
          reader.Fail(value, key_path, "give testing, ageing, specification, or min and max");
        }
        if (value["testing"]) {
          factors.testing = ReadPair(reader, value["testing"], key_path + ".testing");
        }
        if (value["ageing"]) {
          factors.ageing = ReadPair(reader, value["ageing"], key_path + ".ageing");
        }
        if (value["specification"]) {
          factors.specification =
              ReadPair(reader, value["specification"], key_path + ".specification");
        }
      }
      properties.push_back(factors);
    }
  }
  return properties;
}

}  // namespace isolab::model
