#include "isolab/model/fitted_building_file.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>

#include "isolab/core/errors.h"
#include "isolab/hysteresis/law_parameters.h"

namespace isolab::model {
namespace {

std::string Number(double value) { return fmt::format("{:.9g}", value); }

YAML::Node Flow(YAML::Node node) {
  node.SetStyle(YAML::EmitterStyle::Flow);
  return node;
}

YAML::Node Components(const hysteresis::ParallelAssembly& assembly) {
  YAML::Node list;
  for (const hysteresis::Component& component : assembly.components()) {
    YAML::Node entry;
    entry["name"] = component.name;
    const hysteresis::LawType type = component.parameters.type();
    entry["type"] = std::string(hysteresis::LawName(type));
    const auto keys = hysteresis::ParameterKeys(type, hysteresis::ParameterForm::kMathematical);
    const std::vector<double> values =
        component.parameters.Values(hysteresis::ParameterForm::kMathematical);
    for (std::size_t k = 0; k < keys.size(); ++k) {
      if (!std::isnan(values[k])) entry[std::string(keys[k])] = Number(values[k]);
    }
    list.push_back(Flow(entry));
  }
  return list;
}

// A mass as a quantity in tonnes, which a reader takes in any unit system.
std::string Tonnes(double mass, const UnitSystem& units) {
  return Number(mass * units.SiFactor(dimension::kMass) / 1000.0) + " t";
}

}  // namespace

std::string FittedBuildingText(const ModelFile& fitted, const std::string& note) {
  YAML::Node root = YAML::Load(fitted.text);
  if (fitted.isolation.size() > 0) {
    const YAML::Node old = root["isolation"];
    YAML::Node isolation;
    for (const char* key : {"name", "count"}) {
      if (old && old.IsMap() && old[key]) isolation[key] = old[key];
    }
    if (fitted.isolation_count && !isolation["count"]) {
      isolation["count"] = *fitted.isolation_count;
      isolation["name"] = fitted.isolation_name;
    }
    if (fitted.identified_range) {
      const identification::IdentifiedRange& range = *fitted.identified_range;
      YAML::Node node;
      node["displacement"] = Number(range.displacement);
      node["velocity"] = Number(range.velocity);
      node["cycles"] = Number(range.cycles);
      for (const std::string& name : range.data) node["data"].push_back(name);
      isolation["identified_range"] = Flow(node);
    }
    isolation["components"] = Components(fitted.isolation);
    root["isolation"] = isolation;
  }
  if (fitted.structure && fitted.structure->kind == StructureSection::Kind::kShearBuilding) {
    const structure::ShearBuilding& building = fitted.structure->building;
    YAML::Node structure = root["structure"];
    if (fitted.isolation.size() > 0)
      structure["base_mass"] = Tonnes(building.base_mass, fitted.units);
    bool linear = true;
    YAML::Node stories;
    for (const structure::Story& story : building.stories) {
      const auto& components = story.assembly.components();
      linear = linear && components.size() == 1 &&
               components[0].parameters.type() == hysteresis::LawType::kLinearSpring;
      if (!linear) break;
      YAML::Node entry;
      entry["mass"] = Tonnes(story.floor_mass, fitted.units);
      entry["stiffness"] =
          Number(components[0].parameters.Values(hysteresis::ParameterForm::kMathematical)[0]);
      if (story.height > 0.0) entry["height"] = Number(story.height);
      stories.push_back(Flow(entry));
    }
    if (linear) structure["stories"] = stories;
    if (building.damping.kind == structure::SuperstructureDamping::Kind::kModal) {
      YAML::Node damping;
      damping["type"] = "modal";
      YAML::Node ratios;
      for (const double ratio : building.damping.modal_ratios) ratios.push_back(Number(ratio));
      damping["ratios"] = Flow(ratios);
      structure["damping"] = Flow(damping);
    }
  }
  if (fitted.uncertainty) {
    const ParameterUncertainty& u = *fitted.uncertainty;
    YAML::Node section;
    for (std::size_t p = 0; p < u.names.size(); ++p) {
      YAML::Node entry;
      entry["name"] = u.names[p];
      entry["value"] = Number(u.values[p]);
      entry["log"] = bool(u.log[p]);
      section["parameters"].push_back(Flow(entry));
    }
    for (long i = 0; i < u.covariance.rows(); ++i) {
      YAML::Node row;
      for (long j = 0; j < u.covariance.cols(); ++j) row.push_back(Number(u.covariance(i, j)));
      section["covariance"].push_back(Flow(row));
    }
    for (const ModelFormFit& fit : u.model_form) {
      YAML::Node entry, motions, values;
      for (const std::string& motion : fit.fitted_on) motions.push_back(motion);
      for (const double value : fit.values) values.push_back(Number(value));
      entry["fitted_on"] = Flow(motions);
      entry["values"] = Flow(values);
      section["model_form"].push_back(entry);
    }
    for (const ParameterPrior& prior : u.priors) {
      YAML::Node entry;
      entry["name"] = prior.name;
      entry["value"] = Number(prior.value);
      entry["sigma"] = Number(prior.sigma);
      entry["source"] = prior.source;
      section["priors"].push_back(Flow(entry));
    }
    root["uncertainty"] = section;
  }
  const std::string from = root["description"] ? root["description"].Scalar() : "";
  root["description"] = note + (from.empty() ? "" : "; it started from: " + from);
  YAML::Emitter out;
  out << root;
  const std::string text = std::string(out.c_str()) + "\n";
  try {
    LoadModelText(text, fitted.path);
  } catch (const InputError& error) {
    throw InputError({fitted.path},
                     fmt::format("the fitted model breaks a rule: {}", error.what()));
  }
  return text;
}

}  // namespace isolab::model
