// The trilinear spring g of trilinear_spring.h extended to a plan deformation x = (x_x, x_y)
// isotropically (the radial extension):
//   g(x) = g_r(|x|) x / |x|,   g_r the 1-D spring on r = |x|,
// so its force is radial, its energy is the 1-D energy of |x| (a potential, so no work is lost
// round a closed path), and along any line through the origin it is the 1-D spring exactly. Its
// stiffness is anisotropic beyond uc, the radial slope along e = x / r and the secant across:
//   Dg = g_r'(r) e e^T + (g_r(r) / r) (I - e e^T),
// where the secant g_r(r) / r lies between kh1 and kh2. Segments, for the rate forms: 0 for
// r <= uc, where g = kh1 x; 1 beyond, where g = kh2 x + (kh1 - kh2) uc e.
#pragma once

#include <cmath>

#include "isolab/hysteresis/plan_vector.h"
#include "isolab/hysteresis/trilinear_spring.h"

namespace isolab::hysteresis {

inline int RadialSegment(const TrilinearSpring& g, Vec2 x) { return Norm(x) <= g.uc ? 0 : 1; }

inline Vec2 RadialSegmentForce(const TrilinearSpring& g, Vec2 x, int segment) {
  if (segment == 0) return g.kh1 * x;
  return (g.kh2 + (g.kh1 - g.kh2) * g.uc / Norm(x)) * x;
}
inline Vec2 RadialForce(const TrilinearSpring& g, Vec2 x) {
  return RadialSegmentForce(g, x, RadialSegment(g, x));
}

inline Mat2 RadialSegmentStiffness(const TrilinearSpring& g, Vec2 x, int segment) {
  if (segment == 0) return Identity(g.kh1);
  const double r = Norm(x);
  return Identity(g.kh2) + ((g.kh1 - g.kh2) * g.uc / r) * NormalProjector(x / r);
}
inline Mat2 RadialStiffness(const TrilinearSpring& g, Vec2 x) {
  return RadialSegmentStiffness(g, x, RadialSegment(g, x));
}

// d (Dg(x) w) / dx on `segment` at fixed w: zero inside; beyond uc, with c = (kh1 - kh2) uc,
//   -c / r^2 [w e^T + e w^T + (e.w) (I - 3 e e^T)].
// The rate forms need it where their rates multiply Dg by a vector.
inline Mat2 RadialStiffnessDerivative(const TrilinearSpring& g, Vec2 x, int segment, Vec2 w) {
  if (segment == 0) return {};
  const double r = Norm(x);
  const Vec2 e = x / r;
  const double ew = Dot(e, w);
  const Mat2 m = Outer(w, e) + Outer(e, w) + ew * (Identity() - 3.0 * Outer(e, e));
  return (-(g.kh1 - g.kh2) * g.uc / (r * r)) * m;
}

inline double RadialEnergy(const TrilinearSpring& g, Vec2 x) { return g.Energy(Norm(x)); }

// Solves ke x + g(x) = rhs for x with g on `segment`'s branch, continued beyond the segment (for
// the rate forms, which stay on a branch until an event switches it). The solution is along rhs.
inline Vec2 SolveRadialSegmentInSeries(const TrilinearSpring& g, double ke, Vec2 rhs, int segment) {
  if (segment == 0) return rhs / (ke + g.kh1);
  return ((1.0 - (g.kh1 - g.kh2) * g.uc / Norm(rhs)) / (ke + g.kh2)) * rhs;
}

// Solves ke x + g(x) = rhs for x (the spring in series with a spring ke, loaded by rhs). The
// solution is radial along rhs, so it is the 1-D solution (TrilinearSpring::SolveInSeries) at
// |rhs|: unique when ke + kh1 > 0 and ke + kh2 > 0.
inline Vec2 SolveRadialInSeries(const TrilinearSpring& g, double ke, Vec2 rhs) {
  return SolveRadialSegmentInSeries(g, ke, rhs, Norm(rhs) <= (ke + g.kh1) * g.uc ? 0 : 1);
}

}  // namespace isolab::hysteresis
