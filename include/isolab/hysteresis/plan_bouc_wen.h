// Bouc-Wen hysteresis in two directions (bouc_wen.h for one), the biaxial form of Park, Wen &
// Ang (1986) written for an isotropic bearing as OpenSees' elastomericBearingBoucWen writes it:
// the force is the hysteretic vector z,
//   dz/dt = alpha v - beta |z|^(nu-2) z (gamma |z . v| + delta z . v),
// in the 1-D law's names (beta scales, gamma multiplies the sign term, delta the other). Along a
// line through the origin it is the 1-D law; for nu = 2 it is Park, Wen & Ang's equation whenever
// z_x v_x and z_y v_y have one sign (which holds along any line). Their form signs each component
// product separately, gamma z (|z_x v_x| + |z_y v_y|), which depends on the orientation of the x
// and y axes; an isotropic bearing cannot, so this law takes the sign of z . v (3D-BASIS uses the
// component form). The yield surface is the circle |z| = (alpha / (beta (gamma + delta)))^(1/nu):
// on it, loading (z . v > 0) moves z only across its radius.
//
// Rate-independent, so over an increment du, with T(z) = |z|^(nu-2) (gamma |z . du| + delta
// z . du) z, the trapezoidal rule of 1-D reads
//   z1 = z0 + (G(z0) + G(z1)) / 2,   G(z) = alpha du - beta T(z),
// solved by Newton on the 2x2 Jacobian I + (beta/2) dT/dz to round-off (NaN if it fails; the
// integrator cuts the step). Tangent, the exact derivative of that update:
//   d z1 / d u = (I + (beta/2) dT/dz(z1))^-1 (A(z0) + A(z1)) / 2,   A = alpha I - beta dT/d(du),
// with dT/d(du) = |z|^(nu-2) (gamma s + delta) z z^T, s = sign(z . du) (of z . v when du = 0,
// +1 when both vanish). Stored energy |z|^2 / (2 alpha); dissipated = the trapezoidal work
// (z0 + z1) . du / 2 less the change in stored energy.
#pragma once

#include "isolab/hysteresis/bouc_wen.h"
#include "isolab/hysteresis/plan_law_state.h"

namespace isolab::hysteresis {

struct PlanBoucWen {
  BoucWen law;

  // T(z, d) of the header with its derivatives in z and in d; `sign_direction` decides sign(z.d)
  // where z . d = 0 (the trial velocity, as in 1-D).
  struct Term {
    Vec2 value;
    Mat2 d_z;
    Mat2 d_d;
  };
  Term Hysteretic(Vec2 z, Vec2 d, Vec2 sign_direction) const;

  void Update(PlanLawStateView committed, const PlanLawInput& in, PlanLawStateSlot trial,
              PlanLawResponse* response) const;

  double StoredEnergy(PlanLawStateView state) const {
    const Vec2 z = Force(state);
    return Dot(z, z) / (2.0 * law.alpha);
  }
};

}  // namespace isolab::hysteresis
