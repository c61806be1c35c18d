#include "bearing_parameters.h"

#include <cmath>
#include <numbers>

#include "isolab/hysteresis/hdr_bearing.h"

namespace isolab::hysteresis {
namespace {

constexpr std::string_view kPendulumKeys[] = {"w", "r", "uy", "mu", "mu_slow", "mu_fast", "a"};
// Mechanical: the engineer's Qd, Kd, Ku; mathematical: Qd, Kd and the yield displacement Dy.
constexpr std::string_view kLeadRubberMech[] = {"qd",
                                                "kd",
                                                "ku",
                                                "lead_diameter",
                                                "lead_height",
                                                "lead_heat_capacity",
                                                "steel_conductivity",
                                                "steel_diffusivity",
                                                "shim_thickness",
                                                "e2"};
constexpr std::string_view kLeadRubberMath[] = {"qd",
                                                "kd",
                                                "dy",
                                                "lead_diameter",
                                                "lead_height",
                                                "lead_heat_capacity",
                                                "steel_conductivity",
                                                "steel_diffusivity",
                                                "shim_thickness",
                                                "e2"};
constexpr std::string_view kHdrKeys[] = {"g", "area", "tr", "damping", "strain", "yield_strain"};

constexpr std::string_view kFrictionAlternatives[] = {"mu_slow", "mu_fast", "a"};
constexpr std::string_view kHeatingKeys[] = {"lead_height", "lead_heat_capacity", "e2"};
constexpr std::string_view kConductivityKey[] = {"steel_conductivity"};
constexpr std::string_view kConductionKeys[] = {"steel_diffusivity", "shim_thickness"};

constexpr double kDefaultE2 = 0.0069;        // 1/degC, Kalpakidis & Constantinou (2009)
constexpr double kDefaultYieldStrain = 0.1;  // hdr_bearing.h

bool Given(double value) { return !std::isnan(value); }

// A key that belongs to a group switched on by `leader` was given without it.
void RequireLeader(const RuleChecker& r, std::span<const std::string_view> members,
                   std::string_view leader, std::string_view what) {
  for (const std::string_view key : members) {
    if (Given(r(key)) && !Given(r(leader))) {
      r.Holds(key, false, fmt::format("is given, so {} is required ({})", leader, what));
    }
  }
}

void Require(const RuleChecker& r, std::string_view key, std::string_view why) {
  if (!Given(r(key))) {
    throw InvalidParameter({std::string(key), NAN, fmt::format("is required {}", why)});
  }
}

void ValidatePendulum(const RuleChecker& r) {
  r.Greater("w", 0.0);
  r.Greater("r", 0.0);
  r.Greater("uy", 0.0);
  if (Given(r("mu"))) {
    for (const std::string_view key : kFrictionAlternatives) {
      if (Given(r(key))) {
        r.Holds(key, false, "cannot be given with mu (give mu, or mu_slow, mu_fast and a)");
      }
    }
    r.AtLeast("mu", 0.0);
    return;
  }
  if (!Given(r("mu_slow")) && !Given(r("mu_fast")) && !Given(r("a"))) {
    throw InvalidParameter({"mu", NAN, "is required (or mu_slow, mu_fast and a)"});
  }
  for (const std::string_view key : kFrictionAlternatives) {
    Require(r, key, "with velocity-dependent friction (mu_slow, mu_fast, a)");
  }
  r.AtLeast("mu_slow", 0.0);
  r.AtLeast("mu_fast", r("mu_slow"), "mu_slow");
  r.AtLeast("a", 0.0);
}

void ValidateLeadRubber(const RuleChecker& r, ParameterForm form) {
  r.Greater("qd", 0.0);
  r.AtLeast("kd", 0.0);
  if (form == ParameterForm::kMechanical) {
    r.Greater("ku", r("kd"), "kd");
  } else {
    r.Greater("dy", 0.0);
  }
  RequireLeader(r, kHeatingKeys, "lead_diameter", "the heating of the lead core");
  RequireLeader(r, kConductivityKey, "lead_diameter", "the heating of the lead core");
  RequireLeader(r, kConductionKeys, "steel_conductivity", "conduction out of the lead core");
  if (!Given(r("lead_diameter"))) return;
  r.Greater("lead_diameter", 0.0);
  Require(r, "lead_height", "when lead_diameter is given (the heating of the lead core)");
  r.Greater("lead_height", 0.0);
  Require(r, "lead_heat_capacity", "when lead_diameter is given (the heating of the lead core)");
  r.Greater("lead_heat_capacity", 0.0);
  if (Given(r("e2"))) r.Greater("e2", 0.0);
  if (!Given(r("steel_conductivity"))) return;
  r.AtLeast("steel_conductivity", 0.0);
  Require(r, "steel_diffusivity", "when steel_conductivity is given");
  r.Greater("steel_diffusivity", 0.0);
  Require(r, "shim_thickness", "when steel_conductivity is given");
  r.AtLeast("shim_thickness", 0.0);
}

HdrDesign Design(const ParameterArray& v) {
  HdrDesign design;
  design.shear_modulus = v[0];
  design.bonded_area = v[1];
  design.rubber_thickness = v[2];
  design.damping = v[3];
  design.strain = v[4];
  design.yield_strain = Given(v[5]) ? v[5] : kDefaultYieldStrain;
  return design;
}

void ValidateHdr(const RuleChecker& r, const ParameterArray& v) {
  r.Greater("g", 0.0);
  r.Greater("area", 0.0);
  r.Greater("tr", 0.0);
  r.Greater("strain", 0.0);
  const HdrDesign design = Design(v);
  if (Given(r("yield_strain"))) {
    r.Greater("yield_strain", 0.0);
    r.Less("yield_strain", r("strain"), "strain");
  } else if (!(design.yield_strain < design.strain)) {
    r.Holds("strain", false,
            fmt::format("must be > the default yield_strain {:g}, or give yield_strain",
                        kDefaultYieldStrain));
  }
  r.Greater("damping", 0.0);
  r.Holds("damping", r("damping") <= design.MaxDamping(),
          fmt::format("must be <= 2 (1 - yield_strain/strain) / pi = {:.4g}: more needs a "
                      "negative post-yield stiffness",
                      design.MaxDamping()));
}

}  // namespace

bool IsBearingPreset(LawType type) {
  return type == LawType::kFrictionPendulum || type == LawType::kLeadRubber ||
         type == LawType::kHdrBearing;
}

Keys BearingKeys(LawType type, ParameterForm form) {
  switch (type) {
    case LawType::kFrictionPendulum:
      return kPendulumKeys;
    case LawType::kLeadRubber:
      return form == ParameterForm::kMechanical ? Keys(kLeadRubberMech) : Keys(kLeadRubberMath);
    case LawType::kHdrBearing:
      return kHdrKeys;
    default:
      return {};
  }
}

bool BearingKeyMayBeOmitted(LawType type, std::string_view key) {
  switch (type) {
    case LawType::kFrictionPendulum:
      return key == "mu" || key == "mu_slow" || key == "mu_fast" || key == "a";
    case LawType::kLeadRubber:
      return key != "qd" && key != "kd" && key != "ku" && key != "dy";
    case LawType::kHdrBearing:
      return key == "yield_strain";
    default:
      return false;
  }
}

void ValidateBearing(LawType type, ParameterForm form, const ParameterArray& values) {
  const RuleChecker r(BearingKeys(type, form), values);
  switch (type) {
    case LawType::kFrictionPendulum:
      ValidatePendulum(r);
      return;
    case LawType::kLeadRubber:
      ValidateLeadRubber(r, form);
      return;
    case LawType::kHdrBearing:
      ValidateHdr(r, values);
      return;
    default:
      return;
  }
}

ParameterArray ConvertBearing(LawType type, ParameterForm to, const ParameterArray& values) {
  ParameterArray converted = values;
  if (type == LawType::kLeadRubber) {  // Ku = Kd + Qd / Dy, Dy = Qd / (Ku - Kd)
    const double qd = values[0], kd = values[1];
    converted[2] = to == ParameterForm::kMechanical ? kd + qd / values[2] : qd / (values[2] - kd);
  }
  return converted;
}

LawKernel BearingKernel(LawType type, const ParameterArray& q) {
  if (type == LawType::kFrictionPendulum) {
    const double w = q[0], r = q[1], uy = q[2];
    const bool constant = Given(q[3]);
    return FrictionPendulum{w,
                            w / r,
                            constant ? q[3] : q[4],
                            constant ? q[3] : q[5],
                            constant ? 0.0 : q[6],
                            UnitSlider{uy}};
  }
  if (type == LawType::kLeadRubber) {
    const double qd = q[0], kd = q[1], ku = q[2];
    LeadRubber law{kd, qd, UnitSlider{qd / (ku - kd)}, {}};
    if (Given(q[3])) {
      const double a = 0.5 * q[3], height = q[4], rho_c = q[5];
      LeadCoreHeating& heating = law.heating;
      heating.capacity = rho_c * std::numbers::pi * a * a * height;
      heating.e2 = Given(q[9]) ? q[9] : kDefaultE2;
      if (Given(q[6])) {
        heating.conduction = q[6] / (a * rho_c * height);
        heating.shim_ratio = 1.274 * q[8] / a;
        heating.diffusion = q[7] / (a * a);
      }
    }
    return law;
  }
  const Bhm2Mechanical bhm2 = EquivalentBhm2(Design(q));
  return ParallelSlider{bhm2.ke - bhm2.kh, bhm2.fs, {bhm2.kh, bhm2.kh, INFINITY}};
}

}  // namespace isolab::hysteresis
