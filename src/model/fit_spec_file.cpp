#include "isolab/model/fit_spec_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "isolab/core/errors.h"
#include "model_sections.h"

namespace isolab::model {
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

// Where a shape coordinate makes a valid law (the rules of hysteresis/law_parameters.h in the
// coordinates' terms): a bound, a fixed value or a start outside it would fail inside the fit.
struct CoordinateDomain {
  double low, high;
  bool low_open, high_open;
  const char* rule;
};

CoordinateDomain DomainOf(const std::string& name) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (name == "k1_ratio" || name == "k2_ratio") return {-kInf, 1.0, true, true, "must be < 1"};
  if (name == "loss") return {0.0, 1.0, false, true, "must be in [0, 1)"};
  return {0.0, kInf, true, true, "must be > 0"};  // uy, uyh, uyh_gap, slip_scale
}

void RequireInDomain(const YamlReader& reader, const YAML::Node& node, const std::string& path,
                     const std::string& name, double value) {
  const CoordinateDomain d = DomainOf(name);
  const bool above = d.low_open ? value > d.low : value >= d.low;
  const bool below = d.high_open ? value < d.high : value <= d.high;
  if (!above || !below) reader.Fail(node, path, fmt::format("{} = {:g} ({})", name, value, d.rule));
}

// A fit over this many components would not converge in any practical budget.
constexpr int kMaxComponents = 100;

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
    if (count < 1 || count > kMaxComponents) {
      reader.Fail(entry["count"], at + ".count",
                  fmt::format("{} (must be 1 to {}: a fit of more components would not converge "
                              "in any practical budget)",
                              count, kMaxComponents));
    }
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
      if (!(high > low))
        reader.Fail(node, p, fmt::format("[{:g}, {:g}] (must be low < high)", low, high));
      RequireInDomain(reader, node[0], p + "[0]", name, low);
      RequireInDomain(reader, node[1], p + "[1]", name, high);
      component.ranges[name] = CoordinateRange{low, high, true};
    });
    read_map("fixed", [&](const std::string& name, const YAML::Node& node, const std::string& p) {
      component.fixed[name] = ReadCoordinate(reader, node, p, name, spec.units);
      RequireInDomain(reader, node, p, name, component.fixed[name]);
    });
    read_map("start", [&](const std::string& name, const YAML::Node& node, const std::string& p) {
      component.start[name] = ReadCoordinate(reader, node, p, name, spec.units);
      RequireInDomain(reader, node, p, name, component.start[name]);
    });
    // A fixed coordinate is not searched: bounds or a start beside it would be dropped silently.
    for (const auto& [name, value] : component.fixed) {
      for (const char* other : {"bounds", "start"}) {
        if (entry[other] && entry[other][name]) {
          reader.Fail(entry["fixed"][name], at + ".fixed." + name,
                      fmt::format("{:g} fixes it, and {}.{} is given too, which a fixed "
                                  "coordinate does not use: give one or the other",
                                  value, other, name));
        }
      }
    }
    // A start must lie within its bounds (the fit would clamp it silently).
    for (const auto& [name, start] : component.start) {
      const auto range = component.ranges.find(name);
      if (range == component.ranges.end()) continue;
      if (start < range->second.low || start > range->second.high) {
        reader.Fail(entry["start"][name], at + ".start." + name,
                    fmt::format("{:g} is outside its bounds [{:g}, {:g}]", start, range->second.low,
                                range->second.high));
      }
    }
    const std::string base = entry["name"] ? reader.ReadString(entry["name"], at + ".name") : "";
    for (int k = 0; k < count; ++k) {
      component.name = !base.empty() ? (count > 1 ? fmt::format("{}{}", base, k + 1) : base)
                                     : fmt::format("c{}", spec.components.size() + 1);
      // The fitted model names its components by these: two alike would be refused only there,
      // after the whole fit.
      const auto same =
          std::find_if(spec.components.begin(), spec.components.end(),
                       [&](const ComponentSpec& c) { return c.name == component.name; });
      if (same != spec.components.end()) {
        reader.Fail(entry["name"] ? entry["name"] : entry, at + ".name",
                    fmt::format("'{}' names component {} already (names are each component's "
                                "own; with count: N, NAME1 to NAMEN)",
                                component.name, same - spec.components.begin() + 1));
      }
      spec.components.push_back(component);
    }
  }
  if (spec.components.empty()) reader.Fail(list, "components", "no component to identify");
  if (spec.components.size() > kMaxComponents) {
    reader.Fail(list, "components",
                fmt::format("{} components (at most {}: a fit of more would not converge in any "
                            "practical budget)",
                            spec.components.size(), kMaxComponents));
  }
  return spec;
}

}  // namespace isolab::model
