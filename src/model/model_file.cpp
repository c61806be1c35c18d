#include "isolab/model/model_file.h"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <utility>

#include "model_sections.h"

namespace isolab::model {

std::vector<BuildingFitPriorEntry> ReadPriorEntries(const YamlReader& reader,
                                                    const YAML::Node& node, const std::string& path,
                                                    bool value_required,
                                                    std::span<const std::string> fitted) {
  reader.RequireSequence(node, path);
  std::vector<BuildingFitPriorEntry> priors;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string at = IndexPath(path, i);
    const YAML::Node entry = node[i];
    reader.RequireMap(entry, at);
    reader.CheckKeys(entry, at, {"name", "value", "sigma", "source"});
    BuildingFitPriorEntry prior;
    prior.where = reader.Locate(entry["name"]);
    prior.name = reader.ReadString(reader.Require(entry, at, "name"), at + ".name");
    if (value_required || entry["value"]) {
      prior.value = reader.ReadNumber(reader.Require(entry, at, "value"), at + ".value");
      if (!(*prior.value > 0.0)) {
        reader.Fail(entry["value"], at + ".value", "must be > 0 (drawn in ln p)");
      }
    }
    prior.sigma = reader.ReadNumber(reader.Require(entry, at, "sigma"), at + ".sigma");
    if (!(prior.sigma > 0.0 && prior.sigma <= std::log(10.0))) {
      reader.Fail(
          entry["sigma"], at + ".sigma",
          "must be in (0, ln 10 = 2.303]: a standard deviation in ln p, at most a factor 10");
    }
    prior.source = reader.ReadString(reader.Require(entry, at, "source"), at + ".source");
    if (const auto it = std::find(fitted.begin(), fitted.end(), prior.name); it != fitted.end()) {
      reader.Fail(entry["name"], at + ".name",
                  fmt::format("'{}' is fitted: a prior gives what the fit does not", prior.name));
    }
    for (std::size_t j = 0; j < priors.size(); ++j) {
      if (priors[j].name == prior.name) {
        reader.Fail(entry["name"], at + ".name",
                    fmt::format("'{}' has a prior already ({})", prior.name, IndexPath(path, j)));
      }
    }
    priors.push_back(std::move(prior));
  }
  return priors;
}

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

// The structure's levels and dofs, as build_structure.cpp lays them out: level 0 is the base (or
// an SDOF's mass) when there is one, else floor 1.
struct Extent {
  int levels = 0, dofs = 0;
  bool level_zero = true;
  int directions = 1;
};

Extent ExtentOf(const ModelFile& model) {
  const StructureSection& section = *model.structure;
  switch (section.kind) {
    case StructureSection::Kind::kSdof:
      return {1, 1, true, 1};
    case StructureSection::Kind::kShearBuilding: {
      const bool isolated = model.isolation.size() > 0;
      const int levels = static_cast<int>(section.building.stories.size()) + (isolated ? 1 : 0);
      return {levels, levels, isolated, 1};
    }
    case StructureSection::Kind::kPlanBuilding: {
      const int levels = static_cast<int>(section.plan.stories.size()) + 1;
      return {levels, structure::kPlanDofsPerFloor * levels, true, 2};
    }
  }
  return {};
}

// Checks that need more than one section.
void CheckConsistency(const YamlReader& reader, const YAML::Node& root, const ModelFile& model) {
  const YAML::Node motion = root["excitation"] ? root["excitation"]["ground_motion"] : YAML::Node();
  if (model.axial_load && !model.structure) {
    reader.Fail(root["axial_load"], "axial_load",
                "needs a structure whose weight the bearings carry (structure or plan); a model "
                "of the isolation alone (isolab cyclic, fit) has none");
  }
  if (!model.structure) return;
  const StructureSection& section = *model.structure;
  const YAML::Node structure = root["structure"];
  if (model.axial_load && section.kind == StructureSection::Kind::kShearBuilding &&
      model.isolation.size() == 0) {
    reader.Fail(root["axial_load"], "axial_load",
                "a building without isolation has no bearings to carry its weight");
  }
  if (section.kind == StructureSection::Kind::kSdof && model.isolation.size() == 0) {
    reader.Fail(structure, "structure",
                "an sdof takes its restoring force from isolation.components, which is missing");
  }
  if (section.kind == StructureSection::Kind::kShearBuilding) {
    const bool isolated = model.isolation.size() > 0;
    const bool has_base_mass = section.building.base_mass > 0.0;
    if (isolated && !has_base_mass) {
      reader.Fail(structure, "structure", "an isolated building needs base_mass");
    }
    if (!isolated && has_base_mass) {
      reader.Fail(
          structure["base_mass"], "structure.base_mass",
          "given, but there is no isolation section (a fixed-base building has no base mass)");
    }
    if (!isolated && section.building.stories.empty()) {
      reader.Fail(structure, "structure",
                  "a building without isolation needs stories (an isolated one may have none: "
                  "a slab on its isolators)");
    }
  }
  const Extent extent = ExtentOf(model);
  if (static_cast<int>(model.excitation.ground_motion.size()) > extent.directions ||
      (extent.directions == 1 && model.excitation.angle != 0.0)) {
    const YAML::Node at = motion["h2"] ? motion["h2"] : motion["angle"];
    reader.Fail(at, "excitation.ground_motion",
                "the structure moves along x only: one component, along x (a second component "
                "or an angle needs a building in plan)");
  }
  if (model.excitation.vertical && !(model.axial_load && model.axial_load->vertical)) {
    reader.Fail(motion["v"], "excitation.ground_motion.v",
                "a vertical component acts only through the axial loads of friction pendulum "
                "bearings: give axial_load: {vertical: true} (or leave v out)");
  }
  if (model.axial_load && model.axial_load->vertical && !model.excitation.vertical &&
      !model.excitation.ground_motion.empty()) {
    reader.Fail(root["axial_load"]["vertical"], "axial_load.vertical",
                "needs the record's vertical component, excitation.ground_motion.v");
  }
  if (model.axial_load && model.axial_load->overturning && extent.directions == 1) {
    reader.Fail(root["axial_load"]["overturning"], "axial_load.overturning",
                "a one-direction model has no layout of bearings to share the overturning "
                "moment: overturning needs a building in plan");
  }
  if (model.axial_load && model.analysis.integrator == AnalysisSection::Integrator::kIda) {
    reader.Fail(root["axial_load"], "axial_load",
                "the bearings' axial loads run with Newmark only (analysis.integrator: newmark)");
  }
  const YAML::Node levels = root["output"] ? root["output"]["levels"] : YAML::Node();
  for (std::size_t i = 0; i < model.output.levels.size(); ++i) {
    const int level = model.output.levels[i];
    const int lowest = extent.level_zero ? 0 : 1;
    const int highest = lowest + extent.levels - 1;
    if (level != kRoofLevel && (level > highest || level < lowest)) {
      reader.Fail(
          levels[i], IndexPath("output.levels", i),
          fmt::format("{} (the structure's levels are {} to {}, or roof)", level, lowest, highest));
    }
  }
  const YAML::Node forces = root["excitation"] ? root["excitation"]["forces"] : YAML::Node();
  for (std::size_t i = 0; i < model.excitation.forces.size(); ++i) {
    const int dof = model.excitation.forces[i].dof;
    if (dof < 0 || dof >= extent.dofs) {
      reader.Fail(
          forces[i]["dof"], IndexPath("excitation.forces", i) + ".dof",
          fmt::format("{} (the structure's degrees of freedom are 0 to {})", dof, extent.dofs - 1));
    }
  }
}

// The axial_load section: {vertical, overturning, base_height}, each optional.
AxialLoadSection ReadAxialLoad(const YamlReader& reader, const YAML::Node& node,
                               const UnitSystem& units) {
  const std::string path = "axial_load";
  reader.RequireMap(node, path);
  reader.CheckKeys(node, path, {"vertical", "overturning", "base_height"});
  AxialLoadSection section;
  section.location = reader.Locate(node);
  const auto flag = [&](const char* key) {
    const YAML::Node value = node[key];
    bool result = false;
    if (!value) return result;
    if (!value.IsScalar() || !YAML::convert<bool>::decode(value, result)) {
      reader.Fail(value, ChildPath(path, key), "expected true or false");
    }
    return result;
  };
  section.vertical = flag("vertical");
  section.overturning = flag("overturning");
  if (node["base_height"]) {
    section.base_height = reader.ReadQuantity(node["base_height"], "axial_load.base_height",
                                              dimension::kLength, units);
    if (!(section.base_height >= 0.0)) {
      reader.Fail(node["base_height"], "axial_load.base_height", "must be >= 0");
    }
  }
  return section;
}

// uncertainty.model_form: [{fitted_on: [names], values: [one per parameter]}], each value finite
// and > 0 where its parameter is drawn in ln p.
std::vector<ModelFormFit> ReadModelForm(const YamlReader& reader, const YAML::Node& node,
                                        const ParameterUncertainty& uncertainty) {
  const std::string path = "uncertainty.model_form";
  reader.RequireSequence(node, path);
  if (node.size() < 2) {
    reader.Fail(node, path, "expected at least two fits, one for each motion held out");
  }
  std::vector<ModelFormFit> fits;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string at = IndexPath(path, i);
    reader.RequireMap(node[i], at);
    reader.CheckKeys(node[i], at, {"fitted_on", "values"});
    ModelFormFit& fit = fits.emplace_back();
    const YAML::Node motions = reader.Require(node[i], at, "fitted_on");
    reader.RequireSequence(motions, at + ".fitted_on");
    for (std::size_t m = 0; m < motions.size(); ++m) {
      fit.fitted_on.push_back(reader.ReadString(motions[m], IndexPath(at + ".fitted_on", m)));
    }
    const YAML::Node values = reader.Require(node[i], at, "values");
    reader.RequireSequence(values, at + ".values");
    if (values.size() != uncertainty.names.size()) {
      reader.Fail(values, at + ".values",
                  fmt::format("expected {} numbers, one per parameter", uncertainty.names.size()));
    }
    for (std::size_t p = 0; p < values.size(); ++p) {
      fit.values.push_back(reader.ReadNumber(values[p], IndexPath(at + ".values", p)));
      if (uncertainty.log[p] && !(fit.values.back() > 0.0)) {
        reader.Fail(values[p], IndexPath(at + ".values", p),
                    fmt::format("must be > 0: {} is drawn in ln p", uncertainty.names[p]));
      }
    }
  }
  return fits;
}

// uncertainty: {parameters: [{name, value, log}], covariance: [[...]], model_form: [...],
// priors: [...]}, the covariance square, symmetric, with a non-negative diagonal.
ParameterUncertainty ReadUncertainty(const YamlReader& reader, const YAML::Node& node) {
  const std::string path = "uncertainty";
  reader.RequireMap(node, path);
  reader.CheckKeys(node, path, {"parameters", "covariance", "model_form", "priors"});
  ParameterUncertainty uncertainty;
  const YAML::Node parameters = reader.Require(node, path, "parameters");
  reader.RequireSequence(parameters, path + ".parameters");
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    const std::string at = IndexPath(path + ".parameters", i);
    reader.RequireMap(parameters[i], at);
    reader.CheckKeys(parameters[i], at, {"name", "value", "log"});
    uncertainty.names.push_back(
        reader.ReadString(reader.Require(parameters[i], at, "name"), at + ".name"));
    uncertainty.values.push_back(
        reader.ReadNumber(reader.Require(parameters[i], at, "value"), at + ".value"));
    bool log = true;
    if (const YAML::Node flag = parameters[i]["log"];
        flag && (!flag.IsScalar() || !YAML::convert<bool>::decode(flag, log))) {
      reader.Fail(flag, at + ".log", "expected true or false");
    }
    if (log && !(uncertainty.values.back() > 0.0)) {
      reader.Fail(parameters[i]["value"], at + ".value", "must be > 0 where log is true");
    }
    uncertainty.log.push_back(log);
  }
  const std::size_t n = uncertainty.names.size();
  if (n == 0) reader.Fail(parameters, path + ".parameters", "expected at least one parameter");
  const YAML::Node rows = reader.Require(node, path, "covariance");
  reader.RequireSequence(rows, path + ".covariance");
  if (rows.size() != n) {
    reader.Fail(rows, path + ".covariance", fmt::format("expected {} rows, one per parameter", n));
  }
  uncertainty.covariance.resize(long(n), long(n));
  for (std::size_t i = 0; i < n; ++i) {
    const std::string at = IndexPath(path + ".covariance", i);
    reader.RequireSequence(rows[i], at);
    if (rows[i].size() != n) reader.Fail(rows[i], at, fmt::format("expected {} numbers", n));
    for (std::size_t j = 0; j < n; ++j) {
      uncertainty.covariance(long(i), long(j)) = reader.ReadNumber(rows[i][j], IndexPath(at, j));
    }
  }
  const Eigen::MatrixXd& c = uncertainty.covariance;
  if (!((c - c.transpose()).cwiseAbs().maxCoeff() <= 1e-9 * c.cwiseAbs().maxCoeff()) ||
      c.diagonal().minCoeff() < 0.0) {
    reader.Fail(rows, path + ".covariance", "must be symmetric with a non-negative diagonal");
  }
  // A covariance has no negative variance in any direction. The file's nine digits leave
  // eigenvalues of about 1e-9 of the largest on either side of zero, so the test allows 1e-6.
  const Eigen::VectorXd eigenvalues =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(c, Eigen::EigenvaluesOnly).eigenvalues();
  if (eigenvalues.minCoeff() < -1e-6 * eigenvalues.cwiseAbs().maxCoeff()) {
    reader.Fail(rows, path + ".covariance",
                fmt::format("must be positive semi-definite: it has a negative variance ({:.3g}) "
                            "along an eigenvector",
                            eigenvalues.minCoeff()));
  }
  if (node["model_form"]) {
    uncertainty.model_form = ReadModelForm(reader, node["model_form"], uncertainty);
  }
  if (node["priors"]) {
    for (const BuildingFitPriorEntry& prior :
         ReadPriorEntries(reader, node["priors"], "uncertainty.priors", true, uncertainty.names)) {
      uncertainty.priors.push_back({prior.name, *prior.value, prior.sigma, prior.source});
    }
  }
  return uncertainty;
}

// The output section: the results file and what goes into it (output_selection.h).
void ReadOutput(const YamlReader& reader, const YAML::Node& output, ModelFile* model) {
  reader.RequireMap(output, "output");
  reader.CheckKeys(output, "output", {"file", "every", "quantities", "levels", "summary_only"});
  OutputSelection& selection = model->output;
  if (output["file"]) model->output_file = reader.ReadName(output["file"], "output.file");
  if (output["every"]) {
    selection.every = reader.ReadInteger(output["every"], "output.every");
    if (selection.every < 1) {
      reader.Fail(output["every"], "output.every",
                  fmt::format("{} (expected a whole number of steps >= 1)", selection.every));
    }
  }
  if (output["quantities"]) {
    const YAML::Node list = output["quantities"];
    reader.RequireSequence(list, "output.quantities");
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string path = IndexPath("output.quantities", i);
      const std::string name = reader.ReadString(list[i], path);
      const std::string error = UnknownQuantity(name);
      if (!error.empty()) reader.Fail(list[i], path, error);
      selection.quantities.push_back(name);
    }
  }
  if (output["levels"]) {
    const YAML::Node list = output["levels"];
    reader.RequireSequence(list, "output.levels");
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::string path = IndexPath("output.levels", i);
      const std::optional<int> level = ParseLevel(reader.ReadString(list[i], path));
      if (!level)
        reader.Fail(list[i], path, "expected a level: 0 for the base, k for floor k, or roof");
      selection.levels.push_back(*level);
    }
  }
  if (output["summary_only"]) {
    const YAML::Node flag = output["summary_only"];
    bool value = false;
    if (!flag.IsScalar() || !YAML::convert<bool>::decode(flag, value)) {
      reader.Fail(flag, "output.summary_only", "expected true or false");
    }
    selection.summary_only = value;
  }
}

}  // namespace

std::vector<std::string> RecordFiles(const ModelFile& model) {
  std::vector<std::string> files;
  const auto add = [&](const GroundMotionSection& motion) {
    files.push_back(
        (std::filesystem::path(model.path).parent_path() / motion.file).lexically_normal());
  };
  for (const GroundMotionSection& motion : model.excitation.ground_motion) add(motion);
  if (model.excitation.vertical) add(*model.excitation.vertical);
  return files;
}

ModelFile LoadModelFile(const std::string& path) {
  return LoadModelText(YamlReader(path).ReadText(), path);
}

ModelFile LoadModelText(const std::string& text, const std::string& path) {
  const YamlReader reader(path);
  ModelFile model;
  model.text = text;
  const YAML::Node root = reader.LoadText(text);
  reader.RequireMap(root, "");
  reader.CheckKeys(root, "",
                   {"description", "units", "isolation", "structure", "plan", "excitation",
                    "analysis", "output", "cyclic", "axial_load", "uncertainty"});
  if (root["plan"] && root["structure"]) {
    reader.Fail(root["plan"], "plan",
                "a model is either a building in plan (plan) or one in one direction "
                "(structure), not both");
  }
  if (root["plan"] && root["isolation"]) {
    reader.Fail(root["isolation"], "isolation",
                "a building in plan carries its isolators' laws in plan.isolators[i].components");
  }
  model.path = path;
  if (root["description"]) {
    model.description = reader.ReadString(root["description"], "description");
  }
  model.units = ReadUnits(reader, root);
  if (root["isolation"]) {
    BearingGroup group;
    model.isolation = ReadIsolation(reader, root["isolation"], "isolation",
                                    std::filesystem::path(path).parent_path(), model.units,
                                    &model.included_files, &group, &model.identified_range);
    model.isolation_count = group.count;
    model.isolation_name = group.name;
    if (!group.modification.empty()) {
      model.modifications.push_back({"isolation", std::nullopt, std::move(group.modification)});
    }
  }
  if (root["structure"]) model.structure = ReadStructure(reader, root["structure"], model.units);
  if (root["plan"]) {
    model.structure = ReadPlan(reader, root["plan"], model.units, &model.modifications);
  }
  if (root["excitation"])
    model.excitation = ReadExcitation(reader, root["excitation"], model.units);
  if (root["analysis"]) model.analysis = ReadAnalysis(reader, root["analysis"], model.units);
  if (root["axial_load"]) model.axial_load = ReadAxialLoad(reader, root["axial_load"], model.units);
  if (root["output"]) ReadOutput(reader, root["output"], &model);
  if (root["cyclic"]) model.cyclic = ReadCyclic(reader, root["cyclic"]);
  if (root["uncertainty"]) model.uncertainty = ReadUncertainty(reader, root["uncertainty"]);
  if (!model.structure && model.isolation.size() == 0) {
    reader.Fail(root, "",
                "missing key 'isolation' (a model needs isolation, structure, or both; or plan)");
  }
  CheckConsistency(reader, root, model);
  return model;
}

}  // namespace isolab::model
