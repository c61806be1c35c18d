#include "isolab/model/bounds.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace isolab::model {
namespace {

// "50" or "50 kN" times `lambda`: the number scaled, its unit kept; written to 12 significant
// digits, so that 50 x 1.520875 reads 76.04375 as the engineer computes it, not the product's
// round-off (76.04374999999997).
std::string Scaled(const std::string& text, double lambda, const SourceLocation& where) {
  const char* begin = text.c_str();
  char* end = nullptr;
  const double value = std::strtod(begin, &end);
  if (end == begin) {
    throw InputError(where, fmt::format("'{}' is not a number to scale", text));
  }
  return fmt::format("{:.12g}{}", value * lambda, std::string(end));
}

// A path the model names, relative to its folder, made absolute so the bound model runs from
// anywhere.
void Absolute(YAML::Node node, const std::filesystem::path& folder) {
  if (!node || !node.IsMap() || !node["file"]) return;
  const std::filesystem::path file = node["file"].Scalar();
  if (file.is_relative()) node["file"] = (folder / file).lexically_normal().string();
}

// results.h5 -> results_upper.h5, so the three models do not write one file.
void RenameResults(YAML::Node root, const std::string& bound) {
  if (!root["output"] || !root["output"].IsMap() || !root["output"]["file"]) return;
  const std::filesystem::path file = root["output"]["file"].Scalar();
  std::filesystem::path renamed = file;
  renamed.replace_filename(file.stem().string() + "_" + bound + file.extension().string());
  root["output"]["file"] = renamed.string();
}

// The tree with every alias written out: yaml-cpp gives the nodes an alias names one identity, so
// a property scaled through one isolator's alias would be scaled again through each other alias
// (four pendulums sharing `components: &fp` got lambda^4). Copied, each is a value of its own.
YAML::Node WithAliasesExpanded(const YAML::Node& node) {
  YAML::Node copy;
  switch (node.Type()) {
    case YAML::NodeType::Scalar:
      copy = node.Scalar();
      copy.SetTag(node.Tag());
      break;
    case YAML::NodeType::Sequence:
      copy = YAML::Node(YAML::NodeType::Sequence);
      for (const YAML::Node& element : node) copy.push_back(WithAliasesExpanded(element));
      break;
    case YAML::NodeType::Map:
      copy = YAML::Node(YAML::NodeType::Map);
      for (const auto& entry : node) {
        copy.force_insert(WithAliasesExpanded(entry.first), WithAliasesExpanded(entry.second));
      }
      break;
    case YAML::NodeType::Null:
      copy = YAML::Node(YAML::NodeType::Null);
      break;
    case YAML::NodeType::Undefined:
      break;
  }
  copy.SetStyle(node.Style());
  return copy;
}

}  // namespace

std::string WithCentresOfMassShiftedText(const std::string& text, const ModelFile& model,
                                         hysteresis::Vec2 shift, const std::string& case_name) {
  YAML::Node root = WithAliasesExpanded(YAML::Load(text));
  const structure::PlanBuilding& plan = model.structure->plan;
  const auto at = [](hysteresis::Vec2 p) {
    YAML::Node point(YAML::NodeType::Sequence);
    point.SetStyle(YAML::EmitterStyle::Flow);
    point.push_back(fmt::format("{:.17g}", p.x));
    point.push_back(fmt::format("{:.17g}", p.y));
    return point;
  };
  root["plan"]["base"]["centre_of_mass"] = at(plan.base.centre_of_mass + shift);
  if (YAML::Node stories = root["plan"]["stories"]; stories && stories.IsSequence()) {
    for (std::size_t i = 0; i < stories.size(); ++i) {
      stories[i]["centre_of_mass"] = at(plan.stories[i].floor.centre_of_mass + shift);
    }
  } else if (stories && !plan.stories.empty()) {  // equal stories: one centre for all
    stories["centre_of_mass"] = at(plan.stories.front().floor.centre_of_mass + shift);
  }
  const std::string description =
      root["description"] ? root["description"].Scalar() + " " : std::string();
  root["description"] = description + fmt::format(
                                          "(accidental eccentricity {}: every centre of "
                                          "mass moved by [{:g}, {:g}])",
                                          case_name, shift.x, shift.y);
  YAML::Emitter out;
  out << root;
  return std::string(out.c_str()) + "\n";
}

BoundModels MakeBoundModels(const ModelFile& model) {
  if (model.modifications.empty()) {
    throw InputError({model.path},
                     "no property modification factors: give isolation.modification or "
                     "plan.isolators[i].modification (docs/design.md)");
  }
  const std::filesystem::path path = model.path;
  const std::filesystem::path folder = std::filesystem::absolute(path).parent_path();
  BoundModels result;
  for (const char* bound : {"nominal", "upper", "lower"}) {
    const std::string name = bound;
    YAML::Node root = WithAliasesExpanded(YAML::Load(model.text));
    for (const BearingModification& modification : model.modifications) {
      YAML::Node section =
          modification.entry ? root["plan"]["isolators"][*modification.entry] : root["isolation"];
      YAML::Node components = section["components"];
      for (const PropertyFactors& property : modification.properties) {
        YAML::Node value = components[property.component][property.key];
        const FactorPair lambda = property.Combined();
        const std::string nominal = value.Scalar();
        if (name == "upper") value = Scaled(nominal, lambda.max, property.location);
        if (name == "lower") value = Scaled(nominal, lambda.min, property.location);
        if (name == "nominal") {
          result.properties.push_back({modification.bearing, property.component_name, property.key,
                                       lambda, nominal,
                                       Scaled(nominal, lambda.min, property.location),
                                       Scaled(nominal, lambda.max, property.location)});
        }
      }
      section.remove("modification");
    }
    if (YAML::Node excitation = root["excitation"]; excitation && excitation.IsMap()) {
      if (YAML::Node motion = excitation["ground_motion"]; motion && motion.IsMap()) {
        Absolute(motion, folder);
        Absolute(motion["h1"], folder);
        Absolute(motion["h2"], folder);
      }
    }
    Absolute(root["isolation"], folder);
    RenameResults(root, name);
    const std::string description =
        root["description"] ? root["description"].Scalar() + " " : std::string();
    root["description"] =
        description + (name == "nominal" ? "(nominal properties)"
                       : name == "upper" ? "(upper bound: the properties times lambda_max)"
                                         : "(lower bound: the properties times lambda_min)");
    YAML::Emitter out;
    out << root;
    const std::string text =
        fmt::format("{}the {} bound of {}\n", kBoundModelHeader, name, model.path) + out.c_str() +
        "\n";
    const std::string written = (folder / (path.stem().string() + "_" + name + ".yaml")).string();
    try {
      LoadModelText(text, written);
    } catch (const InputError& error) {
      // The bound's text is not written: its rule is reported at the model given, without the
      // line of a file the user cannot open.
      const std::string where = error.location().Describe() + ": ";
      std::string what = error.what();
      if (what.starts_with(where)) what.erase(0, where.size());
      throw InputError({model.path},
                       fmt::format("the {} bound model breaks a rule: {}", name, what));
    }
    result.models.push_back({name, text});
  }
  return result;
}

}  // namespace isolab::model
