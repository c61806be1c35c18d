#include "isolab/hysteresis/plan_series_arrangement.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <numbers>

namespace isolab::hysteresis {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kMaxNewtonIterations = 100;
constexpr int kMaxAngleIterations = 100;

// The unit vector at angle a from the unit reference r (towards Perpendicular(r) for a > 0), so
// that a = 0 gives r exactly: along an axis the plan form keeps the 1-D law's numbers.
Vec2 Turned(Vec2 r, double a) { return std::cos(a) * r + std::sin(a) * Perpendicular(r); }

// One element's displacement at the force F (the header's three cases) and its derivative.
struct ElementResponse {
  Vec2 z;
  Mat2 dz_dforce;
  double travel = 0.0;  // |z - z_n|, computed without cancellation
  bool sliding = false;
  bool at_stop = false;
};

class Element {
 public:
  Element() = default;
  Element(const SeriesElement& e, Vec2 z_n, bool sliding_n, bool at_stop_n, Vec2 force_n)
      : k_(e.stiffness),
        f_(e.strength),
        d_(e.stop),
        z_n_(z_n),
        sliding_n_(sliding_n),
        at_stop_n_(at_stop_n),
        force_n_(force_n) {}

  ElementResponse At(Vec2 force) const {
    const Vec2 w = force - k_ * z_n_;  // the slider's force if it sticks
    if (at_stop_n_) {
      const Vec2 e = z_n_ / Norm(z_n_), t = Perpendicular(e);
      // Pressed against the ring: its part along the ring decides, and the slide, if any, ends
      // near z_n on that side (the force's part along the ring falls as the end point turns
      // towards it). A slide round the ring ends with that part at f cos(a / 2), inside the
      // friction circle (the chord it moved along leans by a / 2 from the ring's tangent), so,
      // unlike a slide inside the ring, it does not go on at once.
      if (Dot(w, e) > 0.0) {
        const double along = Dot(w, t);
        if (!(std::abs(along) > f_)) return Stuck(true);
        const Ring ring{this, force, e, true};
        return OnRing(ring, ring.FirstMinimum(along > 0 ? 1.0 : -1.0));
      }
    }
    const Vec2 committed_friction = force_n_ - k_ * z_n_;
    const bool goes_on =
        sliding_n_ && !at_stop_n_ && Dot(committed_friction, force - force_n_) >= 0.0;
    const double w_norm = Norm(w);
    if (!goes_on && !(w_norm > f_)) return Stuck(at_stop_n_);
    // Inside the stop: the force-driven radial return.
    ElementResponse r;
    r.sliding = true;
    const Vec2 n = w_norm > 0.0 ? w / w_norm : Vec2{1.0, 0.0};
    r.travel = std::max(0.0, w_norm - f_) / k_;
    r.z = z_n_ + r.travel * n;
    const double across = w_norm > 0.0 ? std::max(0.0, 1.0 - f_ / w_norm) : 1.0;
    r.dz_dforce = (1.0 / k_) * (Outer(n, n) + across * NormalProjector(n));
    if (!(Dot(r.z, r.z) > d_ * d_)) return r;
    // Beyond the ring: the end point is on it, wherever psi is least there (the force may pull the
    // element across the disc).
    const Ring ring = at_stop_n_ ? Ring{this, force, z_n_ / Norm(z_n_), true}
                                 : Ring{this, force, r.z / Norm(r.z), false};
    return OnRing(ring, ring.Minimum());
  }

  // The element's part of Phi (the header): F . (z - z_n) - psi(z) + psi(z_n); `size` gathers the
  // magnitude of its terms, the scale of its round-off.
  double Potential(Vec2 force, const ElementResponse& r, double* size) const {
    const double work = Dot(force, r.z - z_n_),
                 spring = 0.5 * k_ * (Dot(r.z, r.z) - Dot(z_n_, z_n_));
    *size += std::abs(work) + 0.5 * k_ * (Dot(r.z, r.z) + Dot(z_n_, z_n_)) + f_ * r.travel;
    return work - spring - f_ * r.travel;
  }

 private:
  ElementResponse Stuck(bool at_stop) const {
    ElementResponse r;
    r.z = z_n_;
    r.at_stop = at_stop;
    return r;
  }

  // psi on the ring, in the angle a of the end point d Turned(r, a) about a unit r: from z_n on
  // the ring r = e_n (a = 0 is z_n, where psi has a corner, and the chord is 2 d sin(|a|/2), free
  // of cancellation); from inside, r the direction of the unconstrained slide's end.
  //   Phi(a) = (f |z(a) - z_n| - d F . e(a)) / d,
  //   H(a) = -dPhi/da = (F - f m(a)) . t(a)  (the force less friction along the ring),
  //   dH/da = -(F - f m) . e - f d (1 - (m . t)^2) / |z(a) - z_n|,
  // m the chord's direction, t = Perpendicular(e). A minimum has H = 0 and dH/da < 0, and
  // z(F) there moves along t with dz/dF = -d t t^T / (dH/da).
  struct Ring {
    const Element* element;
    Vec2 force, r;
    bool from_ring;

    double Chord(double a) const {
      const double d = element->d_;
      return from_ring ? 2.0 * d * std::sin(0.5 * std::abs(a))
                       : Norm(d * Turned(r, a) - element->z_n_);
    }
    // The chord's direction; at a = 0 from the ring, the limit on `side`.
    Vec2 Slip(double a, double side) const {
      if (from_ring)
        return (a != 0.0 ? (a > 0 ? 1.0 : -1.0) : side) * Perpendicular(Turned(r, 0.5 * a));
      const Vec2 chord = element->d_ * Turned(r, a) - element->z_n_;
      return chord / Norm(chord);
    }
    double Phi(double a) const {
      return element->f_ * Chord(a) / element->d_ - Dot(force, Turned(r, a));
    }
    double H(double a, double side = 1.0) const {
      return Dot(force - element->f_ * Slip(a, side), Perpendicular(Turned(r, a)));
    }
    double Slope(double a) const {
      const Vec2 e = Turned(r, a), t = Perpendicular(e);
      const double f = element->f_;
      if (from_ring) return -Dot(force, e) + 0.5 * f * std::sin(0.5 * std::abs(a));
      const Vec2 m = Slip(a, 1.0);
      const double mt = Dot(m, t);
      return -Dot(force - f * m, e) - f * element->d_ * (1.0 - mt * mt) / Chord(a);
    }

    // The minimum nearest a = 0 on `side` from the ring, where H(0) > 0 on that side: H falls
    // through zero once before the end point passes the force's direction.
    double FirstMinimum(double side) const {
      const double step = side * kPi / 32;
      double a = 0.0;
      // Descending: H > 0 going up, H < 0 going down.
      for (int i = 0; i < 32 && (H(a + step, side) > 0.0) == (side > 0); ++i) a += step;
      return RootOfH(std::min(a, a + step), std::max(a, a + step), side);
    }

    // The least of psi's minima on the ring: every local minimum of 64 samples refined, the least
    // kept (psi on a circle may have two; the problem on the disc, being convex, has one).
    double Minimum() const {
      constexpr int kSamples = 64;
      constexpr double kStep = 2 * kPi / kSamples;
      std::array<double, kSamples> value;
      for (int j = 0; j < kSamples; ++j) value[j] = Phi(-kPi + kStep * (j + 1));
      double best = from_ring ? 0.0 : NAN, best_value = from_ring ? Phi(0.0) : INFINITY;
      if (from_ring && (H(0.0, 1.0) > 0.0 || H(0.0, -1.0) < 0.0)) {
        // z_n is not a corner minimum: descend from it on the side that falls.
        best = H(0.0, 1.0) > 0.0 ? FirstMinimum(1.0) : FirstMinimum(-1.0);
        best_value = Phi(best);
      }
      for (int j = 0; j < kSamples; ++j) {
        const double here = value[j];
        if (here > value[(j + 1) % kSamples] || here > value[(j + kSamples - 1) % kSamples])
          continue;
        double low = -kPi + kStep * j, high = low + 2 * kStep;
        const double a_j = low + kStep;
        if (!from_ring && a_j == 0.0 && H(0.0) == 0.0) return 0.0;  // exactly along an axis
        if (from_ring) {  // keep to one side of the corner at z_n
          if (low < 0.0 && high > 0.0) (a_j > 0.0 ? low : high) = 0.0;
          if (a_j == 0.0) continue;
        }
        const double side = a_j > 0.0 ? 1.0 : -1.0;
        const double a = RootOfH(low, high, side);
        if (const double v = Phi(a); v < best_value) {
          best = a;
          best_value = v;
        }
      }
      return best;
    }

    // The root of H on [low, high] where H falls through zero (H(low) > 0 > H(high)); an end
    // where H has the sign of a minimum beyond the bracket is returned as it is. Newton, falling
    // back to bisection whenever a step leaves the bracket, to round-off.
    double RootOfH(double low, double high, double side) const {
      const auto h = [&](double a) { return H(a, side); };
      if (!(h(low) > 0.0)) return low;
      if (!(h(high) < 0.0)) return high;
      double x = low - h(low) / Slope(low);
      if (!(x > low && x < high)) x = 0.5 * (low + high);
      for (int i = 0; i < kMaxAngleIterations; ++i) {
        const double value = h(x);
        if (value == 0.0) return x;
        (value > 0.0 ? low : high) = x;
        double next = x - value / Slope(x);
        if (!(next > low && next < high)) next = 0.5 * (low + high);
        if (std::abs(next - x) <= 4 * DBL_EPSILON * (1.0 + std::abs(x))) return next;
        x = next;
      }
      return x;
    }
  };

  ElementResponse OnRing(const Ring& ring, double a) const {
    if (ring.from_ring && a == 0.0) return Stuck(true);
    ElementResponse r;
    r.sliding = true;
    r.at_stop = true;
    const Vec2 e = Turned(ring.r, a), t = Perpendicular(e);
    r.z = d_ * e;
    r.travel = ring.Chord(a);
    const double slope = ring.Slope(a);
    r.dz_dforce = slope < 0.0 ? (-d_ / slope) * Outer(t, t) : Mat2{};
    return r;
  }

  double k_ = 1.0, f_ = 0.0, d_ = INFINITY;
  Vec2 z_n_;
  bool sliding_n_ = false, at_stop_n_ = false;
  Vec2 force_n_;
};

}  // namespace

PlanSeriesArrangement::Step PlanSeriesArrangement::Solve(Vec2 u_n, Vec2 force_n,
                                                         const PlanSeriesElementStates& elements_n,
                                                         Vec2 u) const {
  const int n = law.count;
  std::array<Element, kMaxSeriesElements> elements;
  for (int k = 0; k < n; ++k) {
    elements[k] = Element(law.elements[k], elements_n.z[k], elements_n.sliding[k],
                          elements_n.at_stop[k], force_n);
  }
  const Vec2 du = u - u_n;
  std::array<ElementResponse, kMaxSeriesElements> responses;
  // U(F) - u, its Jacobian H and Phi at F.
  struct Evaluation {
    Vec2 residual;
    Mat2 jacobian;
    double potential = 0.0;
    double potential_size = 0.0;  // the magnitude of its terms
    bool sliding = false;
  };
  const auto evaluate = [&](Vec2 force) {
    Evaluation ev;
    const Vec2 df = force - force_n;
    ev.residual = df / law.ke - du;
    ev.jacobian = Identity(1.0 / law.ke);
    ev.potential = 0.5 * Dot(df, df) / law.ke - Dot(force, du);
    ev.potential_size = 0.5 * Dot(df, df) / law.ke + std::abs(Dot(force, du));
    for (int k = 0; k < n; ++k) {
      responses[k] = elements[k].At(force);
      ev.residual = ev.residual + (responses[k].z - elements_n.z[k]);
      ev.jacobian = ev.jacobian + responses[k].dz_dforce;
      ev.potential += elements[k].Potential(force, responses[k], &ev.potential_size);
      ev.sliding = ev.sliding || responses[k].sliding;
    }
    return ev;
  };

  Step step;
  // The elastic trial: the answer when every element sticks.
  Vec2 force = force_n + law.ke * du;
  Evaluation ev = evaluate(force);
  if (ev.sliding) {
    // Newton from the committed force, where the first step is the tangent's prediction.
    force = force_n;
    ev = evaluate(force);
    double scale = Norm(u_n) + Norm(du) + Norm(force_n) / law.ke;
    for (int k = 0; k < n; ++k) scale += Norm(elements_n.z[k]);
    const double tolerance = 8 * DBL_EPSILON * scale;
    bool converged = false;
    for (int iteration = 0; iteration < kMaxNewtonIterations; ++iteration) {
      if (Norm(ev.residual) <= tolerance) {
        converged = true;
        break;
      }
      ++step.iterations;
      const Vec2 direction = -hysteresis::Solve(ev.jacobian, ev.residual);
      const double descent = Dot(ev.residual, direction);  // < 0: H is positive definite
      double fraction = 1.0;
      Vec2 candidate = force + direction;
      Evaluation next = evaluate(candidate);
      // Armijo on Phi. Near the solution Phi's decrease drowns in its round-off, so a step that
      // halves the residual without raising Phi beyond that round-off is taken too.
      const auto accepted = [&](const Evaluation& e, double fraction) {
        if (e.potential <= ev.potential + 1e-4 * fraction * descent) return true;
        const double roundoff = 64 * DBL_EPSILON * (ev.potential_size + e.potential_size);
        return Norm(e.residual) <= 0.5 * Norm(ev.residual) &&
               e.potential <= ev.potential + roundoff;
      };
      while (!accepted(next, fraction) && fraction > 1e-12) {
        fraction *= 0.5;
        candidate = force + fraction * direction;
        next = evaluate(candidate);
      }
      if (Norm(candidate - force) <= 4 * DBL_EPSILON * Norm(force)) {
        converged = Norm(next.residual) <= 1e-9 * scale;
        force = candidate;
        ev = next;
        break;
      }
      force = candidate;
      ev = next;
    }
    if (!converged) force = {NAN, NAN};
  }
  // The element states at the final force (responses_ hold them from its evaluation).
  step.force = force;
  step.stiffness = Inverse(ev.jacobian);
  for (int k = 0; k < n; ++k) {
    const ElementResponse& r = responses[k];
    step.elements.z[k] = r.z;
    step.elements.travel[k] = elements_n.travel[k] + r.travel;
    step.elements.sliding[k] = r.sliding;
    step.elements.at_stop[k] = r.at_stop;
    step.sliding = step.sliding || r.sliding;
    step.travel += r.travel;
    step.dissipated += law.elements[k].strength * r.travel;
  }
  return step;
}

PlanSeriesElementStates PlanSeriesArrangement::Gather(
    std::span<const PlanLawState> element_states) const {
  PlanSeriesElementStates elements;
  for (int k = 0; k < law.count; ++k) {
    const PlanLawState& s = element_states[k];
    elements.z[k] = {s.x.slider, s.y.slider};
    elements.travel[k] = s.x.accumulated_slip;
    elements.sliding[k] = s.x.slip != 0;
    elements.at_stop[k] = s.y.slip != 0;
  }
  return elements;
}

void PlanSeriesArrangement::Scatter(const PlanSeriesElementStates& elements,
                                    std::span<PlanLawState> element_states) const {
  for (int k = 0; k < law.count; ++k) {
    element_states[k].x = LawState{.slider = elements.z[k].x,
                                   .accumulated_slip = elements.travel[k],
                                   .slip = elements.sliding[k] ? 1 : 0};
    element_states[k].y = LawState{.slider = elements.z[k].y, .slip = elements.at_stop[k] ? 1 : 0};
  }
}

namespace {

// Element k's pair in a flat LawState array (x at 2k, y at 2k + 1) as a PlanLawState and back.
PlanLawState PairAt(std::span<const LawState> flat, int k) {
  return {flat[2 * k], flat[2 * k + 1]};
}

}  // namespace

void PlanSeriesArrangement::UpdateFlat(PlanLawStateView committed,
                                       std::span<const LawState> committed_elements,
                                       const PlanLawInput& in, PlanLawStateSlot trial,
                                       std::span<LawState> trial_elements,
                                       PlanLawResponse* response) const {
  std::array<PlanLawState, kMaxSeriesElements> from{}, to{};
  for (int k = 0; k < law.count; ++k) from[k] = PairAt(committed_elements, k);
  Update(committed, std::span(from).first(law.count), in, trial, std::span(to).first(law.count),
         response);
  for (int k = 0; k < law.count; ++k) {
    trial_elements[2 * k] = to[k].x;
    trial_elements[2 * k + 1] = to[k].y;
  }
}

double PlanSeriesArrangement::StoredEnergyFlat(PlanLawStateView state,
                                               std::span<const LawState> elements) const {
  std::array<PlanLawState, kMaxSeriesElements> pairs{};
  for (int k = 0; k < law.count; ++k) pairs[k] = PairAt(elements, k);
  return StoredEnergy(state, std::span(pairs).first(law.count));
}

void PlanSeriesArrangement::Update(PlanLawStateView committed,
                                   std::span<const PlanLawState> committed_elements,
                                   const PlanLawInput& in, PlanLawStateSlot trial,
                                   std::span<PlanLawState> trial_elements,
                                   PlanLawResponse* response) const {
  const Step step =
      Solve(Displacement(committed), Force(committed), Gather(committed_elements), in.u);
  CoupledState next = Carried(committed);
  next.force = step.force;
  next.slider = {};
  for (int k = 0; k < law.count; ++k) next.slider = next.slider + step.elements.z[k];
  next.dissipated += step.dissipated;
  next.accumulated_slip += step.travel;
  next.slipping = step.sliding;
  Store(in, next, trial);
  Scatter(step.elements, trial_elements);
  response->force = step.force;
  response->stiffness = step.stiffness;
  response->damping = {};
}

double PlanSeriesArrangement::StoredEnergy(PlanLawStateView state,
                                           std::span<const PlanLawState> elements) const {
  const Vec2 f = Force(state);
  double energy = 0.5 * Dot(f, f) / law.ke;
  for (int k = 0; k < law.count; ++k) {
    const Vec2 z{elements[k].x.slider, elements[k].y.slider};
    energy += 0.5 * law.elements[k].stiffness * Dot(z, z);
  }
  return energy;
}

}  // namespace isolab::hysteresis
