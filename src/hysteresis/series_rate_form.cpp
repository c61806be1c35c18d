#include "isolab/hysteresis/series_rate_form.h"

#include <cmath>
#include <span>

namespace isolab::hysteresis {
namespace {

// The direction the sliding elements slide in, or 0 if none slides.
int Direction(const SeriesArrangement& law, const SeriesPhase& phase) {
  for (int k = 0; k < law.count; ++k) {
    if (phase.slip[k] != 0) return phase.slip[k];
  }
  return 0;
}

// Which stop an element stuck against it presses: +1, -1, or 0 (none).
int AgainstStop(const SeriesElement& e, double z) {
  return z == e.stop ? 1 : (z == -e.stop ? -1 : 0);
}

// u's force with the sliding elements on their surfaces and the stuck ones where they are:
// u = F / ke + sum_stuck z_k + sum_sliding (F - s f_k) / k_k.
double ForceOfDisplacement(const SeriesArrangement& law, const SeriesPhase& phase, double u,
                           const double* z) {
  double compliance = 1.0 / law.ke, rest = u;
  for (int k = 0; k < law.count; ++k) {
    const SeriesElement& e = law.elements[k];
    if (phase.slip[k] == 0) {
      rest -= z[k];
    } else {
      compliance += 1.0 / e.stiffness;
      rest += phase.slip[k] * e.strength / e.stiffness;
    }
  }
  return rest / compliance;
}

// Puts the sliding elements on their surfaces at the force u gives; then, as long as any does,
// starts the stuck elements whose friction that force has reached in the direction of motion and
// stops those beyond their stops: events that fall together (two equal surfaces, as a triple
// pendulum's inner ones) switch together, however the integrator reports them.
void Settle(const SeriesArrangement& law, double u, double v, SeriesPhaseSwitch* next) {
  for (int pass = 0; pass <= law.count; ++pass) {
    double force = law.ke * u;
    if (Direction(law, next->phase) != 0) {
      force = ForceOfDisplacement(law, next->phase, u, next->z.data());
      for (int k = 0; k < law.count; ++k) {
        const int slip = next->phase.slip[k];
        if (slip != 0) {
          next->z[k] = (force - slip * law.elements[k].strength) / law.elements[k].stiffness;
        }
      }
    } else {
      for (int k = 0; k < law.count; ++k) force -= law.ke * next->z[k];
    }
    bool changed = false;
    const int motion = v > 0.0 ? 1 : (v < 0.0 ? -1 : 0);
    for (int k = 0; k < law.count; ++k) {
      const SeriesElement& e = law.elements[k];
      const int slip = next->phase.slip[k];
      if (slip != 0 && slip * next->z[k] >= e.stop) {
        next->z[k] = slip * e.stop;
        next->phase.slip[k] = 0;
        changed = true;
      } else if (slip == 0 && motion != 0 && next->z[k] != motion * e.stop &&
                 motion * (force - e.stiffness * next->z[k]) >= e.strength) {
        next->phase.slip[k] = motion;
        changed = true;
      }
    }
    if (!changed) return;
  }
}

}  // namespace

SeriesRateResponse EvaluateSeriesRate(const SeriesArrangement& law, const SeriesPhase& phase,
                                      double u, double v, const double* z) {
  SeriesRateResponse r;
  const int s = Direction(law, phase);
  if (s == 0) {
    double sliders = 0.0;
    for (int k = 0; k < law.count; ++k) {
      sliders += z[k];
      r.force_z[k] = -law.ke;
    }
    r.force = law.ke * (u - sliders);
    r.force_u = law.ke;
    return r;
  }
  double compliance = 1.0 / law.ke;
  int first = -1;
  for (int k = 0; k < law.count; ++k) {
    if (phase.slip[k] == 0) continue;
    compliance += 1.0 / law.elements[k].stiffness;
    if (first < 0) first = k;
  }
  const SeriesElement& reference = law.elements[first];
  r.force = s * reference.strength + reference.stiffness * z[first];
  r.force_z[first] = reference.stiffness;
  for (int k = 0; k < law.count; ++k) {
    if (phase.slip[k] == 0) continue;
    r.rate_v[k] = 1.0 / (compliance * law.elements[k].stiffness);
    r.rate[k] = r.rate_v[k] * v;
    // s f dz/dt rather than f |dz/dt|: equal while the phase holds, smooth past its end.
    r.hysteretic_power += s * law.elements[k].strength * r.rate[k];
  }
  return r;
}

void SeriesPhaseRoots(const SeriesArrangement& law, const SeriesPhase& phase, double u, double v,
                      const double* z, double* roots) {
  const double force = EvaluateSeriesRate(law, phase, u, v, z).force;
  const int s = Direction(law, phase);
  for (int k = 0; k < law.count; ++k) {
    const SeriesElement& e = law.elements[k];
    if (phase.slip[k] != 0) {
      roots[k] = std::isinf(e.stop) ? 1.0 : e.stop - phase.slip[k] * z[k];
      continue;
    }
    const double friction = force - e.stiffness * z[k];
    const int stop = AgainstStop(e, z[k]);
    roots[k] = stop != 0 ? e.strength + stop * friction : e.strength - std::abs(friction);
  }
  roots[law.count] = s != 0 ? s * v : 1.0;
}

SeriesPhaseSwitch SwitchSeriesPhase(const SeriesArrangement& law, const SeriesPhase& phase,
                                    std::span<const int> roots_found, double u, double v,
                                    const double* z) {
  SeriesPhaseSwitch next{phase, {}};
  for (int k = 0; k < law.count; ++k) next.z[k] = z[k];
  const double force = EvaluateSeriesRate(law, phase, u, v, z).force;
  for (int k = 0; k < law.count; ++k) {
    if (roots_found[k] == 0) continue;
    const SeriesElement& e = law.elements[k];
    if (phase.slip[k] != 0) {  // it reached its stop
      next.z[k] = phase.slip[k] * e.stop;
      next.phase.slip[k] = 0;
      continue;
    }
    const int stop = AgainstStop(e, z[k]);
    const int direction = stop != 0 ? -stop : (force - e.stiffness * z[k] >= 0.0 ? 1 : -1);
    // One that touched its friction while the motion goes the other way stays stuck.
    if (direction * v > 0.0) next.phase.slip[k] = direction;
  }
  if (roots_found[law.count] != 0) {  // the motion reverses: every slider sticks where it is
    for (int k = 0; k < law.count; ++k) next.phase.slip[k] = 0;
  }
  Settle(law, u, v, &next);
  return next;
}

void SeriesRateFormState(const SeriesArrangement& law, const SeriesPhase& phase, double u, double v,
                         const double* z, std::span<LawState> block) {
  double sliders = 0.0;
  for (int k = 0; k < law.count; ++k) {
    sliders += z[k];
    block[k + 1] = LawState{.slider = z[k], .slip = phase.slip[k]};
  }
  block[0] = LawState{.u = u,
                      .v = v,
                      .force = EvaluateSeriesRate(law, phase, u, v, z).force,
                      .slider = sliders,
                      .slip = Direction(law, phase)};
}

}  // namespace isolab::hysteresis
