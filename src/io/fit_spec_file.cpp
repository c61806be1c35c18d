#include "isolab/io/fit_spec_file.h"

#include <fmt/format.h>

#include <stdexcept>

#include "isolab/core/errors.h"
#include "model_sections.h"

namespace isolab::io {
namespace {

using identification::ComponentSpec;
using identification::CoordinateRange;

// Quantities of a shape coordinate: displacements carry a length unit, ratios none.
double ReadCoordinate(const YamlReader& reader, const YAML::Node& node, const std::string& path,
                      const std::string& name, const UnitSystem& units) {
  return name.find("ratio") != std::string::npos || name == "loss"
             ? reader.ReadNumber(node, path)
             : reader.ReadQuantity(node, path, dimension::kLength, units);
}

}  // namespace

FitSpec LoadFitSpec(const std::string& path) {
  const YamlReader reader(path);
  const YAML::Node root = reader.LoadFile();
  reader.RequireMap(root, "");
  reader.CheckKeys(root, "", {"description", "units", "components"});
  FitSpec spec;
  spec.path = path;
  spec.units = ReadUnits(reader, root);
  const YAML::Node list = reader.Require(root, "", "components");
  reader.RequireSequence(list, "components");
  for (std::size_t i = 0; i < list.size(); ++i) {
    const YAML::Node entry = list[i];
    const std::string at = fmt::format("components[{}]", i);
    reader.RequireMap(entry, at);
    reader.CheckKeys(entry, at, {"type", "count", "name", "bounds", "fixed", "start"});
    const YAML::Node type_node = reader.Require(entry, at, "type");
    const std::string type_name = reader.ReadString(type_node, at + ".type");
    const auto type = hysteresis::LawTypeFromName(type_name);
    std::vector<std::string> coordinates;
    try {
      if (!type) throw std::invalid_argument("");
      coordinates = identification::CoordinateNames(*type);
    } catch (const std::invalid_argument&) {
      reader.Fail(type_node, at + ".type",
                  fmt::format("'{}' cannot be identified (expected thm1, thm2, bhm1, bhm2, "
                              "trilinear_elastic, elastoplastic, degrading_bhm2, linear_spring "
                              "or dashpot)",
                              type_name));
    }
    const int count = entry["count"] ? reader.ReadInteger(entry["count"], at + ".count") : 1;
    if (count < 1) reader.Fail(entry["count"], at + ".count", fmt::format("{} (must be >= 1)", count));
    ComponentSpec component;
    component.type = *type;
    const auto read_map = [&](const char* key, auto&& read) {
      if (!entry[key]) return;
      const std::string map_path = at + "." + key;
      reader.RequireMap(entry[key], map_path);
      std::vector<std::string_view> allowed(coordinates.begin(), coordinates.end());
      reader.CheckKeys(entry[key], map_path, allowed);
      for (const auto& item : entry[key]) {
        const std::string name = item.first.as<std::string>();
        read(name, item.second, map_path + "." + name);
      }
    };
    read_map("bounds", [&](const std::string& name, const YAML::Node& node, const std::string& p) {
      reader.RequireSequence(node, p);
      if (node.size() != 2) reader.Fail(node, p, "expected [low, high]");
      const double low = ReadCoordinate(reader, node[0], p + "[0]", name, spec.units);
      const double high = ReadCoordinate(reader, node[1], p + "[1]", name, spec.units);
      if (!(high > low)) reader.Fail(node, p, fmt::format("[{:g}, {:g}] (must be low < high)", low, high));
      component.ranges[name] = CoordinateRange{low, high, true};
    });
    read_map("fixed", [&](const std::string& name, const YAML::Node& node, const std::string& p) {
      component.fixed[name] = ReadCoordinate(reader, node, p, name, spec.units);
    });
    read_map("start", [&](const std::string& name, const YAML::Node& node, const std::string& p) {
      component.start[name] = ReadCoordinate(reader, node, p, name, spec.units);
    });
    const std::string base = entry["name"] ? reader.ReadString(entry["name"], at + ".name") : "";
    for (int k = 0; k < count; ++k) {
      component.name = !base.empty() ? (count > 1 ? fmt::format("{}{}", base, k + 1) : base)
                                     : fmt::format("c{}", spec.components.size() + 1);
      spec.components.push_back(component);
    }
  }
  if (spec.components.empty()) reader.Fail(list, "components", "no component to identify");
  return spec;
}

}  // namespace isolab::io
