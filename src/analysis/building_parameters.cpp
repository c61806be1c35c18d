#include "isolab/analysis/building_parameters.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>

#include "isolab/core/errors.h"
#include "isolab/hysteresis/law_parameters.h"

namespace isolab::analysis {
namespace {

std::vector<std::string> Split(const std::string& name) {
  std::vector<std::string> parts;
  std::size_t begin = 0;
  while (true) {
    const std::size_t dot = name.find('.', begin);
    parts.push_back(name.substr(begin, dot - begin));
    if (dot == std::string::npos) return parts;
    begin = dot + 1;
  }
}

[[noreturn]] void Refuse(const model::ModelFile& model, const std::string& name,
                         const std::string& why) {
  throw InputError({model.path}, fmt::format("parameter '{}': {}", name, why));
}

const structure::ShearBuilding& Building(const model::ModelFile& model, const std::string& name) {
  if (!model.structure || model.structure->kind != model::StructureSection::Kind::kShearBuilding) {
    Refuse(model, name, "the model needs a one-direction shear_building structure");
  }
  return model.structure->building;
}

// A 1-based index within [1, count].
std::size_t Index(const model::ModelFile& model, const std::string& name, const std::string& text,
                  std::size_t count, const char* what) {
  std::size_t n = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (error != std::errc() || end != text.data() + text.size() || n < 1 || n > count) {
    Refuse(model, name, fmt::format("'{}' is not a {} number from 1 to {}", text, what, count));
  }
  return n - 1;
}

// Where a named property lives in the model.
struct Target {
  enum class Kind { kIsolation, kStoryStiffness, kDamping, kMass } kind = Kind::kMass;
  std::size_t index = 0;  // component, story (kAll for every one), mode (kAll) or level
  std::size_t key = 0;    // isolation: the key's position in ParameterKeys(type, form)
  hysteresis::ParameterForm form = hysteresis::ParameterForm::kMathematical;
  static constexpr std::size_t kAll = static_cast<std::size_t>(-1);
};

Target Locate(const model::ModelFile& model, const std::string& name) {
  const std::vector<std::string> part = Split(name);
  if (part[0] == "isolation" && part.size() == 3) {
    const auto& components = model.isolation.components();
    const auto found = std::find_if(components.begin(), components.end(),
                                    [&](const auto& c) { return c.name == part[1]; });
    if (found == components.end()) {
      std::string names;
      for (const auto& c : components) names += (names.empty() ? "" : ", ") + c.name;
      Refuse(model, name,
             fmt::format("no isolation component '{}' (the model has: {})", part[1],
                         names.empty() ? "none" : names));
    }
    Target target{Target::Kind::kIsolation, std::size_t(found - components.begin())};
    const hysteresis::LawType type = found->parameters.type();
    for (const auto form :
         {hysteresis::ParameterForm::kMathematical, hysteresis::ParameterForm::kMechanical}) {
      const auto keys = hysteresis::ParameterKeys(type, form);
      const auto key = std::find(keys.begin(), keys.end(), part[2]);
      if (key != keys.end()) {
        target.form = form;
        target.key = std::size_t(key - keys.begin());
        return target;
      }
    }
    Refuse(model, name,
           fmt::format("{} has no parameter '{}'", hysteresis::LawName(type), part[2]));
  }
  if (part[0] == "stories" && part.size() == 2 && part[1] == "stiffness") {
    Building(model, name);
    return {Target::Kind::kStoryStiffness, Target::kAll};
  }
  if (part[0] == "story" && part.size() == 3 && part[2] == "stiffness") {
    const auto& stories = Building(model, name).stories;
    return {Target::Kind::kStoryStiffness, Index(model, name, part[1], stories.size(), "story")};
  }
  if (part[0] == "damping" && part.size() >= 2 && part.size() <= 3 && part[1] == "ratio") {
    const auto& building = Building(model, name);
    if (building.damping.kind != structure::SuperstructureDamping::Kind::kModal) {
      Refuse(model, name, "the superstructure's damping must be modal (damping: {type: modal})");
    }
    if (part.size() == 2) return {Target::Kind::kDamping, Target::kAll};
    return {Target::Kind::kDamping, Index(model, name, part[2], building.stories.size(), "mode")};
  }
  if (part[0] == "mass" && part.size() >= 2) {
    const auto& building = Building(model, name);
    if (part.size() == 2 && part[1] == "base") {
      if (model.isolation.size() == 0) {
        Refuse(model, name, "the building has no base level (no isolation)");
      }
      return {Target::Kind::kMass, 0};
    }
    if (part.size() == 3 && part[1] == "floor") {
      return {Target::Kind::kMass,
              Index(model, name, part[2], building.stories.size(), "floor") + 1};
    }
  }
  Refuse(model, name,
         "expected isolation.<component>.<key>, stories.stiffness, story.<n>.stiffness, "
         "damping.ratio, damping.ratio.<n>, mass.base or mass.floor.<n>");
}

double StoryStiffness(const model::ModelFile& model, const std::string& name,
                      const structure::Story& story) {
  const auto& components = story.assembly.components();
  if (components.size() != 1 ||
      components[0].parameters.type() != hysteresis::LawType::kLinearSpring) {
    Refuse(model, name,
           fmt::format("{} is not linear (stiffness: ...): only a linear story's "
                       "stiffness is fitted",
                       story.name));
  }
  return components[0].parameters.Values(hysteresis::ParameterForm::kMathematical)[0];
}

// Level l's mass: 0 the base, then the floors.
template <typename Building>
auto& LevelMass(Building& building, std::size_t level) {
  return level == 0 ? building.base_mass : building.stories[level - 1].floor_mass;
}

}  // namespace

double ParameterValue(const model::ModelFile& model, const std::string& name) {
  const Target target = Locate(model, name);
  switch (target.kind) {
    case Target::Kind::kIsolation:
      return model.isolation.components()[target.index].parameters.Values(target.form)[target.key];
    case Target::Kind::kStoryStiffness: {
      const auto& stories = model.structure->building.stories;
      if (target.index != Target::kAll) return StoryStiffness(model, name, stories[target.index]);
      double sum = 0.0;  // every story's: their mean, the value a uniform fit starts from
      for (const auto& story : stories) sum += StoryStiffness(model, name, story);
      return sum / double(stories.size());
    }
    case Target::Kind::kDamping: {
      const auto& ratios = model.structure->building.damping.modal_ratios;
      return ratios[target.index == Target::kAll || ratios.size() == 1 ? 0 : target.index];
    }
    case Target::Kind::kMass:
      return LevelMass(model.structure->building, target.index);
  }
  return 0.0;
}

void SetParameters(model::ModelFile* model, std::span<const std::string> names,
                   std::span<const double> values) {
  std::vector<std::pair<std::size_t, double>> masses;  // level, value
  for (std::size_t p = 0; p < names.size(); ++p) {
    const Target target = Locate(*model, names[p]);
    const double value = values[p];
    switch (target.kind) {
      case Target::Kind::kIsolation: {
        std::vector<hysteresis::Component> components = model->isolation.components();
        hysteresis::LawParameters& law = components[target.index].parameters;
        std::vector<double> given = law.Values(target.form);
        given[target.key] = value;
        law = hysteresis::LawParameters::Make(law.type(), target.form, given);
        model->isolation = hysteresis::ParallelAssembly(std::move(components));
        break;
      }
      case Target::Kind::kStoryStiffness: {
        auto& stories = model->structure->building.stories;
        for (std::size_t s = 0; s < stories.size(); ++s) {
          if (target.index != Target::kAll && s != target.index) continue;
          StoryStiffness(*model, names[p], stories[s]);
          stories[s].assembly =
              hysteresis::SingleLaw(hysteresis::LawType::kLinearSpring, {value}, "k");
        }
        break;
      }
      case Target::Kind::kDamping: {
        auto& building = model->structure->building;
        auto& ratios = building.damping.modal_ratios;
        if (target.index == Target::kAll) {
          std::fill(ratios.begin(), ratios.end(), value);
        } else {
          if (ratios.size() == 1) ratios.assign(building.stories.size(), ratios[0]);
          ratios[target.index] = value;
        }
        break;
      }
      case Target::Kind::kMass:
        masses.emplace_back(target.index, value);
        break;
    }
  }
  if (masses.empty()) return;
  structure::ShearBuilding& building = model->structure->building;
  const std::size_t levels = building.stories.size() + 1;
  const std::size_t first = model->isolation.size() > 0 ? 0 : 1;  // a fixed base has no level 0
  double total = 0.0, named = 0.0;
  for (std::size_t l = first; l < levels; ++l) total += LevelMass(building, l);
  std::vector<bool> fixed(levels, false);
  fixed[0] = first == 1;
  for (const auto& [level, value] : masses) {
    if (!(value > 0.0)) throw InvalidParameter({"mass", value, "must be > 0"});
    fixed[level] = true;
    named += value;
  }
  const long free = std::count(fixed.begin(), fixed.end(), false);
  if (free == 0) {
    throw InputError({model->path},
                     "every level's mass is a parameter: leave at least one free to hold the "
                     "model's total mass (motions alone cannot fix a mass scale)");
  }
  const double share = (total - named) / double(free);
  if (!(share > 0.0)) {
    throw InvalidParameter({"mass", named, "leaves no mass for the levels not named"});
  }
  for (const auto& [level, value] : masses) LevelMass(building, level) = value;
  for (std::size_t l = 0; l < levels; ++l) {
    if (!fixed[l]) LevelMass(building, l) = share;
  }
}

ParameterRange DefaultRange(const std::string& name, double value) {
  if (name.rfind("damping.ratio", 0) == 0) return {0.002, 0.3, true};
  if (value > 0.0) return {value / 3.0, value * 3.0, true};
  const double span = std::max(3.0 * std::abs(value), 1e-12);
  return {-span, span, false};
}

}  // namespace isolab::analysis
