#include "isolab/hysteresis/hdr_bearing.h"

#include <numbers>

namespace isolab::hysteresis {

double HdrDesign::MaxDamping() const {
  return 2.0 * (1.0 - yield_strain / strain) / std::numbers::pi;
}

Bhm2Mechanical EquivalentBhm2(const HdrDesign& design) {
  const double k_eff = design.EffectiveStiffness();
  const double d = design.DesignDisplacement();
  const double dy = design.YieldDisplacement();
  Bhm2Mechanical bhm2;
  bhm2.fs = 0.5 * std::numbers::pi * design.damping * k_eff * d * d / (d - dy);
  bhm2.kh = k_eff - bhm2.fs / d;
  bhm2.ke = bhm2.kh + bhm2.fs / dy;
  return bhm2;
}

}  // namespace isolab::hysteresis
