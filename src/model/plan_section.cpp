// plan: a building in plan. Plan coordinates (x, y) are in the model's length unit, from any
// origin; the footprint is the rectangle every centre and isolator must lie in.
//
//   plan:
//     footprint: [[0, 0], [20, 12]]              # two opposite corners
//     base: {mass: 100 t, centre_of_mass: [10, 6], radius_of_gyration: 6.7}
//     stories:                                    # bottom to top; or {count: 5, ...} for equal
//       - name: s1                                # stories (default: story1, story2, ...); none
//         mass: 100 t                             # or [] for a slab on its isolators
//         centre_of_mass: [10.3, 6]               # default: the footprint's centre
//         rotational_inertia: 4000 t*m^2          # or radius_of_gyration; default: a uniform
//                                                 # slab over the footprint, m (a^2 + b^2) / 12
//         height: 3                               # for reporting
//         centre_of_stiffness: [10, 6]            # default: the footprint's centre
//         stiffness: {x: 120 kN/mm, y: 120 kN/mm, torsion: 4.3e9 kN*mm}  # linear, or
//         x: [components], y: [...], torsion: ... # any laws along x and y, a linear torsion
//     damping: {type: rayleigh, periods: [0.6, 0.1], ratios: [0.05, 0.05]}   # or none (default)
//     isolators:
//       - name: sw
//         position: [0, 0]                        # or positions: [[x1, y1], [x2, y2], ...]:
//                                                 # this type at each, named sw_1, sw_2, ...
//         coupling: coupled                       # or uncoupled: each law along x and along y
//         components: [{type: bhm2, k0: 2, k1: 0.25, uy: 20}]
//         modification: {c1: {k0: {min: 0.9, max: 1.2}}}   # property_modification.h
#include <fmt/format.h>

#include <cmath>
#include <string_view>

#include "model_sections.h"

namespace isolab::model {
namespace {

using hysteresis::Vec2;

constexpr Dimension kRotationalInertia{1, 2, 0};    // mass*length^2
constexpr Dimension kTorsionalStiffness{1, 2, -2};  // force*length per radian

struct Footprint {
  Vec2 low, high;
  Vec2 centre() const { return 0.5 * (low + high); }
  bool Contains(Vec2 p) const {
    // A point on the edge is inside (a corner isolator), within round-off of the edge's size.
    const double tolerance = 1e-9 * std::max(high.x - low.x, high.y - low.y);
    return p.x >= low.x - tolerance && p.x <= high.x + tolerance && p.y >= low.y - tolerance &&
           p.y <= high.y + tolerance;
  }
};

Vec2 ReadPoint(const YamlReader& reader, const YAML::Node& node, const std::string& path,
               const UnitSystem& units) {
  if (!node.IsSequence() || node.size() != 2) {
    reader.Fail(node, path, "expected a plan position [x, y]");
  }
  return {reader.ReadQuantity(node[0], path, dimension::kLength, units),
          reader.ReadQuantity(node[1], path, dimension::kLength, units)};
}

Vec2 ReadInside(const YamlReader& reader, const YAML::Node& map, const std::string& path,
                std::string_view key, const Footprint& footprint, const UnitSystem& units) {
  const std::string child = ChildPath(path, key);
  if (!map[std::string(key)]) return footprint.centre();
  const Vec2 p = ReadPoint(reader, map[std::string(key)], child, units);
  if (!footprint.Contains(p)) {
    reader.Fail(
        map[std::string(key)], child,
        fmt::format("[{:g}, {:g}] is outside the footprint [[{:g}, {:g}], [{:g}, {:g}]]", p.x, p.y,
                    footprint.low.x, footprint.low.y, footprint.high.x, footprint.high.y));
  }
  return p;
}

Footprint ReadFootprint(const YamlReader& reader, const YAML::Node& plan, const UnitSystem& units) {
  const YAML::Node node = reader.Require(plan, "plan", "footprint");
  if (!node.IsSequence() || node.size() != 2) {
    reader.Fail(node, "plan.footprint", "expected two opposite corners [[x1, y1], [x2, y2]]");
  }
  const Vec2 a = ReadPoint(reader, node[0], "plan.footprint", units);
  const Vec2 b = ReadPoint(reader, node[1], "plan.footprint", units);
  const Footprint footprint{{std::min(a.x, b.x), std::min(a.y, b.y)},
                            {std::max(a.x, b.x), std::max(a.y, b.y)}};
  if (!(footprint.high.x > footprint.low.x && footprint.high.y > footprint.low.y)) {
    reader.Fail(node, "plan.footprint", "the corners must span an area (different x and y)");
  }
  return footprint;
}

// A floor's mass, centre of mass and rotational inertia (given, from a radius of gyration, or a
// uniform slab over the footprint).
structure::PlanFloor ReadFloor(const YamlReader& reader, const YAML::Node& node,
                               const std::string& path, const Footprint& footprint,
                               const UnitSystem& units) {
  structure::PlanFloor floor;
  floor.mass = ReadPositive(reader, node, path, "mass", dimension::kMass, units);
  floor.centre_of_mass = ReadInside(reader, node, path, "centre_of_mass", footprint, units);
  if (node["rotational_inertia"] && node["radius_of_gyration"]) {
    reader.Fail(node, path, "give rotational_inertia or radius_of_gyration, not both");
  }
  if (node["rotational_inertia"]) {
    floor.rotational_inertia =
        ReadPositive(reader, node, path, "rotational_inertia", kRotationalInertia, units);
  } else if (node["radius_of_gyration"]) {
    const double r =
        ReadPositive(reader, node, path, "radius_of_gyration", dimension::kLength, units);
    floor.rotational_inertia = floor.mass * r * r;
  } else {
    const Vec2 size = footprint.high - footprint.low;
    floor.rotational_inertia = floor.mass * (size.x * size.x + size.y * size.y) / 12.0;
  }
  return floor;
}

hysteresis::ParallelAssembly LinearLaw(double k) {
  return hysteresis::SingleLaw(hysteresis::LawType::kLinearSpring, {k}, "k");
}

structure::PlanStory ReadStory(const YamlReader& reader, const YAML::Node& node,
                               const std::string& path, std::size_t index,
                               const Footprint& footprint, const UnitSystem& units) {
  reader.RequireMap(node, path);
  reader.CheckKeys(node, path,
                   {"name", "mass", "centre_of_mass", "rotational_inertia", "radius_of_gyration",
                    "height", "centre_of_stiffness", "stiffness", "x", "y", "torsion"});
  structure::PlanStory story;
  story.name = node["name"] ? reader.ReadString(node["name"], ChildPath(path, "name"))
                            : DefaultStoryName(index);
  story.floor = ReadFloor(reader, node, path, footprint, units);
  if (node["height"]) {
    story.height =
        reader.ReadQuantity(node["height"], ChildPath(path, "height"), dimension::kLength, units);
  }
  story.centre_of_stiffness =
      ReadInside(reader, node, path, "centre_of_stiffness", footprint, units);
  if (node["stiffness"]) {
    if (node["x"] || node["y"] || node["torsion"]) {
      reader.Fail(node, path,
                  "give either 'stiffness: {x, y, torsion}' (linear) or laws 'x', 'y' and "
                  "'torsion', not both");
    }
    const std::string s_path = ChildPath(path, "stiffness");
    const YAML::Node s = node["stiffness"];
    reader.RequireMap(s, s_path);
    reader.CheckKeys(s, s_path, {"x", "y", "torsion"});
    story.x = LinearLaw(ReadPositive(reader, s, s_path, "x", dimension::kStiffness, units));
    story.y = LinearLaw(ReadPositive(reader, s, s_path, "y", dimension::kStiffness, units));
    story.torsion =
        LinearLaw(ReadPositive(reader, s, s_path, "torsion", kTorsionalStiffness, units));
    return story;
  }
  story.x = ReadAssembly(reader, reader.Require(node, path, "x"), ChildPath(path, "x"), units);
  story.y = ReadAssembly(reader, reader.Require(node, path, "y"), ChildPath(path, "y"), units);
  // Torque against twist: a linear stiffness (a law's parameters are read as translations').
  story.torsion =
      LinearLaw(ReadPositive(reader, node, path, "torsion", kTorsionalStiffness, units));
  return story;
}

std::vector<structure::PlanStory> ReadStories(const YamlReader& reader, const YAML::Node& node,
                                              const Footprint& footprint, const UnitSystem& units) {
  const std::string path = "plan.stories";
  std::vector<structure::PlanStory> stories;
  if (node.IsSequence()) {  // empty: a slab on its isolators
    for (std::size_t i = 0; i < node.size(); ++i) {
      stories.push_back(ReadStory(reader, node[i], IndexPath(path, i), i, footprint, units));
    }
    return stories;
  }
  // Uniform shorthand: count copies of one story.
  reader.RequireMap(node, path);
  const YAML::Node count_node = reader.Require(node, path, "count");
  const int count = reader.ReadInteger(count_node, ChildPath(path, "count"));
  if (count < 1 || count > 2000) {
    reader.Fail(count_node, ChildPath(path, "count"), fmt::format("{} (must be 1 to 2000)", count));
  }
  // The node itself, not a clone: a clone has no marks, so every error in the story was
  // located at 1:1. Removing count changes only the tree of this reading.
  YAML::Node one = node;
  one.remove("count");
  if (one["name"])
    reader.Fail(node["name"], ChildPath(path, "name"),
                "equal stories are named story1, story2, ...");
  return EqualStories(ReadStory(reader, one, path, 0, footprint, units), count);
}

// An isolator's laws: coupled bidirectional forms, or each law along x and along y alone.
hysteresis::PlanAssembly IsolatorAssembly(const hysteresis::ParallelAssembly& laws,
                                          bool uncoupled) {
  std::vector<hysteresis::PlanComponent> components;
  for (const hysteresis::Component& law : laws.components()) {
    components.push_back(
        {law.name, law.parameters, uncoupled ? std::optional(law.parameters) : std::nullopt});
  }
  return hysteresis::PlanAssembly(std::move(components));
}

// An isolator entry: one isolator at `position`, or its type at each of `positions` (a group,
// named "<name>_1" ... "<name>_<count>").
std::vector<structure::PlanIsolatorSite> ReadIsolators(
    const YamlReader& reader, const YAML::Node& node, const std::string& path, std::size_t index,
    const Footprint& footprint, const UnitSystem& units,
    std::vector<BearingModification>* modifications) {
  reader.RequireMap(node, path);
  reader.CheckKeys(node, path,
                   {"name", "position", "positions", "coupling", "components", "modification"});
  const std::string name = node["name"] ? reader.ReadString(node["name"], ChildPath(path, "name"))
                                        : fmt::format("isolator{}", index + 1);
  std::vector<hysteresis::Vec2> positions;
  if (node["positions"]) {
    if (node["position"]) {
      reader.Fail(node["positions"], ChildPath(path, "positions"),
                  "give position (one isolator) or positions (a group), not both");
    }
    const std::string list_path = ChildPath(path, "positions");
    const YAML::Node list = node["positions"];
    reader.RequireSequence(list, list_path);
    if (list.size() == 0) {
      reader.Fail(list, list_path,
                  "the list is empty: a group of 0 bearings (give at least one position)");
    }
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string point_path = IndexPath(list_path, i);
      const Vec2 point = ReadPoint(reader, list[i], point_path, units);
      if (!footprint.Contains(point)) {
        reader.Fail(
            list[i], point_path,
            fmt::format("[{:g}, {:g}] is outside the footprint [[{:g}, {:g}], [{:g}, {:g}]]",
                        point.x, point.y, footprint.low.x, footprint.low.y, footprint.high.x,
                        footprint.high.y));
      }
      positions.push_back(point);
    }
  } else {
    reader.Require(node, path, "position");
    positions.push_back(ReadInside(reader, node, path, "position", footprint, units));
  }
  bool uncoupled = false;
  if (node["coupling"]) {
    const std::string coupling = reader.ReadString(node["coupling"], ChildPath(path, "coupling"));
    if (coupling != "coupled" && coupling != "uncoupled") {
      reader.Fail(node["coupling"], ChildPath(path, "coupling"),
                  fmt::format("'{}' (expected coupled or uncoupled)", coupling));
    }
    uncoupled = coupling == "uncoupled";
  }
  const std::string list_path = ChildPath(path, "components");
  const YAML::Node list = reader.Require(node, path, "components");
  const hysteresis::ParallelAssembly laws = ReadAssembly(reader, list, list_path, units);
  const std::size_t c = FirstWithoutCoupledForm(laws);
  if (!uncoupled && c < laws.size()) {
    reader.Fail(list[c], IndexPath(list_path, c),
                fmt::format("{} (give the isolator coupling: uncoupled to use it along x and y "
                            "independently)",
                            NoCoupledForm(laws, c)));
  }
  if (node["modification"]) {
    modifications->push_back({name, index,
                              ReadModification(reader, node["modification"],
                                               ChildPath(path, "modification"), laws, list)});
  }
  const hysteresis::PlanAssembly assembly = IsolatorAssembly(laws, uncoupled);
  std::vector<structure::PlanIsolatorSite> sites;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    sites.push_back(
        {node["positions"] ? fmt::format("{}_{}", name, i + 1) : name, positions[i], assembly});
  }
  return sites;
}

structure::PlanDamping ReadDamping(const YamlReader& reader, const YAML::Node& node,
                                   const UnitSystem& units) {
  const std::string path = "plan.damping";
  structure::PlanDamping damping;
  if (node.IsScalar() && node.Scalar() == "none") return damping;
  reader.RequireMap(node, path);
  const YAML::Node type_node = reader.Require(node, path, "type");
  const std::string type = reader.ReadString(type_node, ChildPath(path, "type"));
  if (type == "none") {
    reader.CheckKeys(node, path, {"type"});
    return damping;
  }
  if (type != "rayleigh") {
    reader.Fail(type_node, ChildPath(path, "type"),
                fmt::format("'{}' is not a plan damping type (expected rayleigh or none)", type));
  }
  reader.CheckKeys(node, path, {"type", "periods", "ratios"});
  damping.rayleigh = true;
  for (const char* key : {"periods", "ratios"}) {
    const YAML::Node pair = reader.Require(node, path, key);
    if (!pair.IsSequence() || pair.size() != 2) {
      reader.Fail(pair, ChildPath(path, key), fmt::format("expected two {}", key));
    }
  }
  for (int i = 0; i < 2; ++i) {
    const std::string periods = ChildPath(path, "periods");
    damping.periods[i] = reader.ReadQuantity(node["periods"][i], periods, dimension::kTime, units);
    if (!(damping.periods[i] > 0.0)) reader.Fail(node["periods"][i], periods, "must be > 0");
    damping.ratios[i] = ReadRatio(reader, node["ratios"][i], ChildPath(path, "ratios"));
  }
  if (damping.periods[0] == damping.periods[1]) {
    reader.Fail(node["periods"], ChildPath(path, "periods"), "two different periods");
  }
  return damping;
}

}  // namespace

std::size_t FirstWithoutCoupledForm(const hysteresis::ParallelAssembly& laws) {
  for (std::size_t c = 0; c < laws.size(); ++c) {
    if (!hysteresis::HasCoupledForm(laws.components()[c].parameters.type())) return c;
  }
  return laws.size();
}

std::string NoCoupledForm(const hysteresis::ParallelAssembly& laws, std::size_t c) {
  return fmt::format("{} has no coupled bidirectional form",
                     hysteresis::LawName(laws.components()[c].parameters.type()));
}

void ReplaceIsolation(ModelFile* model, const hysteresis::ParallelAssembly& laws,
                      std::optional<identification::IdentifiedRange> range, bool uncoupled) {
  model->identified_range = std::move(range);
  if (!model->structure || model->structure->kind != StructureSection::Kind::kPlanBuilding) {
    model->isolation = laws;
    return;
  }
  if (!uncoupled && FirstWithoutCoupledForm(laws) < laws.size()) {
    throw std::invalid_argument(NoCoupledForm(laws, FirstWithoutCoupledForm(laws)));
  }
  for (structure::PlanIsolatorSite& site : model->structure->plan.isolators) {
    site.assembly = IsolatorAssembly(laws, uncoupled);
  }
}

StructureSection ReadPlan(const YamlReader& reader, const YAML::Node& plan, const UnitSystem& units,
                          std::vector<BearingModification>* modifications) {
  reader.RequireMap(plan, "plan");
  reader.CheckKeys(plan, "plan", {"footprint", "base", "stories", "damping", "isolators"});
  StructureSection section;
  section.kind = StructureSection::Kind::kPlanBuilding;
  structure::PlanBuilding& building = section.plan;
  const Footprint footprint = ReadFootprint(reader, plan, units);
  section.footprint_size = footprint.high - footprint.low;
  const YAML::Node base = reader.Require(plan, "plan", "base");
  reader.RequireMap(base, "plan.base");
  reader.CheckKeys(base, "plan.base",
                   {"mass", "centre_of_mass", "rotational_inertia", "radius_of_gyration"});
  building.base = ReadFloor(reader, base, "plan.base", footprint, units);
  if (plan["stories"]) building.stories = ReadStories(reader, plan["stories"], footprint, units);
  if (plan["damping"]) building.damping = ReadDamping(reader, plan["damping"], units);
  const YAML::Node isolators = reader.Require(plan, "plan", "isolators");
  reader.RequireSequence(isolators, "plan.isolators");
  if (isolators.size() == 0) {
    reader.Fail(isolators, "plan.isolators", "the list is empty; give at least one isolator");
  }
  for (std::size_t i = 0; i < isolators.size(); ++i) {
    const std::size_t first = building.isolators.size();
    for (structure::PlanIsolatorSite& site :
         ReadIsolators(reader, isolators[i], IndexPath("plan.isolators", i), i, footprint, units,
                       modifications)) {
      for (std::size_t j = 0; j < first; ++j) {
        if (building.isolators[j].name == site.name) {
          reader.Fail(isolators[i], IndexPath("plan.isolators", i),
                      fmt::format("name '{}' is already used by isolator {}", site.name, j));
        }
      }
      building.isolators.push_back(std::move(site));
    }
  }
  return section;
}

}  // namespace isolab::model
