#include "isolab/diagnosis/effects.h"

namespace isolab::diagnosis {
namespace {

constexpr Effect kAllEffects[] = {
    Effect::kRateDependence,          Effect::kAmplitudeDependentDissipation,
    Effect::kLargeAmplitudeHardening, Effect::kCyclicDegradation,
    Effect::kAsymmetricStrength,      Effect::kBacklash,
};

}  // namespace

std::span<const Effect> AllEffects() { return kAllEffects; }

std::string_view EffectName(Effect effect) {
  switch (effect) {
    case Effect::kRateDependence:
      return "rate_dependence";
    case Effect::kAmplitudeDependentDissipation:
      return "amplitude_dependent_dissipation";
    case Effect::kLargeAmplitudeHardening:
      return "large_amplitude_hardening";
    case Effect::kCyclicDegradation:
      return "cyclic_degradation";
    case Effect::kAsymmetricStrength:
      return "asymmetric_strength";
    case Effect::kBacklash:
      return "backlash";
  }
  return "unknown";
}

std::string_view EffectExplanation(Effect effect) {
  switch (effect) {
    case Effect::kRateDependence:
      return "The force depends on how fast the bearing moves, not only on how far: the residual "
             "follows the velocity, and loops at the same amplitude are fatter at higher test "
             "frequency. Rubber compounds and viscous devices do this. A linear viscous dashpot "
             "in parallel carries it.";
    case Effect::kAmplitudeDependentDissipation:
      return "The energy dissipated per cycle grows with amplitude faster than the model lets it: "
             "more of the material yields as the strain grows (a second, later-yielding "
             "mechanism, as in high-damping rubber). A THM1 element that yields at a larger "
             "displacement and softens carries it.";
    case Effect::kLargeAmplitudeHardening:
      return "The bearing stiffens at large displacement (strain-induced crystallisation of "
             "rubber, or a sliding bearing reaching its restrainer): the secant stiffness at the "
             "peaks rises with amplitude and the residual gathers at large displacement on the "
             "loading branches. A trilinear elastic spring whose stiffness rises beyond a "
             "characteristic displacement carries it.";
    case Effect::kCyclicDegradation:
      return "Loops shrink from one cycle to the next at the same amplitude: strength and "
             "stiffness fall with the slip accumulated (scragging / Mullins softening of filled "
             "rubber, heating of a lead core). A BHM2 element whose force falls with its "
             "accumulated slip (degrading_bhm2) carries it.";
    case Effect::kAsymmetricStrength:
      return "The device is stronger one way than the other: its friction or yield force differs "
             "between the directions of motion, so the force is offset by a constant while it "
             "slips (a friction damper whose pads bear unevenly, a sliding bearing on a slope). "
             "Every other law in the catalogue is odd-symmetric and cannot carry it. An "
             "elastoplastic element whose strength differs by direction "
             "(asymmetric_elastoplastic) carries it.";
    case Effect::kBacklash:
      return "The device has play: after every reversal its force falls to near zero while the "
             "displacement crosses a clearance, then it engages again and stiffens. The tangent "
             "stiffness after a reversal first drops and then rises, which no law in the rest of "
             "the catalogue does before the loop's centre. An elastoplastic element engaged "
             "through a clearance (backlash_elastoplastic) carries it.";
  }
  return "";
}

identification::ComponentSpec EffectComponent(Effect effect) {
  using hysteresis::LawType;
  switch (effect) {
    case Effect::kRateDependence:
      return {"viscous", LawType::kDashpot, {}, {}, {}};
    case Effect::kAmplitudeDependentDissipation:
      // Softening (k2 <= 0 <= k1), as Table 9's components 4-7 that carry the growth of loop
      // area: a THM1 free to harden would also mimic the trilinear hardening spring.
      return {"late_yield", LawType::kThm1, {{"k2_ratio", {-3.0, 0.0, false}}}, {}, {}};
    case Effect::kLargeAmplitudeHardening:
      return {"hardening", LawType::kTrilinearElastic, {}, {}, {}};
    case Effect::kCyclicDegradation:
      return {"degrading", LawType::kDegradingBhm2, {}, {}, {}};
    case Effect::kAsymmetricStrength:
      return {"asymmetric", LawType::kAsymmetricElastoplastic, {}, {}, {}};
    case Effect::kBacklash:
      return {"play", LawType::kBacklashElastoplastic, {}, {}, {}};
  }
  return {};
}

}  // namespace isolab::diagnosis
