#include "isolab/hysteresis/law_parameters.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "bearing_parameters.h"
#include "isolab/core/errors.h"
#include "multiple_pendulum_parameters.h"
#include "rule_checker.h"

namespace isolab::hysteresis {
namespace {

constexpr std::string_view kSpringKeys[] = {"k"};
constexpr std::string_view kDashpotKeys[] = {"c"};
constexpr std::string_view kBilinearMath[] = {"k0", "k1", "uy"};
constexpr std::string_view kBilinearMech[] = {"ke", "kh", "fs"};
constexpr std::string_view kTrilinearMath[] = {"k0", "k1", "k2", "uy", "uyh"};
constexpr std::string_view kTrilinearMech[] = {"ke", "kh1", "kh2", "fs", "uc"};
constexpr std::string_view kElasticMath[] = {"k1", "k2", "uyh"};
constexpr std::string_view kElasticMech[] = {"kh1", "kh2", "uc"};
constexpr std::string_view kElastoplasticMath[] = {"k0", "uy"};
constexpr std::string_view kElastoplasticMech[] = {"ke", "fs"};
constexpr std::string_view kBoucWenKeys[] = {"alpha", "beta", "gamma", "delta", "nu"};
constexpr std::string_view kDegradingMath[] = {"k0", "k1", "uy", "loss", "slip_scale"};
constexpr std::string_view kDegradingMech[] = {"ke", "kh", "fs", "loss", "slip_scale"};
constexpr std::string_view kAsymmetricMath[] = {"k0", "uy_pos", "uy_neg"};
constexpr std::string_view kAsymmetricMech[] = {"ke", "fs_pos", "fs_neg"};
constexpr std::string_view kBacklashMath[] = {"k0", "uy", "gap"};
constexpr std::string_view kBacklashMech[] = {"ke", "fs", "gap"};

constexpr LawType kAllTypes[] = {
    LawType::kLinearSpring,
    LawType::kDashpot,
    LawType::kBhm1,
    LawType::kBhm2,
    LawType::kThm1,
    LawType::kThm2,
    LawType::kTrilinearElastic,
    LawType::kElastoplastic,
    LawType::kBoucWen,
    LawType::kDegradingBhm2,
    LawType::kFrictionPendulum,
    LawType::kLeadRubber,
    LawType::kHdrBearing,
    LawType::kDoubleFrictionPendulum,
    LawType::kTripleFrictionPendulum,
    LawType::kAsymmetricElastoplastic,
    LawType::kBacklashElastoplastic,
};

// The breakpoint that may be omitted when the two slopes around it are equal (it then marks no
// change of slope): uyh between k1 and k2, or uc between kh1 and kh2.
struct OptionalBreakpoint {
  std::string_view key, slope1, slope2;
};

std::optional<OptionalBreakpoint> Breakpoint(LawType type, ParameterForm form) {
  if (type != LawType::kThm1 && type != LawType::kThm2 && type != LawType::kTrilinearElastic) {
    return std::nullopt;
  }
  if (form == ParameterForm::kMathematical) return OptionalBreakpoint{"uyh", "k1", "k2"};
  return OptionalBreakpoint{"uc", "kh1", "kh2"};
}

// Every value present and finite, but for an optional breakpoint between equal slopes.
void CheckPresentAndFinite(LawType type, ParameterForm form, const ParameterArray& values) {
  const Keys keys = ParameterKeys(type, form);
  const RuleChecker r(keys, values);
  const auto breakpoint = Breakpoint(type, form);
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (std::isnan(values[i])) {
      if (BearingKeyMayBeOmitted(type, keys[i])) continue;  // ValidateBearing checks it
      if (!breakpoint || keys[i] != breakpoint->key) {
        throw InvalidParameter({std::string(keys[i]), NAN, "is required"});
      }
      if (r(breakpoint->slope1) != r(breakpoint->slope2)) {
        throw InvalidParameter(
            {std::string(keys[i]), NAN,
             fmt::format("is required when {} != {}", breakpoint->slope1, breakpoint->slope2)});
      }
    } else if (!std::isfinite(values[i])) {
      throw InvalidParameter({std::string(keys[i]), values[i], "must be finite"});
    }
  }
}

// The damage of the degrading laws, the same keys in both forms.
void CheckDamage(const RuleChecker& r) {
  r.AtLeast("loss", 0.0);
  r.Less("loss", 1.0);
  r.Greater("slip_scale", 0.0);
}

void ValidateMathematical(LawType type, const ParameterArray& v) {
  const RuleChecker r(ParameterKeys(type, ParameterForm::kMathematical), v);
  switch (type) {
    case LawType::kLinearSpring:
      r.AtLeast("k", 0.0);
      return;
    case LawType::kDashpot:
      r.AtLeast("c", 0.0);
      return;
    case LawType::kBhm1:
    case LawType::kBhm2:
      r.Greater("k0", 0.0);
      r.Less("k1", r("k0"), "k0");
      r.AtLeast("uy", 0.0);
      return;
    case LawType::kThm1:
      r.Greater("k0", 0.0);
      r.Less("k1", r("k0"), "k0");
      r.Less("k2", r("k0"), "k0");
      r.AtLeast("uy", 0.0);
      if (!std::isnan(r("uyh"))) r.Greater("uyh", r("uy"), "uy");
      return;
    case LawType::kThm2:
      r.Greater("k0", 0.0);
      r.Less("k1", r("k0"), "k0");
      r.AtLeast("uy", 0.0);
      if (!std::isnan(r("uyh"))) r.Greater("uyh", 0.0);
      return;
    case LawType::kTrilinearElastic:
      r.AtLeast("k1", 0.0);
      if (!std::isnan(r("uyh"))) r.Greater("uyh", 0.0);
      return;
    case LawType::kElastoplastic:
      r.Greater("k0", 0.0);
      r.Greater("uy", 0.0);
      return;
    case LawType::kBoucWen:
      r.Greater("alpha", 0.0);
      r.AtLeast("beta", 0.0);
      r.AtLeast("nu", 1.0);
      return;
    case LawType::kDegradingBhm2:
      r.Greater("k0", 0.0);
      r.Less("k1", r("k0"), "k0");
      r.Greater("uy", 0.0);
      CheckDamage(r);
      return;
    case LawType::kFrictionPendulum:
    case LawType::kLeadRubber:
    case LawType::kHdrBearing:
      ValidateBearing(type, ParameterForm::kMathematical, v);
      return;
    case LawType::kDoubleFrictionPendulum:
    case LawType::kTripleFrictionPendulum:
      ValidateMultiplePendulum(type, v);
      return;
    case LawType::kAsymmetricElastoplastic:
      r.Greater("k0", 0.0);
      r.Greater("uy_pos", 0.0);
      r.Greater("uy_neg", 0.0);
      return;
    case LawType::kBacklashElastoplastic:
      r.Greater("k0", 0.0);
      r.Greater("uy", 0.0);
      r.AtLeast("gap", 0.0);
      return;
  }
}

void ValidateMechanical(LawType type, const ParameterArray& v) {
  const RuleChecker r(ParameterKeys(type, ParameterForm::kMechanical), v);
  switch (type) {
    case LawType::kLinearSpring:
    case LawType::kDashpot:
    case LawType::kBoucWen:
      ValidateMathematical(type, v);  // the same names in both forms
      return;
    case LawType::kTrilinearElastic:
      r.AtLeast("kh1", 0.0);
      if (!std::isnan(r("uc"))) r.Greater("uc", 0.0);
      return;
    case LawType::kBhm1:
      r.Greater("ke", 0.0);
      r.Holds("kh", r("ke") + r("kh") > 0.0,
              fmt::format("ke + kh must be > 0, is {:g}", r("ke") + r("kh")));
      r.AtLeast("fs", 0.0);
      return;
    case LawType::kBhm2:
      r.Greater("ke", 0.0);
      r.Less("kh", r("ke"), "ke");
      r.AtLeast("fs", 0.0);
      return;
    case LawType::kThm1:
      r.Greater("ke", 0.0);
      r.Holds("kh1", r("ke") + r("kh1") > 0.0,
              fmt::format("ke + kh1 must be > 0, is {:g}", r("ke") + r("kh1")));
      r.Holds("kh2", r("ke") + r("kh2") > 0.0,
              fmt::format("ke + kh2 must be > 0, is {:g}", r("ke") + r("kh2")));
      r.AtLeast("fs", 0.0);
      if (!std::isnan(r("uc"))) r.Greater("uc", 0.0);
      return;
    case LawType::kThm2:
      r.Greater("ke", 0.0);
      r.Less("kh1", r("ke"), "ke");
      r.AtLeast("fs", 0.0);
      if (!std::isnan(r("uc"))) r.Greater("uc", 0.0);
      return;
    case LawType::kElastoplastic:
      r.Greater("ke", 0.0);
      r.Greater("fs", 0.0);
      return;
    case LawType::kDegradingBhm2:
      r.Greater("ke", 0.0);
      r.Less("kh", r("ke"), "ke");
      r.Greater("fs", 0.0);
      CheckDamage(r);
      return;
    case LawType::kFrictionPendulum:
    case LawType::kLeadRubber:
    case LawType::kHdrBearing:
      ValidateBearing(type, ParameterForm::kMechanical, v);
      return;
    case LawType::kDoubleFrictionPendulum:
    case LawType::kTripleFrictionPendulum:
      ValidateMultiplePendulum(type, v);  // the same keys in both forms
      return;
    case LawType::kAsymmetricElastoplastic:
      r.Greater("ke", 0.0);
      r.Greater("fs_pos", 0.0);
      r.Greater("fs_neg", 0.0);
      return;
    case LawType::kBacklashElastoplastic:
      r.Greater("ke", 0.0);
      r.Greater("fs", 0.0);
      r.AtLeast("gap", 0.0);
      return;
  }
}

// Table 1 of the paper, mathematical -> mechanical.
ParameterArray MechanicalFromMathematical(LawType type, const ParameterArray& m) {
  switch (type) {
    case LawType::kBhm1:  // k0, k1, uy -> ke, kh, fs
      return {m[0], m[0] * m[1] / (m[0] - m[1]), m[0] * m[2], NAN, NAN};
    case LawType::kBhm2:
      return {m[0], m[1], (m[0] - m[1]) * m[2], NAN, NAN};
    case LawType::kDegradingBhm2:
      return {m[0], m[1], (m[0] - m[1]) * m[2], m[3], m[4]};
    case LawType::kThm1: {  // k0, k1, k2, uy, uyh -> ke, kh1, kh2, fs, uc
      const double k0 = m[0], k1 = m[1], k2 = m[2], uy = m[3], uyh = m[4];
      return {k0, k0 * k1 / (k0 - k1), k0 * k2 / (k0 - k2), k0 * uy, (uyh - uy) * (k0 - k1) / k0};
    }
    case LawType::kThm2:
      return {m[0], m[1], m[2], (m[0] - m[1]) * m[3], m[4]};
    case LawType::kElastoplastic:
      return {m[0], m[0] * m[1], NAN, NAN, NAN};
    case LawType::kAsymmetricElastoplastic:  // k0, uy_pos, uy_neg -> ke, fs_pos, fs_neg
      return {m[0], m[0] * m[1], m[0] * m[2], NAN, NAN};
    case LawType::kBacklashElastoplastic:  // k0, uy, gap -> ke, fs, gap
      return {m[0], m[0] * m[1], m[2], NAN, NAN};
    case LawType::kLinearSpring:
    case LawType::kDashpot:
    case LawType::kTrilinearElastic:
    case LawType::kBoucWen:
      return m;
    case LawType::kFrictionPendulum:
    case LawType::kLeadRubber:
    case LawType::kHdrBearing:
      return ConvertBearing(type, ParameterForm::kMechanical, m);
    case LawType::kDoubleFrictionPendulum:
    case LawType::kTripleFrictionPendulum:
      return m;  // the same keys in both forms
  }
  return m;
}

// Table 1 of the paper, mechanical -> mathematical.
ParameterArray MathematicalFromMechanical(LawType type, const ParameterArray& q) {
  switch (type) {
    case LawType::kBhm1:  // ke, kh, fs -> k0, k1, uy
      return {q[0], q[0] * q[1] / (q[0] + q[1]), q[2] / q[0], NAN, NAN};
    case LawType::kBhm2:
      return {q[0], q[1], q[2] / (q[0] - q[1]), NAN, NAN};
    case LawType::kDegradingBhm2:
      return {q[0], q[1], q[2] / (q[0] - q[1]), q[3], q[4]};
    case LawType::kThm1: {  // ke, kh1, kh2, fs, uc -> k0, k1, k2, uy, uyh
      const double ke = q[0], kh1 = q[1], kh2 = q[2], fs = q[3], uc = q[4];
      const double uy = fs / ke;
      return {ke, ke * kh1 / (ke + kh1), ke * kh2 / (ke + kh2), uy, uy + uc * (ke + kh1) / ke};
    }
    case LawType::kThm2:
      return {q[0], q[1], q[2], q[3] / (q[0] - q[1]), q[4]};
    case LawType::kElastoplastic:
      return {q[0], q[1] / q[0], NAN, NAN, NAN};
    case LawType::kAsymmetricElastoplastic:
      return {q[0], q[1] / q[0], q[2] / q[0], NAN, NAN};
    case LawType::kBacklashElastoplastic:
      return {q[0], q[1] / q[0], q[2], NAN, NAN};
    case LawType::kLinearSpring:
    case LawType::kDashpot:
    case LawType::kTrilinearElastic:
    case LawType::kBoucWen:
      return q;
    case LawType::kFrictionPendulum:
    case LawType::kLeadRubber:
    case LawType::kHdrBearing:
      return ConvertBearing(type, ParameterForm::kMathematical, q);
    case LawType::kDoubleFrictionPendulum:
    case LawType::kTripleFrictionPendulum:
      return q;  // the same keys in both forms
  }
  return q;
}

double BreakpointOrInfinity(double uc) { return std::isnan(uc) ? INFINITY : uc; }

}  // namespace

std::string_view LawName(LawType type) {
  switch (type) {
    case LawType::kLinearSpring:
      return "linear_spring";
    case LawType::kDashpot:
      return "dashpot";
    case LawType::kBhm1:
      return "bhm1";
    case LawType::kBhm2:
      return "bhm2";
    case LawType::kThm1:
      return "thm1";
    case LawType::kThm2:
      return "thm2";
    case LawType::kTrilinearElastic:
      return "trilinear_elastic";
    case LawType::kElastoplastic:
      return "elastoplastic";
    case LawType::kBoucWen:
      return "bouc_wen";
    case LawType::kDegradingBhm2:
      return "degrading_bhm2";
    case LawType::kFrictionPendulum:
      return "friction_pendulum";
    case LawType::kLeadRubber:
      return "lead_rubber";
    case LawType::kHdrBearing:
      return "hdr_bearing";
    case LawType::kDoubleFrictionPendulum:
      return "double_friction_pendulum";
    case LawType::kTripleFrictionPendulum:
      return "triple_friction_pendulum";
    case LawType::kAsymmetricElastoplastic:
      return "asymmetric_elastoplastic";
    case LawType::kBacklashElastoplastic:
      return "backlash_elastoplastic";
  }
  return "unknown";
}

std::optional<LawType> LawTypeFromName(std::string_view name) {
  for (const LawType type : kAllTypes) {
    if (LawName(type) == name) return type;
  }
  return std::nullopt;
}

std::span<const LawType> AllLawTypes() { return kAllTypes; }

std::span<const std::string_view> ParameterKeys(LawType type, ParameterForm form) {
  const bool math = form == ParameterForm::kMathematical;
  switch (type) {
    case LawType::kLinearSpring:
      return kSpringKeys;
    case LawType::kDashpot:
      return kDashpotKeys;
    case LawType::kBhm1:
    case LawType::kBhm2:
      return math ? Keys(kBilinearMath) : Keys(kBilinearMech);
    case LawType::kThm1:
    case LawType::kThm2:
      return math ? Keys(kTrilinearMath) : Keys(kTrilinearMech);
    case LawType::kTrilinearElastic:
      return math ? Keys(kElasticMath) : Keys(kElasticMech);
    case LawType::kElastoplastic:
      return math ? Keys(kElastoplasticMath) : Keys(kElastoplasticMech);
    case LawType::kBoucWen:
      return kBoucWenKeys;
    case LawType::kDegradingBhm2:
      return math ? Keys(kDegradingMath) : Keys(kDegradingMech);
    case LawType::kFrictionPendulum:
    case LawType::kLeadRubber:
    case LawType::kHdrBearing:
      return BearingKeys(type, form);
    case LawType::kDoubleFrictionPendulum:
    case LawType::kTripleFrictionPendulum:
      return MultiplePendulumKeys(type);
    case LawType::kAsymmetricElastoplastic:
      return math ? Keys(kAsymmetricMath) : Keys(kAsymmetricMech);
    case LawType::kBacklashElastoplastic:
      return math ? Keys(kBacklashMath) : Keys(kBacklashMech);
  }
  return {};
}

bool IsOptionalKey(LawType type, std::string_view key) {
  if (BearingKeyMayBeOmitted(type, key)) return true;
  for (const ParameterForm form : {ParameterForm::kMathematical, ParameterForm::kMechanical}) {
    const auto breakpoint = Breakpoint(type, form);
    if (breakpoint && breakpoint->key == key) return true;
  }
  return false;
}

LawParameters LawParameters::Make(LawType type, ParameterForm form,
                                  std::span<const double> values) {
  ParameterArray given;
  given.fill(NAN);
  std::copy_n(values.begin(), std::min(values.size(), given.size()), given.begin());
  CheckPresentAndFinite(type, form, given);
  if (form == ParameterForm::kMathematical) {
    ValidateMathematical(type, given);
    return LawParameters(type, given, MechanicalFromMathematical(type, given));
  }
  ValidateMechanical(type, given);
  return LawParameters(type, MathematicalFromMechanical(type, given), given);
}

LawParameters::LawParameters(LawType type, std::array<double, kMaxLawParameters> mathematical,
                             std::array<double, kMaxLawParameters> mechanical)
    : type_(type), mathematical_(mathematical), mechanical_(mechanical) {}

std::vector<double> LawParameters::Values(ParameterForm form) const {
  const std::size_t count = ParameterKeys(type_, form).size();
  const auto& values = form == ParameterForm::kMathematical ? mathematical_ : mechanical_;
  return std::vector<double>(values.begin(), values.begin() + count);
}

LawKernel LawParameters::Kernel() const {
  const auto& q = mechanical_;
  switch (type_) {
    case LawType::kLinearSpring:
      return ElasticSpring{{q[0], q[0], INFINITY}};
    case LawType::kDashpot:
      return Dashpot{q[0]};
    case LawType::kBhm1:
      return SeriesSlider{q[0], q[2], {q[1], q[1], INFINITY}};
    case LawType::kBhm2:
      return ParallelSlider{q[0] - q[1], q[2], {q[1], q[1], INFINITY}};
    case LawType::kThm1:
      return SeriesSlider{q[0], q[3], {q[1], q[2], BreakpointOrInfinity(q[4])}};
    case LawType::kThm2:
      return ParallelSlider{q[0] - q[1], q[3], {q[1], q[2], BreakpointOrInfinity(q[4])}};
    case LawType::kTrilinearElastic:
      return ElasticSpring{{q[0], q[1], BreakpointOrInfinity(q[2])}};
    case LawType::kElastoplastic:
      return SeriesSlider{q[0], q[1], {0.0, 0.0, INFINITY}};
    case LawType::kBoucWen:
      return BoucWen{q[0], q[1], q[2], q[3], q[4]};
    case LawType::kDegradingBhm2:
      return DegradingSlider{q[0] - q[1], q[2], q[1], q[3], q[4]};
    case LawType::kFrictionPendulum:
    case LawType::kLeadRubber:
    case LawType::kHdrBearing:
      return BearingKernel(type_, q);
    case LawType::kDoubleFrictionPendulum:
    case LawType::kTripleFrictionPendulum:
      return MultiplePendulumKernel(type_, q);
    case LawType::kAsymmetricElastoplastic:
      return PlaySlider{q[0], q[1], q[2], 0.0};
    case LawType::kBacklashElastoplastic:
      return PlaySlider{q[0], q[1], q[1], q[2]};
  }
  return Dashpot{0.0};
}

std::optional<double> PendulumWeight(const LawParameters& law) {
  switch (law.type()) {
    case LawType::kFrictionPendulum:
    case LawType::kDoubleFrictionPendulum:
    case LawType::kTripleFrictionPendulum:
      break;
    default:
      return std::nullopt;
  }
  const auto keys = ParameterKeys(law.type(), ParameterForm::kMechanical);
  const std::vector<double> values = law.Values(ParameterForm::kMechanical);
  for (std::size_t k = 0; k < keys.size(); ++k) {
    if (keys[k] == "w") return values[k];
  }
  return std::nullopt;
}

}  // namespace isolab::hysteresis
