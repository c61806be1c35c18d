// Reading law components: type, name and parameters in one form, each a number in the model's
// units or a quantity with its own unit.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <unordered_map>
#include <vector>

#include "model_sections.h"

namespace isolab::model {
namespace {

using hysteresis::Component;
using hysteresis::LawParameters;
using hysteresis::LawType;
using hysteresis::ParameterForm;

// Stiffnesses k* (and Bouc-Wen's alpha), displacements u* and the degrading laws' slip_scale,
// the slider force fs and the dashpot coefficient c; Bouc-Wen's beta, gamma, delta, nu and the
// degrading laws' loss are plain numbers (beta in model units, force^(1-nu)/length). The bearing
// presets: weights and strengths are forces, friction coefficients, damping ratios, strains and
// E2 (1/degC) plain numbers; the lead core's heat capacity rho c is force/length^2 per degC and
// the steel's conductivity force/time per degC (the degree is not a dimension here).
Dimension ParameterDimension(std::string_view key) {
  constexpr Dimension kPressure{1, -1, -2}, kArea{0, 2, 0}, kDiffusivity{0, 2, -1},
      kConductivity{1, 1, -3}, kSlowness{0, -1, 1};
  if (key == "beta" || key == "gamma" || key == "delta" || key == "nu" || key == "loss" ||
      key.starts_with("mu") || key == "damping" || key.ends_with("strain") || key == "e2") {
    return dimension::kNone;
  }
  if (key == "slip_scale" || key == "r" || key == "dy" || key == "tr" || key == "lead_diameter" ||
      key == "lead_height" || key == "shim_thickness") {
    return dimension::kLength;
  }
  if (key == "fs" || key == "w" || key == "qd") return dimension::kForce;
  if (key == "c") return dimension::kDampingCoefficient;
  if (key == "g" || key == "lead_heat_capacity") return kPressure;
  if (key == "area") return kArea;
  if (key == "steel_diffusivity") return kDiffusivity;
  if (key == "steel_conductivity") return kConductivity;
  if (key == "a") return kSlowness;  // the friction law's rate parameter, time/length
  if (key.front() == 'u') return dimension::kLength;
  return dimension::kStiffness;
}

// The lead core's and the steel's material data, in SI per degC: what solids and metals have,
// widely. A value outside is a unit slip (kN/mm^2 taken for MPa, W for kW), and it is no mere
// miscalibration: the core would heat or cool within a fraction of a time step, so that no time
// step resolves its temperature (a heat capacity 10^6 times too small made Newmark's heat and
// force disagree by 68 % of the input energy).
struct MaterialRange {
  std::string_view key;
  double low, high;  // SI
  std::string_view si_unit, per, typical;
};
constexpr MaterialRange kMaterialRanges[] = {
    {"lead_heat_capacity", 0.5e6, 5e6, "J/(m^3 degC)", " per degC", "lead 1.456e6"},
    {"steel_conductivity", 1.0, 500.0, "W/(m degC)", " per degC", "steel 50, copper 400"},
    {"steel_diffusivity", 1e-6, 2e-4, "m^2/s", "", "steel 1.41e-5, stainless 4e-6"},
};

void CheckMaterialData(const YamlReader& reader, const YAML::Node& node, const std::string& path,
                       std::span<const std::string_view> keys, const std::vector<double>& values,
                       const UnitSystem& units) {
  for (const MaterialRange& range : kMaterialRanges) {
    const auto key = std::find(keys.begin(), keys.end(), range.key);
    if (key == keys.end() || std::isnan(values[key - keys.begin()])) continue;
    const double value = values[key - keys.begin()];
    const Dimension dimension = ParameterDimension(range.key);
    const double factor = units.SiFactor(dimension);
    if (value * factor >= range.low && value * factor <= range.high) continue;
    const std::string unit = DescribeUnits(units, dimension) + std::string(range.per);
    reader.Fail(node[std::string(range.key)], "",
                fmt::format("{} = {:g} {} = {:g} {} (must be {:g} to {:g} {}, {:g} to {:g} {}; "
                            "{}): a unit slip?",
                            ChildPath(path, range.key), value, unit, value * factor, range.si_unit,
                            range.low, range.high, range.si_unit, range.low / factor,
                            range.high / factor, unit, range.typical));
  }
}

// The keys a component of this type may carry in either form, for "unknown key" hints.
std::vector<std::string_view> AllowedComponentKeys(LawType type) {
  std::vector<std::string_view> keys = {"name", "type"};
  for (const ParameterForm form : {ParameterForm::kMathematical, ParameterForm::kMechanical}) {
    for (const std::string_view key : hysteresis::ParameterKeys(type, form)) {
      if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
    }
  }
  if (type == LawType::kFrictionPendulum) keys.push_back("period");
  return keys;
}

bool Contains(std::span<const std::string_view> keys, std::string_view key) {
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}

// Which form a component's keys are written in; both forms in one component is an error.
ParameterForm DetectForm(const YamlReader& reader, const YAML::Node& node, const std::string& path,
                         LawType type) {
  const auto math = hysteresis::ParameterKeys(type, ParameterForm::kMathematical);
  const auto mech = hysteresis::ParameterKeys(type, ParameterForm::kMechanical);
  std::string math_key, mech_key;
  for (const auto& entry : node) {
    const std::string key = entry.first.Scalar();  // CheckKeys made sure keys are scalars
    const bool in_math = Contains(math, key), in_mech = Contains(mech, key);
    if (in_math && !in_mech && math_key.empty()) math_key = key;
    if (in_mech && !in_math && mech_key.empty()) mech_key = key;
  }
  if (!math_key.empty() && !mech_key.empty()) {
    reader.Fail(
        node, path,
        fmt::format("mixes mathematical ({}) and mechanical ({}) parameters; give one form: "
                    "{} or {}",
                    math_key, mech_key, fmt::join(math, ", "), fmt::join(mech, ", ")));
  }
  return mech_key.empty() ? ParameterForm::kMathematical : ParameterForm::kMechanical;
}

// A friction pendulum may give its pendulum period T instead of its radius: engineers specify
// either, and R = g T^2 / (4 pi^2) with g in the model's units.
void ReadPendulumPeriod(const YamlReader& reader, const YAML::Node& node, const std::string& path,
                        const UnitSystem& units, std::span<const std::string_view> keys,
                        std::vector<double>& values) {
  const YAML::Node period = node["period"];
  if (!period.IsDefined()) return;
  const std::string period_path = ChildPath(path, "period");
  if (node["r"].IsDefined()) {
    reader.Fail(period, period_path, "give the radius r or the period, not both");
  }
  const double t = reader.ReadQuantity(period, period_path, dimension::kTime, units);
  if (!(t > 0.0) || !std::isfinite(t)) {
    reader.Fail(period, period_path, fmt::format("{} (must be > 0)", t));
  }
  const double g = units.Convert(1.0, "g", dimension::kAcceleration);
  const auto r = std::find(keys.begin(), keys.end(), "r");
  values[r - keys.begin()] = g * t * t / (4.0 * std::numbers::pi * std::numbers::pi);
}

Component ReadComponent(const YamlReader& reader, const YAML::Node& node, const std::string& path,
                        std::size_t index, const UnitSystem& units) {
  reader.RequireMap(node, path);
  const YAML::Node type_node = reader.Require(node, path, "type");
  const std::string type_name = reader.ReadString(type_node, ChildPath(path, "type"));
  const auto type = hysteresis::LawTypeFromName(type_name);
  if (!type) {
    std::vector<std::string_view> names;
    for (const LawType t : hysteresis::AllLawTypes()) names.push_back(hysteresis::LawName(t));
    const std::string_view nearest = NearestWord(type_name, names);
    reader.Fail(type_node, ChildPath(path, "type"),
                fmt::format("'{}' is not an element law{} (expected one of: {})", type_name,
                            nearest.empty() ? "" : fmt::format("; did you mean '{}'?", nearest),
                            fmt::join(names, ", ")));
  }
  reader.CheckKeys(node, path, AllowedComponentKeys(*type));

  const ParameterForm form = DetectForm(reader, node, path, *type);
  const auto keys = hysteresis::ParameterKeys(*type, form);
  std::vector<double> values(keys.size(), NAN);
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const YAML::Node value = node[std::string(keys[i])];
    if (value.IsDefined()) {
      values[i] =
          reader.ReadQuantity(value, ChildPath(path, keys[i]), ParameterDimension(keys[i]), units);
    }
  }

  if (*type == LawType::kFrictionPendulum)
    ReadPendulumPeriod(reader, node, path, units, keys, values);
  CheckMaterialData(reader, node, path, keys, values, units);

  std::string name = fmt::format("c{}", index + 1);
  if (node["name"].IsDefined()) name = reader.ReadString(node["name"], ChildPath(path, "name"));

  try {
    return Component{name, LawParameters::Make(*type, form, values)};
  } catch (const InvalidParameter& error) {
    const ParameterViolation& violation = error.violation();
    const YAML::Node at = node[violation.key];
    if (at.IsDefined()) {
      throw InputError(reader.Locate(at), fmt::format("{}.{}", path, violation.Describe()));
    }
    reader.Fail(
        node, path,
        fmt::format("missing key '{}' ({}; {} in {} form takes {})", violation.key, violation.rule,
                    type_name, form == ParameterForm::kMathematical ? "mathematical" : "mechanical",
                    fmt::join(keys, ", ")));
  }
}

}  // namespace

hysteresis::ParallelAssembly ReadAssembly(const YamlReader& reader, const YAML::Node& list,
                                          const std::string& path, const UnitSystem& units) {
  reader.RequireSequence(list, path);
  if (list.size() == 0) reader.Fail(list, path, "the list is empty; give at least one component");
  std::vector<Component> components;
  // Names seen so far with their index: linear in the component count (a pairwise check took
  // minutes for 10^5 components).
  std::unordered_map<std::string, std::size_t> names;
  for (std::size_t i = 0; i < list.size(); ++i) {
    components.push_back(ReadComponent(reader, list[i], IndexPath(path, i), i, units));
    const auto [earlier, added] = names.emplace(components.back().name, i);
    if (!added) {
      reader.Fail(list[i], IndexPath(path, i),
                  fmt::format("name '{}' is already used by component {}", earlier->first,
                              earlier->second));
    }
  }
  return hysteresis::ParallelAssembly(std::move(components));
}

}  // namespace isolab::model
