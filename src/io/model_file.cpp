#include "isolab/io/model_file.h"

#include <fmt/format.h>

#include <filesystem>
#include <optional>
#include <utility>

#include "model_sections.h"

namespace isolab::io {

UnitSystem ReadUnits(const YamlReader& reader, const YAML::Node& root) {
  const YAML::Node node = reader.Require(root, "", "units");
  reader.RequireMap(node, "units");
  reader.CheckKeys(node, "units", {"force", "length", "time"});
  const std::string force =
      reader.ReadString(reader.Require(node, "units", "force"), "units.force");
  const std::string length =
      reader.ReadString(reader.Require(node, "units", "length"), "units.length");
  const std::string time = node["time"] ? reader.ReadString(node["time"], "units.time") : "s";
  // Built up one unit at a time, so an error points at the unit that is wrong.
  const std::pair<const char*,
                  UnitSystem (*)(const std::string&, const std::string&, const std::string&)>
      steps[] = {
          {"force", [](auto& f, auto&, auto&) { return UnitSystem(f, "m", "s"); }},
          {"length", [](auto& f, auto& l, auto&) { return UnitSystem(f, l, "s"); }},
          {"time", [](auto& f, auto& l, auto& t) { return UnitSystem(f, l, t); }},
      };
  std::optional<UnitSystem> units;
  for (const auto& [key, build] : steps) {
    try {
      units = build(force, length, time);
    } catch (const std::invalid_argument& error) {
      reader.Fail(node[key], ChildPath("units", key),
                  fmt::format("{} (force: N, kN, MN, lbf, kip; length: m, cm, mm, in, ft; time: s, "
                              "ms)",
                              error.what()));
    }
  }
  return *units;
}

namespace {

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

// Checks that need more than one section.
void CheckConsistency(const YamlReader& reader, const YAML::Node& root, const ModelFile& model) {
  if (!model.structure) return;
  const YAML::Node structure = root["structure"];
  int dofs = 1;
  if (model.structure->kind == StructureSection::Kind::kSdof) {
    if (model.isolation.size() == 0) {
      reader.Fail(structure, "structure",
                  "an sdof takes its restoring force from isolation.components, which is missing");
    }
  } else {
    const bool isolated = model.isolation.size() > 0;
    const bool has_base_mass = model.structure->building.base_mass > 0.0;
    if (isolated && !has_base_mass) {
      reader.Fail(structure, "structure", "an isolated building needs base_mass");
    }
    if (!isolated && has_base_mass) {
      reader.Fail(
          structure["base_mass"], "structure.base_mass",
          "given, but there is no isolation section (a fixed-base building has no base mass)");
    }
    dofs = static_cast<int>(model.structure->building.stories.size()) + (isolated ? 1 : 0);
  }
  const YAML::Node forces = root["excitation"] ? root["excitation"]["forces"] : YAML::Node();
  for (std::size_t i = 0; i < model.excitation.forces.size(); ++i) {
    const int dof = model.excitation.forces[i].dof;
    if (dof < 0 || dof >= dofs) {
      reader.Fail(
          forces[i]["dof"], IndexPath("excitation.forces", i) + ".dof",
          fmt::format("{} (the structure's degrees of freedom are 0 to {})", dof, dofs - 1));
    }
  }
}

}  // namespace

ModelFile LoadModelFile(const std::string& path) {
  const YamlReader reader(path);
  ModelFile model;
  const YAML::Node root = reader.LoadFile(&model.text);
  reader.RequireMap(root, "");
  if (root["plan"]) {
    reader.Fail(root["plan"], "plan",
                "a plan model: `isolab run` analyses it (docs/bidirectional.md); this command "
                "takes one-direction models");
  }
  reader.CheckKeys(root, "",
                   {"description", "units", "isolation", "structure", "excitation", "analysis",
                    "output", "cyclic"});
  model.path = path;
  if (root["description"]) {
    model.description = reader.ReadString(root["description"], "description");
  }
  model.units = ReadUnits(reader, root);
  if (root["isolation"]) {
    model.isolation = ReadIsolation(reader, root["isolation"], "isolation",
                                    std::filesystem::path(path).parent_path(), model.units);
  }
  if (root["structure"]) model.structure = ReadStructure(reader, root["structure"], model.units);
  if (root["excitation"])
    model.excitation = ReadExcitation(reader, root["excitation"], model.units);
  if (root["analysis"]) model.analysis = ReadAnalysis(reader, root["analysis"], model.units);
  if (root["output"]) {
    reader.RequireMap(root["output"], "output");
    reader.CheckKeys(root["output"], "output", {"file"});
    model.output_file =
        reader.ReadString(reader.Require(root["output"], "output", "file"), "output.file");
  }
  if (root["cyclic"]) model.cyclic = ReadCyclic(reader, root["cyclic"]);
  if (!model.structure && model.isolation.size() == 0) {
    reader.Fail(root, "", "missing key 'isolation' (a model needs isolation, structure, or both)");
  }
  CheckConsistency(reader, root, model);
  return model;
}

}  // namespace isolab::io
