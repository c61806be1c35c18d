// structure: an SDOF (mass, damping) or a shear building (stories, base mass, damping).
#include <fmt/format.h>

#include "model_sections.h"

namespace isolab::model {

double ReadPositive(const YamlReader& reader, const YAML::Node& map, const std::string& path,
                    std::string_view key, Dimension dimension, const UnitSystem& units) {
  const std::string child = ChildPath(path, key);
  const YAML::Node node = reader.Require(map, path, key);
  const double value = reader.ReadQuantity(node, child, dimension, units);
  if (!(value > 0.0 && std::isfinite(value))) {
    reader.Fail(node, child, fmt::format("{:g} (must be > 0)", value));
  }
  return value;
}

double ReadRatio(const YamlReader& reader, const YAML::Node& node, const std::string& path) {
  const double ratio = reader.ReadNumber(node, path);
  if (!(ratio >= 0.0 && ratio < 1.0)) {
    reader.Fail(node, path, fmt::format("{:g} (a damping ratio must be in [0, 1))", ratio));
  }
  return ratio;
}

std::string DefaultStoryName(std::size_t index) { return fmt::format("story{}", index + 1); }

namespace {

structure::Story ReadStory(const YamlReader& reader, const YAML::Node& node,
                           const std::string& path, const UnitSystem& units, std::size_t index) {
  reader.RequireMap(node, path);
  reader.CheckKeys(node, path, {"name", "mass", "stiffness", "components", "height"});
  structure::Story story;
  story.name = node["name"] ? reader.ReadString(node["name"], ChildPath(path, "name"))
                            : DefaultStoryName(index);
  story.floor_mass = ReadPositive(reader, node, path, "mass", dimension::kMass, units);
  if (node["height"]) {
    story.height =
        reader.ReadQuantity(node["height"], ChildPath(path, "height"), dimension::kLength, units);
  }
  if (node["stiffness"] && node["components"]) {
    reader.Fail(node, path,
                "give either 'stiffness' (linear) or 'components' (any laws), not both");
  }
  if (node["components"]) {
    story.assembly = ReadAssembly(reader, node["components"], ChildPath(path, "components"), units);
  } else {
    story.assembly = hysteresis::SingleLaw(
        hysteresis::LawType::kLinearSpring,
        {ReadPositive(reader, node, path, "stiffness", dimension::kStiffness, units)}, "k");
  }
  return story;
}

std::vector<structure::Story> ReadStories(const YamlReader& reader, const YAML::Node& node,
                                          const std::string& path, const UnitSystem& units) {
  std::vector<structure::Story> stories;
  if (node.IsSequence()) {  // empty: a slab on its isolators (model_file.cpp checks)
    for (std::size_t i = 0; i < node.size(); ++i) {
      stories.push_back(ReadStory(reader, node[i], IndexPath(path, i), units, i));
    }
    return stories;
  }
  // Uniform shorthand: count copies of one story.
  reader.RequireMap(node, path);
  reader.CheckKeys(node, path, {"count", "mass", "stiffness", "components", "height"});
  const YAML::Node count_node = reader.Require(node, path, "count");
  const int count = reader.ReadInteger(count_node, ChildPath(path, "count"));
  if (count < 1 || count > 2000) {
    reader.Fail(count_node, ChildPath(path, "count"), fmt::format("{} (must be 1 to 2000)", count));
  }
  // The node itself, not a clone: a clone has no marks, so every error in the story was
  // located at 1:1. Removing count changes only the tree of this reading.
  YAML::Node one = node;
  one.remove("count");
  // Read once, not count times (CheckKeys above refuses a name of its own).
  return EqualStories(ReadStory(reader, one, path, units, 0), count);
}

structure::SuperstructureDamping ReadBuildingDamping(const YamlReader& reader,
                                                     const YAML::Node& node,
                                                     const std::string& path) {
  structure::SuperstructureDamping damping;
  if (node.IsScalar() && node.Scalar() == "none") return damping;
  reader.RequireMap(node, path);
  const YAML::Node type_node = reader.Require(node, path, "type");
  const std::string type = reader.ReadString(type_node, ChildPath(path, "type"));
  if (type == "none") {
    reader.CheckKeys(node, path, {"type"});
  } else if (type == "rayleigh") {
    reader.CheckKeys(node, path, {"type", "modes", "ratios"});
    damping.kind = structure::SuperstructureDamping::Kind::kRayleigh;
    const YAML::Node ratios = reader.Require(node, path, "ratios");
    if (!ratios.IsSequence() || ratios.size() != 2) {
      reader.Fail(ratios, ChildPath(path, "ratios"), "expected two damping ratios, [z1, z2]");
    }
    for (int i = 0; i < 2; ++i) {
      damping.rayleigh_ratios[i] = ReadRatio(reader, ratios[i], ChildPath(path, "ratios"));
    }
    if (node["modes"]) {
      const YAML::Node modes = node["modes"];
      if (!modes.IsSequence() || modes.size() != 2) {
        reader.Fail(modes, ChildPath(path, "modes"), "expected two mode numbers, [1, 2]");
      }
      for (int i = 0; i < 2; ++i) {
        damping.rayleigh_modes[i] = reader.ReadInteger(modes[i], ChildPath(path, "modes"));
      }
    }
  } else if (type == "modal") {
    reader.CheckKeys(node, path, {"type", "ratio", "ratios"});
    damping.kind = structure::SuperstructureDamping::Kind::kModal;
    if (node["ratio"]) {
      damping.modal_ratios = {ReadRatio(reader, node["ratio"], ChildPath(path, "ratio"))};
    } else {
      const YAML::Node ratios = reader.Require(node, path, "ratios");
      reader.RequireSequence(ratios, ChildPath(path, "ratios"));
      for (std::size_t i = 0; i < ratios.size(); ++i) {
        damping.modal_ratios.push_back(ReadRatio(reader, ratios[i], ChildPath(path, "ratios")));
      }
    }
  } else {
    reader.Fail(type_node, ChildPath(path, "type"),
                fmt::format("'{}' is not a damping type (expected rayleigh, modal or none)", type));
  }
  return damping;
}

}  // namespace

StructureSection ReadStructure(const YamlReader& reader, const YAML::Node& node,
                               const UnitSystem& units) {
  const std::string path = "structure";
  reader.RequireMap(node, path);
  const YAML::Node type_node = reader.Require(node, path, "type");
  const std::string type = reader.ReadString(type_node, "structure.type");
  StructureSection section;
  if (type == "sdof") {
    reader.CheckKeys(node, path, {"type", "mass", "damping"});
    section.mass = ReadPositive(reader, node, path, "mass", dimension::kMass, units);
    if (node["damping"]) {
      const YAML::Node damping = node["damping"];
      reader.RequireMap(damping, "structure.damping");
      reader.CheckKeys(damping, "structure.damping", {"ratio", "coefficient"});
      if (damping["ratio"]) {
        section.damping_ratio = ReadRatio(reader, damping["ratio"], "structure.damping.ratio");
      } else {
        const YAML::Node c = reader.Require(damping, "structure.damping", "coefficient");
        section.damping_coefficient = reader.ReadQuantity(c, "structure.damping.coefficient",
                                                          dimension::kDampingCoefficient, units);
        if (section.damping_coefficient < 0.0) {
          reader.Fail(c, "structure.damping.coefficient", "must be >= 0");
        }
      }
    }
  } else if (type == "shear_building") {
    reader.CheckKeys(node, path, {"type", "stories", "base_mass", "damping"});
    section.kind = StructureSection::Kind::kShearBuilding;
    if (node["stories"]) {
      section.building.stories = ReadStories(reader, node["stories"], "structure.stories", units);
    }
    if (node["base_mass"]) {
      section.building.base_mass =
          ReadPositive(reader, node, path, "base_mass", dimension::kMass, units);
    }
    if (node["damping"]) {
      section.building.damping = ReadBuildingDamping(reader, node["damping"], "structure.damping");
    }
  } else {
    reader.Fail(
        type_node, "structure.type",
        fmt::format("'{}' is not a structure type (expected sdof or shear_building)", type));
  }
  return section;
}

}  // namespace isolab::model
