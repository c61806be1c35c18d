// A high-damping rubber bearing from its design data, mapped onto the paper's BHM2 (Markou &
// Manolis 2016; parallel_slider.h with a linear spring): the BHM2 whose secant stiffness and
// equivalent viscous damping at the design displacement D equal the bearing's,
//   K_eff = G A / T_r,   D = gamma T_r,   D_y = gamma_y T_r,
//   fs (D - D_y) = (pi/2) xi K_eff D^2        (energy per cycle 4 fs (D - D_y) = 2 pi xi K_eff D^2)
//   kh = K_eff - fs / D                         (peak force kh D + fs = K_eff D)
//   ke = kh + fs / D_y                          (BHM2 yields at D_y)
// with G the rubber's shear modulus, A the bonded area, T_r the total rubber thickness, gamma the
// design shear strain, xi the equivalent damping ratio there and gamma_y the shear strain at which
// the equivalent bilinear yields (D_y / T_r; this library's default 0.1 is a choice, not a
// published value: give the bearing's own when its tests show it). The post-yield stiffness kh
// must not be negative, so xi <= 2 (1 - gamma_y / gamma) / pi.
#pragma once

namespace isolab::hysteresis {

struct HdrDesign {
  double shear_modulus = 0.0;     // G (force/length^2), > 0
  double bonded_area = 0.0;       // A (length^2), > 0
  double rubber_thickness = 0.0;  // T_r (length), > 0
  double damping = 0.0;           // xi at the design strain, in (0, 2 (1 - gamma_y/gamma) / pi]
  double strain = 0.0;            // design shear strain gamma, > 0
  double yield_strain = 0.1;      // gamma_y, in (0, gamma)

  double EffectiveStiffness() const { return shear_modulus * bonded_area / rubber_thickness; }
  double DesignDisplacement() const { return strain * rubber_thickness; }
  double YieldDisplacement() const { return yield_strain * rubber_thickness; }
  // The largest damping a BHM2 with kh >= 0 reaches at the design strain.
  double MaxDamping() const;
};

// BHM2 in mechanical form.
struct Bhm2Mechanical {
  double ke = 0.0, kh = 0.0, fs = 0.0;
};

Bhm2Mechanical EquivalentBhm2(const HdrDesign& design);

}  // namespace isolab::hysteresis
