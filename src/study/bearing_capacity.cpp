#include "isolab/study/bearing_capacity.h"

#include <fmt/format.h>

#include <algorithm>
#include <string_view>

namespace isolab::study {
namespace {

using hysteresis::LawType;
using hysteresis::ParameterForm;

// The multiple pendulums and the HDR bearing take the same keys in both forms.
double KeyValue(const hysteresis::LawParameters& law, std::string_view key) {
  const auto keys = hysteresis::ParameterKeys(law.type(), ParameterForm::kMechanical);
  const auto at = std::find(keys.begin(), keys.end(), key);
  return law.Values(ParameterForm::kMechanical)[static_cast<std::size_t>(at - keys.begin())];
}

std::optional<BearingCapacity> OfLaw(const std::string& name, const hysteresis::LawParameters& law,
                                     double shear_strain_limit) {
  switch (law.type()) {
    case LawType::kDoubleFrictionPendulum:
      return BearingCapacity{KeyValue(law, "d1") + KeyValue(law, "d2"),
                             fmt::format("d1 + d2 of {}", name)};
    case LawType::kTripleFrictionPendulum:
      return BearingCapacity{
          KeyValue(law, "d1") + KeyValue(law, "d2") + KeyValue(law, "d3") + KeyValue(law, "d4"),
          fmt::format("d1 + d2 + d3 + d4 of {}", name)};
    case LawType::kHdrBearing:
      if (!(shear_strain_limit > 0.0)) return std::nullopt;
      return BearingCapacity{
          KeyValue(law, "tr") * shear_strain_limit,
          fmt::format("tr x shear_strain_limit {:g} of {}", shear_strain_limit, name)};
    default:
      return std::nullopt;
  }
}

// The least capacity among an isolator's components.
template <class Components, class Law>
std::optional<BearingCapacity> Least(const Components& components, Law law,
                                     double shear_strain_limit) {
  std::optional<BearingCapacity> least;
  for (const auto& component : components) {
    const std::optional<BearingCapacity> c =
        OfLaw(component.name, law(component), shear_strain_limit);
    if (c && (!least || c->displacement < least->displacement)) least = c;
  }
  return least;
}

}  // namespace

std::optional<BearingCapacity> DisplacementCapacity(const hysteresis::ParallelAssembly& laws,
                                                    double shear_strain_limit) {
  return Least(
      laws.components(),
      [](const hysteresis::Component& c) -> const hysteresis::LawParameters& {
        return c.parameters;
      },
      shear_strain_limit);
}

std::optional<BearingCapacity> DisplacementCapacity(const hysteresis::PlanAssembly& laws,
                                                    double shear_strain_limit) {
  return Least(
      laws.components(),
      [](const hysteresis::PlanComponent& c) -> const hysteresis::LawParameters& { return c.law; },
      shear_strain_limit);
}

}  // namespace isolab::study
