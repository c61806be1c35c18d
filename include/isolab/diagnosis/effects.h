// The catalogue of physical effects a bilinear or trilinear isolator model can lack, each with
// the component that carries it when added in parallel and a plain-language explanation. The
// first four are odd-symmetric, as every law before the play sliders is; asymmetric strength and
// backlash are what real friction devices add (play_slider.h).
#pragma once

#include <span>
#include <string_view>

#include "isolab/identification/parametrisation.h"

namespace isolab::diagnosis {

enum class Effect {
  kRateDependence,                 // force grows with velocity: a viscous dashpot
  kAmplitudeDependentDissipation,  // loop area grows faster than linearly: a softening THM1
  kLargeAmplitudeHardening,        // stiffening at large strain: a trilinear hardening spring
  kCyclicDegradation,              // loops shrink cycle after cycle: a degrading BHM2
  kAsymmetricStrength,  // strength differs by direction (an offset): asymmetric_elastoplastic
  kBacklash,            // a clearance after every reversal: backlash_elastoplastic
};

std::span<const Effect> AllEffects();

// "rate_dependence", ... as reports and the command line write them.
std::string_view EffectName(Effect effect);

// What the effect is and what the added component represents, for a reader of the report.
std::string_view EffectExplanation(Effect effect);

// The component added in parallel to carry the effect (its parameters free, to be fitted).
identification::ComponentSpec EffectComponent(Effect effect);

}  // namespace isolab::diagnosis
