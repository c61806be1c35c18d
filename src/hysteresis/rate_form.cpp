#include "isolab/hysteresis/rate_form.h"

#include <cmath>
#include <stdexcept>
#include <type_traits>

#include "bearing_rate_form.h"

namespace isolab::hysteresis {
namespace {

double Sign(double x) { return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0); }

// The segment entered when `x` leaves `segment` (segment roots fall through zero only there).
int NextSegment(int segment, double x) { return segment != 0 ? 0 : (x >= 0.0 ? 1 : -1); }

// A phase with no slider (fs = 0) slips all the time; its direction plays no part.
LawPhase SliderRestPhase(double fs) { return {fs > 0.0 ? 0 : 1, 0}; }

// ---- THM1 family: z = u_h, force ke (u - u_h) = f_slider + g(u_h). ----

// u_h on the slip surface ke (u - u_h) - g(u_h) = s fs with g on `segment`'s branch.
double SeriesSlipSurface(const SeriesSlider& law, const LawPhase& phase, double u) {
  const double offset = law.spring.SegmentForce(0.0, phase.segment);
  return (law.ke * u - phase.slip * law.fs - offset) /
         (law.ke + law.spring.SegmentStiffness(phase.segment));
}

RateResponse Evaluate(const SeriesSlider& law, const LawPhase& phase, double u, double v,
                      double z) {
  RateResponse r;
  if (phase.slip == 0) {
    r.force = law.ke * (u - z);
    r.force_u = law.ke;
    r.force_z = -law.ke;
    return r;
  }
  const double kh = law.spring.SegmentStiffness(phase.segment);
  r.force = phase.slip * law.fs + law.spring.SegmentForce(z, phase.segment);
  r.force_z = kh;
  r.rate_v = law.ke / (law.ke + kh);  // d(ke (u - u_h) - g(u_h))/dt = 0 on the surface
  r.rate = r.rate_v * v;
  // s fs dz/dt rather than fs |dz/dt|: equal while the phase holds, and smooth past its end, so an
  // integrator that steps over the event and interpolates back does not see a kink.
  r.hysteretic_power = phase.slip * law.fs * r.rate;
  return r;
}

void Roots(const SeriesSlider& law, const LawPhase& phase, double u, double v, double z,
           double* roots) {
  if (law.fs == 0.0) {
    roots[0] = 1.0;
  } else if (phase.slip == 0) {
    roots[0] = law.fs - std::abs(law.ke * (u - z) - law.spring.SegmentForce(z, phase.segment));
  } else {
    roots[0] = phase.slip * v;
  }
  roots[1] = law.spring.SegmentMargin(z, phase.segment);
}

PhaseSwitch Switch(const SeriesSlider& law, const LawPhase& phase, int root, double u, double v,
                   double z) {
  PhaseSwitch next{phase, z};
  if (root == 0) {
    if (phase.slip == 0) {
      const int s =
          static_cast<int>(Sign(law.ke * (u - z) - law.spring.SegmentForce(z, phase.segment)));
      if (s * v <= 0.0) return next;  // touched fs while already unloading: still sticks
      next.phase.slip = s;
    } else {
      next.phase.slip = 0;
    }
  } else {
    next.phase.segment = NextSegment(phase.segment, z);
  }
  // The stuck slider keeps the position where slip ended (or began) exactly on the surface.
  const LawPhase surface{next.phase.slip != 0 ? next.phase.slip : phase.slip, next.phase.segment};
  if (surface.slip != 0) next.z = SeriesSlipSurface(law, surface, u);
  return next;
}

// ---- THM2 family: z = u_s, force kp (u - u_s) + g(u), |kp (u - u_s)| <= fs. ----

RateResponse Evaluate(const ParallelSlider& law, const LawPhase& phase, double u, double v,
                      double z) {
  RateResponse r;
  const double g = law.spring.SegmentForce(u, phase.segment);
  const double kh = law.spring.SegmentStiffness(phase.segment);
  if (phase.slip == 0) {
    r.force = law.kp * (u - z) + g;
    r.force_u = law.kp + kh;
    r.force_z = -law.kp;
    return r;
  }
  r.force = phase.slip * law.fs + g;
  r.force_u = kh;
  r.rate = v;
  r.rate_v = 1.0;
  r.hysteretic_power = phase.slip * law.fs * v;  // s fs v, smooth past the event as above
  return r;
}

void Roots(const ParallelSlider& law, const LawPhase& phase, double u, double v, double z,
           double* roots) {
  if (law.fs == 0.0) {
    roots[0] = 1.0;
  } else if (phase.slip == 0) {
    roots[0] = law.fs - std::abs(law.kp * (u - z));
  } else {
    roots[0] = phase.slip * v;
  }
  roots[1] = law.spring.SegmentMargin(u, phase.segment);
}

PhaseSwitch Switch(const ParallelSlider& law, const LawPhase& phase, int root, double u, double v,
                   double z) {
  PhaseSwitch next{phase, z};
  if (root == 1) {
    next.phase.segment = NextSegment(phase.segment, u);
    return next;
  }
  if (phase.slip == 0) {
    const int s = static_cast<int>(Sign(u - z));
    if (s * v <= 0.0) return next;
    next.phase.slip = s;
    next.z = u - s * law.fs / law.kp;
  } else {
    next.z = u - phase.slip * law.fs / law.kp;
    next.phase.slip = 0;
  }
  return next;
}

// ---- Elastic spring (one segment root), dashpot and Bouc-Wen (smooth, no roots). ----

RateResponse Evaluate(const ElasticSpring& law, const LawPhase& phase, double u, double, double) {
  RateResponse r;
  r.force = law.spring.SegmentForce(u, phase.segment);
  r.force_u = law.spring.SegmentStiffness(phase.segment);
  return r;
}

void Roots(const ElasticSpring& law, const LawPhase& phase, double u, double, double,
           double* roots) {
  roots[0] = law.spring.SegmentMargin(u, phase.segment);
}

PhaseSwitch Switch(const ElasticSpring&, const LawPhase& phase, int, double u, double, double z) {
  return {{phase.slip, NextSegment(phase.segment, u)}, z};
}

RateResponse Evaluate(const Dashpot& law, const LawPhase&, double, double v, double) {
  RateResponse r;
  r.force = law.c * v;
  r.force_v = law.c;
  r.viscous_power = law.c * v * v;
  return r;
}

// dz/dt = v g(z, sign v): |v| makes it continuous (not smooth) at reversals, which is how the law
// is defined; no event is needed for a continuous right-hand side.
RateResponse Evaluate(const BoucWen& law, const LawPhase&, double, double v, double z) {
  RateResponse r;
  const double s = v < 0.0 ? -1.0 : 1.0;
  r.force = z;
  r.force_z = 1.0;
  r.rate_v = law.Slope(z, s);
  r.rate = v * r.rate_v;
  r.rate_z = v * law.SlopeDerivative(z, s);
  // Work rate z v less the rate of the stored z^2 / (2 alpha).
  r.hysteretic_power = z * v - z * r.rate / law.alpha;
  return r;
}

void Roots(const Dashpot&, const LawPhase&, double, double, double, double*) {}
void Roots(const BoucWen&, const LawPhase&, double, double, double, double*) {}
PhaseSwitch Switch(const Dashpot&, const LawPhase& phase, int, double, double, double z) {
  return {phase, z};
}
PhaseSwitch Switch(const BoucWen&, const LawPhase& phase, int, double, double, double z) {
  return {phase, z};
}

// The degrading law has two internal variables (slider and accumulated slip) and the play
// sliders a clearance, and neither has a rate form yet; sliders in series have one of their own
// (series_rate_form.h), with a variable per element. HasRateForm keeps them all away from this
// contract, so these are never reached.
template <class Law>
concept WithoutRateContract = std::is_same_v<Law, DegradingSlider> ||
    std::is_same_v<Law, SeriesArrangement> || std::is_same_v<Law, PlaySlider>;

template <class Law>
[[noreturn]] void NoRateForm() {
  throw std::logic_error(std::is_same_v<Law, SeriesArrangement>
                             ? "sliders in series take series_rate_form.h (HasRateForm is false)"
                             : "the law has no rate form (HasRateForm is false)");
}
template <class Law>
requires WithoutRateContract<Law> RateResponse Evaluate(const Law&, const LawPhase&, double, double,
                                                        double) {
  NoRateForm<Law>();
}
template <class Law>
requires WithoutRateContract<Law>
void Roots(const Law&, const LawPhase&, double, double, double, double*) { NoRateForm<Law>(); }
template <class Law>
requires WithoutRateContract<Law> PhaseSwitch Switch(const Law&, const LawPhase&, int, double,
                                                     double, double) {
  NoRateForm<Law>();
}

}  // namespace

bool HasRateForm(const LawKernel& kernel) {
  return !std::holds_alternative<DegradingSlider>(kernel) &&
         !std::holds_alternative<SeriesArrangement>(kernel) &&
         !std::holds_alternative<PlaySlider>(kernel);
}

int InternalVariableCount(const LawKernel& kernel) {
  if (std::holds_alternative<ElasticSpring>(kernel) || std::holds_alternative<Dashpot>(kernel) ||
      std::holds_alternative<SeriesArrangement>(kernel)) {
    return 0;
  }
  if (const auto* law = std::get_if<LeadRubber>(&kernel)) return law->heating.heats() ? 2 : 1;
  return 1;
}

int PhaseRootCount(const LawKernel& kernel) {
  if (std::holds_alternative<SeriesSlider>(kernel) ||
      std::holds_alternative<ParallelSlider>(kernel) ||
      std::holds_alternative<FrictionPendulum>(kernel)) {
    return 2;
  }
  return std::holds_alternative<ElasticSpring>(kernel) || std::holds_alternative<LeadRubber>(kernel)
             ? 1
             : 0;
}

LawPhase RestPhase(const LawKernel& kernel) {
  if (const auto* law = std::get_if<SeriesSlider>(&kernel)) return SliderRestPhase(law->fs);
  if (const auto* law = std::get_if<ParallelSlider>(&kernel)) return SliderRestPhase(law->fs);
  return {};
}

RateResponse EvaluateRate(const LawKernel& kernel, const LawPhase& phase, double u, double v,
                          double z, double w, double t) {
  return std::visit(
      [&](const auto& law) {
        if constexpr (std::is_same_v<std::decay_t<decltype(law)>, LeadRubber>) {
          return Evaluate(law, phase, u, v, z, w, t);
        } else {
          return Evaluate(law, phase, u, v, z);
        }
      },
      kernel);
}

void PhaseRoots(const LawKernel& kernel, const LawPhase& phase, double u, double v, double z,
                double* roots) {
  std::visit([&](const auto& law) { Roots(law, phase, u, v, z, roots); }, kernel);
}

PhaseSwitch SwitchPhase(const LawKernel& kernel, const LawPhase& phase, int root, double u,
                        double v, double z) {
  return std::visit([&](const auto& law) { return Switch(law, phase, root, u, v, z); }, kernel);
}

LawState RateFormState(const LawKernel& kernel, const LawPhase& phase, double u, double v, double z,
                       double w, double t) {
  LawState state;
  state.u = u;
  state.v = v;
  state.t = t;
  state.force = EvaluateRate(kernel, phase, u, v, z, w, t).force;
  if (std::holds_alternative<SeriesSlider>(kernel) ||
      std::holds_alternative<ParallelSlider>(kernel) ||
      std::holds_alternative<FrictionPendulum>(kernel) ||
      std::holds_alternative<LeadRubber>(kernel)) {
    state.slider = z;
    state.slip = phase.slip;
  }
  if (std::holds_alternative<LeadRubber>(kernel)) state.temperature = w;
  return state;
}

}  // namespace isolab::hysteresis
