// The named element laws and their parameters, in the paper's mathematical form (k0, k1, k2, uy,
// uyh) or its mechanical form (ke, kh1, kh2, fs, uc), converted as in Markou & Manolis (2016),
// Table 1 (restated in shared/design/models.md):
//
//   THM1 (series):   ke = k0, kh1 = k0 k1/(k0 - k1), kh2 = k0 k2/(k0 - k2), fs = k0 uy,
//                    uc = (uyh - uy)(k0 - k1)/k0
//   THM2 (parallel): ke = k0, kh1 = k1, kh2 = k2, fs = (k0 - k1) uy, uc = uyh
//   BHM1, BHM2: THM1, THM2 with k2 = k1 (one hardening stiffness kh, no uyh / uc).
//
// Degenerate forms are their own types and also reachable as THM1: the trilinear elastic spring
// (THM1 with uy = 0 and k0 >> k1, k2; then kh1 = k1, kh2 = k2, uc = uyh) and the elastoplastic
// element (THM1 with k1 = k2 = 0; uyh is then meaningless and may be omitted).
//
// Bouc-Wen (bouc_wen.h) takes alpha, beta, gamma, delta, nu in both forms. The degrading BHM2
// (degrading_slider.h) takes BHM2's k0, k1, uy (ke, kh, fs) and its damage's loss, slip_scale.
// The play sliders (play_slider.h): asymmetric_elastoplastic k0, uy_pos, uy_neg (ke, fs_pos,
// fs_neg = k0 uy_pos, k0 uy_neg); backlash_elastoplastic k0, uy, gap (ke, fs = k0 uy, gap).
//
// The bearing presets take the engineer's data, the same keys in both forms unless noted:
//   friction_pendulum  w, r, uy and mu, or mu_slow, mu_fast, a   (friction_pendulum.h)
//   lead_rubber        qd, kd and ku (mechanical) or dy (mathematical); optionally the lead
//                      core's heating: lead_diameter, lead_height, lead_heat_capacity [, e2]
//                      [, steel_conductivity, steel_diffusivity, shim_thickness]  (lead_rubber.h)
//   hdr_bearing        g, area, tr, damping, strain [, yield_strain]  (hdr_bearing.h)
//   double_friction_pendulum  w, r1, r2, mu1, mu2, d1, d2, uy            (multiple_pendulum.h)
//   triple_friction_pendulum  w, r1..r4, mu1..mu4, d1..d4, uy            (multiple_pendulum.h)
//
// Units are whatever the caller uses consistently (the paper: kN, mm).
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "isolab/hysteresis/law_kernel.h"

namespace isolab::hysteresis {

enum class LawType {
  kLinearSpring,
  kDashpot,
  kBhm1,
  kBhm2,
  kThm1,
  kThm2,
  kTrilinearElastic,
  kElastoplastic,
  kBoucWen,
  kDegradingBhm2,
  kFrictionPendulum,        // friction_pendulum.h
  kLeadRubber,              // lead_rubber.h
  kHdrBearing,              // hdr_bearing.h: BHM2 from design data
  kDoubleFrictionPendulum,  // multiple_pendulum.h: two sliding surfaces in series
  kTripleFrictionPendulum,  // multiple_pendulum.h: Fenz & Constantinou's series model
  // play_slider.h: a strength that differs by direction, and a slider engaged through a
  // clearance.
  kAsymmetricElastoplastic,
  kBacklashElastoplastic,
};

// The most keys a law takes (the triple pendulum's 14).
inline constexpr int kMaxLawParameters = 14;

enum class ParameterForm { kMathematical, kMechanical };

// The name used in model files ("thm1", "linear_spring", ...).
std::string_view LawName(LawType type);
std::optional<LawType> LawTypeFromName(std::string_view name);
std::span<const LawType> AllLawTypes();

// The parameter names of a law in one form, in the order values are passed and returned.
std::span<const std::string_view> ParameterKeys(LawType type, ParameterForm form);

// True when a law may omit this key: THM1's uyh (uc) when k1 = k2 (kh1 = kh2); the bearing
// presets' alternatives, optional heating and defaulted keys.
bool IsOptionalKey(LawType type, std::string_view key);

// A validated law. The form the user gave is kept exactly and drives the kernel; the other
// form is derived from it.
class LawParameters {
 public:
  // `values` follows ParameterKeys(type, form); NaN marks an omitted value. Throws
  // InvalidParameter naming the first key that breaks a rule, in the form given.
  static LawParameters Make(LawType type, ParameterForm form, std::span<const double> values);

  LawType type() const { return type_; }
  // Values in the order of ParameterKeys(type(), form); NaN for an omitted optional value.
  std::vector<double> Values(ParameterForm form) const;
  LawKernel Kernel() const;

 private:
  LawParameters(LawType type, std::array<double, kMaxLawParameters> mathematical,
                std::array<double, kMaxLawParameters> mechanical);

  LawType type_;
  std::array<double, kMaxLawParameters> mathematical_;
  std::array<double, kMaxLawParameters> mechanical_;
};

// The weight W a friction pendulum bearing (friction_pendulum, double_friction_pendulum,
// triple_friction_pendulum) carries; nullopt for every other law. Each of these laws' strengths
// (mu W) and stiffnesses (W / R, the pre-slide mu W / u_y) is W times a constant, and their
// sliders' decisions compare forces with strengths only, so the displacement history a law's state
// follows does not depend on W: under an axial load N its force, tangent and work are exactly
// N / W times those at W (the axial load scaling of structure/axial_load.h).
std::optional<double> PendulumWeight(const LawParameters& law);

}  // namespace isolab::hysteresis
