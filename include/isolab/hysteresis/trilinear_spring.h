// Element 3 of Markou & Manolis (2016): a symmetric trilinear elastic spring on its own
// elongation x,
//   g(x) = kh1 x                                 |x| <= uc
//   g(x) = sign(x) kh1 uc + kh2 (x - sign(x) uc)  |x| >  uc
// written as g(x) = kh2 x + (kh1 - kh2) clamp(x, -uc, uc), which also holds for uc = +inf
// (a linear spring, used by the bilinear forms).
#pragma once

#include <algorithm>
#include <cmath>

namespace isolab::hysteresis {

struct TrilinearSpring {
  double kh1 = 0.0;      // stiffness inside +-uc (force/length)
  double kh2 = 0.0;      // stiffness beyond +-uc (force/length); may be negative (softening)
  double uc = INFINITY;  // characteristic displacement where the slope changes (length), > 0

  double Force(double x) const { return kh2 * x + (kh1 - kh2) * std::clamp(x, -uc, uc); }

  // Slope of the segment holding x; at x = +-uc the inner slope, so the tangent is one-sided
  // but always the slope of a segment the update can actually be on.
  double Stiffness(double x) const { return std::abs(x) <= uc ? kh1 : kh2; }

  // The linear branch of one segment (-1: x < -uc, 0: inside, +1: x > uc) continued beyond the
  // segment, for integrators that stay on a smooth branch until an event switches it.
  double SegmentForce(double x, int segment) const {
    return segment == 0 ? kh1 * x : kh2 * x + (kh1 - kh2) * segment * uc;
  }
  double SegmentStiffness(int segment) const { return segment == 0 ? kh1 : kh2; }
  // Positive while x is on `segment`; it falls through zero where x leaves it.
  double SegmentMargin(double x, int segment) const {
    if (segment != 0) return segment * x - uc;
    return std::isfinite(uc) ? uc - std::abs(x) : 1.0;
  }

  // Strain energy, the integral of g from 0 to x.
  double Energy(double x) const {
    const double ax = std::abs(x);
    if (ax <= uc) return 0.5 * kh1 * x * x;
    const double beyond = ax - uc;
    return 0.5 * kh1 * uc * uc + kh1 * uc * beyond + 0.5 * kh2 * beyond * beyond;
  }

  // Solves ke x + g(x) = rhs exactly for x (the spring in series with a spring ke, loaded by
  // rhs): h(x) = ke x + g(x) is piecewise linear and strictly increasing when ke + kh1 > 0 and
  // ke + kh2 > 0, so the segment follows from the value of h at uc. Writes the segment slope.
  double SolveInSeries(double ke, double rhs, double* slope) const {
    const double h_at_uc = (ke + kh1) * uc;  // +inf when uc is +inf: always the inner segment
    if (std::abs(rhs) <= h_at_uc) {
      *slope = kh1;
      return rhs / (ke + kh1);
    }
    *slope = kh2;
    const double sign = rhs > 0.0 ? 1.0 : -1.0;
    return (rhs - sign * (kh1 - kh2) * uc) / (ke + kh2);
  }
};

}  // namespace isolab::hysteresis
