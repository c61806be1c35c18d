#include "isolab/hysteresis/plan_series_rate_form.h"

#include <cmath>

namespace isolab::hysteresis {
namespace {

Vec2 ElementAt(const double* q, int k) { return {q[2 * k], q[2 * k + 1]}; }

bool Sliding(RingMode mode) {
  return mode == RingMode::kSliding || mode == RingMode::kSlidingOnRing;
}
bool OnRing(RingMode mode) {
  return mode == RingMode::kStuckOnRing || mode == RingMode::kSlidingOnRing;
}

Vec2 ForceOf(const SeriesArrangement& law, Vec2 u, const double* q) {
  Vec2 sliders;
  for (int k = 0; k < law.count; ++k) sliders = sliders + ElementAt(q, k);
  return law.ke * (u - sliders);
}

// An element's compliance while it slides (zero while it sticks) and its friction direction.
struct ElementRate {
  Mat2 compliance;
  Vec2 friction;  // unit, the direction its friction acts in while it slides
};
ElementRate RateOf(const SeriesElement& e, RingMode mode, int side, Vec2 force, Vec2 z) {
  ElementRate r;
  if (mode == RingMode::kSliding) {
    const Vec2 s = force - e.stiffness * z;
    r.friction = s / Norm(s);
    r.compliance = (1.0 / e.stiffness) * Outer(r.friction, r.friction);
  } else if (mode == RingMode::kSlidingOnRing) {
    const double radius = Norm(z);
    const Vec2 n = z / radius, t = Perpendicular(n);
    r.friction = side * t;
    r.compliance = (radius / Dot(force, n)) * Outer(t, t);
  }
  return r;
}

// d(C w)/dF and d(C w)/dz at fixed w, for a sliding element (the header's C).
void RateDerivatives(const SeriesElement& e, RingMode mode, Vec2 force, Vec2 z, Vec2 w, Mat2* p,
                     Mat2* q) {
  if (mode == RingMode::kSliding) {
    // C w = m (m . w) / k, m = s / |s|, s = F - k z: dm = (I - m m^T) ds / |s|.
    const Vec2 s = force - e.stiffness * z;
    const double norm = Norm(s);
    const Vec2 m = s / norm;
    const Mat2 across = NormalProjector(m);
    *p = (1.0 / (e.stiffness * norm)) * (Dot(m, w) * across + Outer(m, across * w));
    *q = -e.stiffness * *p;
    return;
  }
  // C w = g t, g = r (t . w) / (F . n), n = z / r, t = Perpendicular(n): dn = t (t . dz) / r,
  // dt = -n (t . dz) / r, dr = n . dz.
  const double r = Norm(z);
  const Vec2 n = z / r, t = Perpendicular(n);
  const double fn = Dot(force, n), ft = Dot(force, t), tw = Dot(t, w), nw = Dot(n, w);
  *p = (-r * tw / (fn * fn)) * Outer(t, n);
  *q = Outer(t, (tw / fn) * n - (nw / fn + tw * ft / (fn * fn)) * t) - (tw / fn) * Outer(n, t);
}

// H = I / ke + sum of the sliding elements' compliances.
Mat2 Flexibility(const SeriesArrangement& law, const PlanSeriesPhase& phase, Vec2 force,
                 const double* q) {
  Mat2 h = Identity(1.0 / law.ke);
  for (int k = 0; k < law.count; ++k) {
    if (!Sliding(phase.mode[k])) continue;
    h = h +
        RateOf(law.elements[k], phase.mode[k], phase.side[k], force, ElementAt(q, k)).compliance;
  }
  return h;
}

// The sliding elements inside their rings back on their friction circles, at the force u gives
// with the others where they are, and the elements on a ring exactly on it.
void Project(const SeriesArrangement& law, const PlanSeriesPhase& phase, Vec2 u, double* q) {
  const Vec2 force = ForceOf(law, u, q);
  double compliance = 1.0 / law.ke;
  Vec2 rest = u;
  std::array<Vec2, kMaxSeriesElements> friction{};
  for (int k = 0; k < law.count; ++k) {
    const SeriesElement& e = law.elements[k];
    Vec2 z = ElementAt(q, k);
    if (OnRing(phase.mode[k])) {
      z = (e.stop / Norm(z)) * z;
      q[2 * k] = z.x;
      q[2 * k + 1] = z.y;
    }
    if (phase.mode[k] == RingMode::kSliding) {
      const Vec2 s = force - e.stiffness * z;
      friction[k] = s / Norm(s);
      compliance += 1.0 / e.stiffness;
      rest = rest + (e.strength / e.stiffness) * friction[k];
    } else {
      rest = rest - z;
    }
  }
  const Vec2 projected = rest / compliance;
  for (int k = 0; k < law.count; ++k) {
    if (phase.mode[k] != RingMode::kSliding) continue;
    const SeriesElement& e = law.elements[k];
    const Vec2 z = (1.0 / e.stiffness) * (projected - e.strength * friction[k]);
    q[2 * k] = z.x;
    q[2 * k + 1] = z.y;
  }
}

// Projects, then switches every element whose event the projected state has reached in the
// direction of motion, until none does: events that fall together switch together.
void Settle(const SeriesArrangement& law, Vec2 u, Vec2 v, PlanSeriesPhaseSwitch* next) {
  for (int pass = 0; pass <= 2 * law.count; ++pass) {
    Project(law, next->phase, u, next->q.data());
    const Vec2 force = ForceOf(law, u, next->q.data());
    const Vec2 rate = Inverse(Flexibility(law, next->phase, force, next->q.data())) * v;
    bool changed = false;
    for (int k = 0; k < law.count; ++k) {
      const SeriesElement& e = law.elements[k];
      const Vec2 z = ElementAt(next->q.data(), k), s = force - e.stiffness * z;
      RingMode& mode = next->phase.mode[k];
      if (mode == RingMode::kStuck && Norm(s) >= e.strength && Dot(s, rate) > 0.0) {
        mode = RingMode::kSliding;
        changed = true;
      } else if (mode == RingMode::kSliding && Norm(z) >= e.stop) {
        mode = RingMode::kStuckOnRing;
        changed = true;
      } else if (mode == RingMode::kStuckOnRing) {
        const Vec2 n = z / Norm(z), t = Perpendicular(n);
        const double along = Dot(s, t);
        if (Dot(s, n) < 0.0) {
          mode = RingMode::kStuck;
          changed = true;
        } else if (std::abs(along) >= e.strength && along * Dot(t, rate) > 0.0) {
          mode = RingMode::kSlidingOnRing;
          next->phase.side[k] = along > 0.0 ? 1 : -1;
          changed = true;
        }
      }
    }
    if (!changed) return;
  }
}

void SetBlock(std::array<std::array<double, kMaxPlanSeriesVariables>, 2>* rows, int column,
              const Mat2& m) {
  (*rows)[0][column] = m.xx;
  (*rows)[0][column + 1] = m.xy;
  (*rows)[1][column] = m.yx;
  (*rows)[1][column + 1] = m.yy;
}

}  // namespace

PlanSeriesRateResponse EvaluatePlanSeriesRate(const SeriesArrangement& law,
                                              const PlanSeriesPhase& phase, Vec2 u, Vec2 v,
                                              const double* q) {
  PlanSeriesRateResponse r;
  const Vec2 force = ForceOf(law, u, q);
  r.force = force;
  r.force_u = Identity(law.ke);
  for (int k = 0; k < law.count; ++k) SetBlock(&r.force_q, 2 * k, Identity(-law.ke));

  const Mat2 h_inverse = Inverse(Flexibility(law, phase, force, q));
  const Vec2 w = h_inverse * v;  // dF/dt
  std::array<ElementRate, kMaxSeriesElements> rates{};
  std::array<Mat2, kMaxSeriesElements> p{}, dz{};
  Mat2 p_sum;
  for (int k = 0; k < law.count; ++k) {
    if (!Sliding(phase.mode[k])) continue;
    const Vec2 z = ElementAt(q, k);
    rates[k] = RateOf(law.elements[k], phase.mode[k], phase.side[k], force, z);
    RateDerivatives(law.elements[k], phase.mode[k], force, z, w, &p[k], &dz[k]);
    p_sum = p_sum + p[k];
  }
  // dw/du = -H^-1 ke sum P; dw/dz_j = -H^-1 (-ke sum P + Q_j).
  const Mat2 dw_du = -law.ke * (h_inverse * p_sum);
  for (int k = 0; k < law.count; ++k) {
    if (!Sliding(phase.mode[k])) continue;
    const Mat2& c = rates[k].compliance;
    const Vec2 rate = c * w;
    r.rate[2 * k] = rate.x;
    r.rate[2 * k + 1] = rate.y;
    r.hysteretic_power += law.elements[k].strength * Dot(rates[k].friction, rate);
    const Mat2 rate_v = c * h_inverse, rate_u = law.ke * p[k] + c * dw_du;
    r.rate_v[2 * k] = {rate_v.xx, rate_v.xy};
    r.rate_v[2 * k + 1] = {rate_v.yx, rate_v.yy};
    r.rate_u[2 * k] = {rate_u.xx, rate_u.xy};
    r.rate_u[2 * k + 1] = {rate_u.yx, rate_u.yy};
    for (int j = 0; j < law.count; ++j) {
      const Mat2 own = j == k ? dz[k] : Mat2{};
      const Mat2 dw_dz =
          -1.0 * (h_inverse * (-law.ke * p_sum + (Sliding(phase.mode[j]) ? dz[j] : Mat2{})));
      const Mat2 block = -law.ke * p[k] + own + c * dw_dz;
      r.rate_q[2 * k][2 * j] = block.xx;
      r.rate_q[2 * k][2 * j + 1] = block.xy;
      r.rate_q[2 * k + 1][2 * j] = block.yx;
      r.rate_q[2 * k + 1][2 * j + 1] = block.yy;
    }
  }
  return r;
}

void PlanSeriesPhaseRoots(const SeriesArrangement& law, const PlanSeriesPhase& phase, Vec2 u,
                          Vec2 v, const double* q, double* roots) {
  const Vec2 force = ForceOf(law, u, q);
  const Vec2 rate = Inverse(Flexibility(law, phase, force, q)) * v;
  for (int k = 0; k < law.count; ++k) {
    const SeriesElement& e = law.elements[k];
    const Vec2 z = ElementAt(q, k), s = force - e.stiffness * z;
    double* root = roots + 2 * k;
    switch (phase.mode[k]) {
      case RingMode::kStuck:
        root[0] = e.strength - Norm(s);
        root[1] = 1.0;
        break;
      case RingMode::kSliding:
        root[0] = Dot(s / Norm(s), rate);
        root[1] = std::isinf(e.stop) ? 1.0 : e.stop - Norm(z);
        break;
      case RingMode::kStuckOnRing: {
        const Vec2 n = z / Norm(z);
        root[0] = e.strength - std::abs(Dot(s, Perpendicular(n)));
        root[1] = Dot(s, n);
        break;
      }
      case RingMode::kSlidingOnRing: {
        const Vec2 n = z / Norm(z);
        root[0] = phase.side[k] * Dot(Perpendicular(n), rate);
        root[1] = Dot(s, n);
        break;
      }
    }
  }
}

PlanSeriesPhaseSwitch SwitchPlanSeriesPhase(const SeriesArrangement& law,
                                            const PlanSeriesPhase& phase,
                                            std::span<const int> roots_found, Vec2 u, Vec2 v,
                                            const double* q) {
  PlanSeriesPhaseSwitch next{phase, {}};
  for (int i = 0; i < 2 * law.count; ++i) next.q[i] = q[i];
  const Vec2 force = ForceOf(law, u, q);
  const Vec2 rate = Inverse(Flexibility(law, phase, force, q)) * v;
  for (int k = 0; k < law.count; ++k) {
    const bool loading = roots_found[2 * k] != 0, other = roots_found[2 * k + 1] != 0;
    if (!loading && !other) continue;
    const SeriesElement& e = law.elements[k];
    const Vec2 z = ElementAt(q, k), s = force - e.stiffness * z;
    RingMode& mode = next.phase.mode[k];
    switch (phase.mode[k]) {
      case RingMode::kStuck:  // its friction reached its strength: it slides if loaded
        if (Dot(s, rate) > 0.0) mode = RingMode::kSliding;
        break;
      case RingMode::kSliding:
        // Reaching the ring, it sticks against it (its friction leans off the ring's tangent).
        mode = other ? RingMode::kStuckOnRing : RingMode::kStuck;
        break;
      case RingMode::kStuckOnRing: {
        const Vec2 t = Perpendicular(z / Norm(z));
        if (other) {
          mode = RingMode::kStuck;  // pulled off the ring
        } else if (Dot(s, t) * Dot(t, rate) > 0.0) {
          mode = RingMode::kSlidingOnRing;
          next.phase.side[k] = Dot(s, t) > 0.0 ? 1 : -1;
        }
        break;
      }
      case RingMode::kSlidingOnRing:
        mode = other ? RingMode::kSliding : RingMode::kStuckOnRing;
        break;
    }
  }
  Settle(law, u, v, &next);
  return next;
}

void PlanSeriesRateFormState(const SeriesArrangement& law, const PlanSeriesPhase& phase, Vec2 u,
                             Vec2 v, const double* q, std::span<PlanLawState> block) {
  CoupledState c;
  c.force = ForceOf(law, u, q);
  for (int k = 0; k < law.count; ++k) {
    const Vec2 z = ElementAt(q, k);
    c.slider = c.slider + z;
    c.slipping = c.slipping || Sliding(phase.mode[k]);
    block[k + 1].x = LawState{.slider = z.x, .slip = Sliding(phase.mode[k]) ? 1 : 0};
    block[k + 1].y = LawState{.slider = z.y, .slip = OnRing(phase.mode[k]) ? 1 : 0};
  }
  Store({u, v, 0.0}, c, &block[0]);
}

}  // namespace isolab::hysteresis
