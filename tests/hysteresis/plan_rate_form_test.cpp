// The plan rate forms (plan_rate_form.h): their partial derivatives are the derivatives of what
// they compute, in every phase; marched with their own events (a Runge-Kutta march whose steps end
// where a root falls through zero, as IDA's root finder does) they reproduce the incremental laws
// along any line through the origin, and on a circular orbit the continuous closed form
// 2 pi fs sqrt(R^2 - u_y^2) to which the incremental laws converge at first order; a stick root
// reached while unloading leaves the slider stuck and a switch puts it on its surface; the
// uncoupled pair is the two 1-D rate forms.
#include "isolab/hysteresis/plan_rate_form.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "isolab/hysteresis/radial_spring.h"
#include "plan_law_cases.h"

namespace isolab::hysteresis {
namespace {

using testing::Math;
using testing::PlanLawCase;
using testing::PlanLawCases;

constexpr double kPi = std::numbers::pi;

// ---- Partial derivatives. ----

struct Probe {
  PlanLawPhase phase;
  Vec2 u, v;
  PlanInternalVariables q;
  double t;
};

// Whether the law has a spring g with a breakpoint (a second segment to probe).
bool HasBreakpoint(const PlanLawKernel& kernel) {
  if (const auto* law = std::get_if<PlanSeriesSlider>(&kernel))
    return std::isfinite(law->law.spring.uc);
  if (const auto* law = std::get_if<PlanParallelSlider>(&kernel)) {
    return std::isfinite(law->law.spring.uc);
  }
  if (const auto* law = std::get_if<PlanElasticSpring>(&kernel))
    return std::isfinite(law->law.spring.uc);
  return std::holds_alternative<UncoupledPair>(kernel);  // its laws' own phases
}

// Points in every phase of a law (the rate form is evaluated off its surfaces too, inside the
// integrator's Newton iteration, so generic points serve).
std::vector<Probe> ProbesOf(const PlanLawKernel& kernel, double scale) {
  const int n = PlanInternalVariableCount(kernel);
  std::vector<Probe> probes;
  const std::vector<Vec2> us = {{0.7 * scale, -0.4 * scale}, {-0.2 * scale, 0.9 * scale}};
  const std::vector<Vec2> vs = {{300.0, 120.0}, {-40.0, 250.0}};
  for (int slip = 0; slip <= 1; ++slip) {
    for (int segment = 0; segment <= (HasBreakpoint(kernel) ? 1 : 0); ++segment) {
      for (std::size_t k = 0; k < us.size(); ++k) {
        Probe p;
        p.phase = PlanRestPhase(kernel);
        p.phase.slip = slip;
        p.phase.segment = segment;
        p.phase.direction = {0.6, -0.8};
        p.u = us[k];
        p.v = vs[k];
        p.t = 1.5;
        // Internal variables near u (sliders), of the force's size (Bouc-Wen), a temperature.
        const double offsets[] = {0.61 * scale, -0.23 * scale, 35.0, 0.1 * scale};
        for (int i = 0; i < n; ++i)
          p.q[i] = offsets[i] + (i < 2 ? 0.5 * (i == 0 ? p.u.x : p.u.y) : 0.0);
        if (std::holds_alternative<PlanBoucWen>(kernel)) {
          p.q[0] = 3.0 * (k + 1);
          p.q[1] = -2.0;
        }
        if (std::holds_alternative<UncoupledPair>(kernel)) {
          p.phase.along_x.slip = slip;
          p.phase.along_x.segment = segment;
          p.phase.along_y.slip = -slip;
          p.phase.along_y.segment = 1 - segment;
        }
        probes.push_back(p);
      }
    }
  }
  return probes;
}

// Value vector [force, rate(n)] and its derivative in one input.
std::vector<double> Values(const PlanRateResponse& r, int n) {
  std::vector<double> values{r.force.x, r.force.y};
  for (int i = 0; i < n; ++i) values.push_back(r.rate[i]);
  return values;
}

void ExpectJacobianMatchesFiniteDifferences(const PlanLawKernel& kernel, const Probe& p,
                                            double scale, const std::string& name) {
  const int n = PlanInternalVariableCount(kernel);
  const PlanRateResponse r = EvaluatePlanRate(kernel, p.phase, p.u, p.v, p.q.data(), p.t);
  // Input j: 0, 1 = u; 2, 3 = v; 4.. = q. Analytic column j of d [force; rate] / d input.
  const auto analytic = [&](int row, int j) {
    if (row < 2) {
      const Mat2& m = j < 2 ? r.force_u : r.force_v;
      if (j < 4) return (row == 0 ? (j % 2 == 0 ? m.xx : m.xy) : (j % 2 == 0 ? m.yx : m.yy));
      return r.force_q[row][j - 4];
    }
    const int k = row - 2;
    if (j < 2) return r.rate_u[k][j];
    if (j < 4) return r.rate_v[k][j - 2];
    return r.rate_q[k][j - 4];
  };
  for (int j = 0; j < 4 + n; ++j) {
    Probe plus = p, minus = p;
    double h = 0.0;
    if (j < 2) {
      h = 1e-6 * scale;
      (j == 0 ? plus.u.x : plus.u.y) += h;
      (j == 0 ? minus.u.x : minus.u.y) -= h;
    } else if (j < 4) {
      h = 1e-6 * (1.0 + Norm(p.v));
      (j == 2 ? plus.v.x : plus.v.y) += h;
      (j == 2 ? minus.v.x : minus.v.y) -= h;
    } else {
      h = 1e-6 * (1.0 + std::abs(p.q[j - 4]));
      plus.q[j - 4] += h;
      minus.q[j - 4] -= h;
    }
    const auto a =
        Values(EvaluatePlanRate(kernel, plus.phase, plus.u, plus.v, plus.q.data(), p.t), n);
    const auto b =
        Values(EvaluatePlanRate(kernel, minus.phase, minus.u, minus.v, minus.q.data(), p.t), n);
    double column_scale = 0.0;
    std::vector<double> numeric(a.size());
    for (std::size_t row = 0; row < a.size(); ++row) {
      numeric[row] = (a[row] - b[row]) / (2 * h);
      column_scale = std::max(column_scale, std::abs(numeric[row]));
    }
    for (std::size_t row = 0; row < a.size(); ++row) {
      EXPECT_NEAR(analytic(static_cast<int>(row), j), numeric[row],
                  1e-6 * std::abs(numeric[row]) + 1e-8 * column_scale + 1e-12)
          << name << " phase (" << p.phase.slip << ", " << p.phase.segment << ") at u = (" << p.u.x
          << ", " << p.u.y << "): d row " << row << " / d input " << j;
    }
  }
}

TEST(PlanRateForm, PartialDerivativesMatchFiniteDifferencesInEveryPhase) {
  for (const PlanLawCase& c : PlanLawCases()) {
    const PlanLawKernel kernel = c.plan();
    for (const Probe& p : ProbesOf(kernel, c.scale)) {
      ExpectJacobianMatchesFiniteDifferences(kernel, p, c.scale, c.name);
    }
  }
  // Uncoupled pairs, 1-D laws with two internal variables and with none.
  const PlanLawKernel pair = UncoupledKernel(
      Math(LawType::kLeadRubber, {60, 1, 6, 100, 200, 1.456e-3, 0.05, 14.1, 60, NAN}),
      Math(LawType::kThm1, {1, 0.2, 0.45, 20, 120}));
  ASSERT_EQ(PlanInternalVariableCount(pair), 3);
  for (const Probe& p : ProbesOf(pair, 100.0)) {
    ExpectJacobianMatchesFiniteDifferences(pair, p, 100.0, "pair");
  }
}

// ---- Marching the rate form with its own events. ----

struct PathPoint {
  Vec2 u, v;
};
using Path = std::function<PathPoint(double)>;

class PlanRateMarch {
 public:
  explicit PlanRateMarch(const PlanLawKernel& kernel)
      : kernel_(kernel),
        phase_(PlanRestPhase(kernel)),
        n_(PlanInternalVariableCount(kernel)),
        roots_(PlanPhaseRootCount(kernel)) {}

  // From time t_ to `end` along `path` in Runge-Kutta steps of at most `step`, each ending where
  // a root falls through zero (bisected to round-off), the phase switched there.
  void MoveTo(const Path& path, double end, double step) {
    const double steps = std::ceil((end - t_) / step);
    for (int guard = 0; t_ < end; ++guard) {
      if (guard > steps + 1000) {  // every step ends at an event or a full step
        ADD_FAILURE() << "the march stalled at t = " << t_;
        return;
      }
      const double h = std::min(step, end - t_);
      double fraction = 1.0;
      if (Crossed(path, h)) {
        double low = 0.0, high = 1.0;
        for (int i = 0; i < 200 && high - low > 1e-16; ++i) {
          const double mid = 0.5 * (low + high);
          (Crossed(path, mid * h) ? high : low) = mid;
        }
        fraction = high;
      }
      double before[kMaxPlanPhaseRoots];
      const PathPoint a = path(t_);
      PlanPhaseRoots(kernel_, phase_, a.u, a.v, q_.data(), before);
      Advance(path, fraction * h);
      if (fraction < 1.0 || Crossed(before, path)) Switch(path, before);
    }
  }

  Vec2 Force(const Path& path) const {
    const PathPoint at = path(t_);
    return EvaluatePlanRate(kernel_, phase_, at.u, at.v, q_.data(), t_).force;
  }
  double dissipated() const { return dissipated_; }
  const PlanInternalVariables& q() const { return q_; }

 private:
  struct State {
    PlanInternalVariables q;
    double energy;
  };
  State Rate(const Path& path, double t, const State& s) const {
    const PathPoint at = path(t);
    const PlanRateResponse r = EvaluatePlanRate(kernel_, phase_, at.u, at.v, s.q.data(), t);
    return {r.rate, r.hysteretic_power};
  }
  State Step(const Path& path, double h) const {
    const State s0{q_, dissipated_};
    const auto add = [&](const State& s, const State& k, double f) {
      State out = s;
      for (int i = 0; i < n_; ++i) out.q[i] += f * k.q[i];
      out.energy += f * k.energy;
      return out;
    };
    const State k1 = Rate(path, t_, s0);
    const State k2 = Rate(path, t_ + h / 2, add(s0, k1, h / 2));
    const State k3 = Rate(path, t_ + h / 2, add(s0, k2, h / 2));
    const State k4 = Rate(path, t_ + h, add(s0, k3, h));
    State s1 = s0;
    for (int i = 0; i < n_; ++i) s1.q[i] += h / 6 * (k1.q[i] + 2 * k2.q[i] + 2 * k3.q[i] + k4.q[i]);
    s1.energy += h / 6 * (k1.energy + 2 * k2.energy + 2 * k3.energy + k4.energy);
    return s1;
  }
  bool Crossed(const Path& path, double h) const {
    double before[kMaxPlanPhaseRoots], after[kMaxPlanPhaseRoots];
    const PathPoint a = path(t_), b = path(t_ + h);
    PlanPhaseRoots(kernel_, phase_, a.u, a.v, q_.data(), before);
    PlanPhaseRoots(kernel_, phase_, b.u, b.v, Step(path, h).q.data(), after);
    for (int r = 0; r < roots_; ++r) {
      if (before[r] > 0.0 && after[r] <= 0.0) return true;
    }
    return false;
  }
  bool Crossed(const double* before, const Path& path) const {
    double after[kMaxPlanPhaseRoots];
    const PathPoint b = path(t_);
    PlanPhaseRoots(kernel_, phase_, b.u, b.v, q_.data(), after);
    for (int r = 0; r < roots_; ++r) {
      if (before[r] > 0.0 && after[r] <= 0.0) return true;
    }
    return false;
  }
  void Advance(const Path& path, double h) {
    const State s = Step(path, h);
    q_ = s.q;
    dissipated_ = s.energy;
    t_ += h;
  }
  // Every root that fell through zero, then (as RateFormSystem::SwitchPhases) any other the
  // switch left below zero; a root just switched is not switched back for a margin of round-off.
  void Switch(const Path& path, const double* before) {
    const PathPoint at = path(t_);
    double after[kMaxPlanPhaseRoots];
    PlanPhaseRoots(kernel_, phase_, at.u, at.v, q_.data(), after);
    bool switched[kMaxPlanPhaseRoots] = {};
    for (int r = 0; r < roots_; ++r) {
      if (before[r] > 0.0 && after[r] <= 0.0) switched[r] = Apply(r, at);
    }
    for (int pass = 0; pass < 2 * kMaxPlanPhaseRoots; ++pass) {
      PlanPhaseRoots(kernel_, phase_, at.u, at.v, q_.data(), after);
      int below = -1;
      for (int r = 0; r < roots_ && below < 0; ++r) {
        if (after[r] < 0.0 && !switched[r]) below = r;
      }
      if (below < 0 || !(switched[below] = Apply(below, at))) break;
    }
  }
  bool Apply(int root, const PathPoint& at) {
    const PlanPhaseSwitch next = SwitchPlanPhase(kernel_, phase_, root, at.u, at.v, q_.data());
    const bool changed = !(next.phase == phase_);
    phase_ = next.phase;
    q_ = next.q;
    return changed;
  }

  const PlanLawKernel& kernel_;
  PlanLawPhase phase_;
  int n_, roots_;
  PlanInternalVariables q_{};
  double t_ = 0.0, dissipated_ = 0.0;
};

// The 1-D rate-form test's growing, reversing sine along direction d: v linear between samples,
// u its exact integral, so u peaks exactly where v changes sign.
struct LinePath {
  std::vector<double> u, v;
  double dt;
  Vec2 d;
  PathPoint operator()(double t) const {
    const int k = std::min(static_cast<int>(t / dt), static_cast<int>(u.size()) - 2);
    const double s = t / dt - k;
    const double along = u[k] + dt * s * (v[k] + 0.5 * s * (v[k + 1] - v[k]));
    return {along * d, (v[k] + s * (v[k + 1] - v[k])) * d};
  }
};
LinePath GrowingSine(double amplitude, Vec2 d) {
  LinePath path{{0.0}, {0.0}, 1.0 / 4000, d};
  const double w = 2 * kPi * 3;
  for (int k = 1; k <= 4000; ++k) {
    const double t = k * path.dt;
    const double v = amplitude * (std::sin(w * t) + t * w * std::cos(w * t));
    path.u.push_back(path.u.back() + 0.5 * path.dt * (path.v.back() + v));
    path.v.push_back(v);
  }
  return path;
}

bool PiecewiseLinearOnLines(const PlanLawKernel& kernel) {
  return !std::holds_alternative<PlanBoucWen>(kernel);  // Bouc-Wen's update is trapezoidal
}

TEST(PlanRateForm, MarchedRateFormReproducesTheIncrementalLawAlongAnyLine) {
  for (const PlanLawCase& c : PlanLawCases()) {
    const PlanLawKernel kernel = c.plan();
    if (!PiecewiseLinearOnLines(kernel)) continue;
    for (const double degrees : {0.0, 57.0, 200.0}) {
      const Vec2 d{std::cos(degrees * kPi / 180), std::sin(degrees * kPi / 180)};
      const LinePath line = GrowingSine(c.scale, d);
      const Path path = [&line](double t) { return line(t); };
      PlanRateMarch march(kernel);
      PlanLawState committed, trial;
      PlanLawResponse response;
      double worst = 0.0, scale = 0.0;
      for (std::size_t k = 1; k < line.u.size(); ++k) {
        march.MoveTo(path, k * line.dt, line.dt / 4);
        // The incremental law sees only end points: give it the displacement peak inside a step.
        if (line.v[k - 1] * line.v[k] < 0.0) {
          const double peak = (k - 1 + line.v[k - 1] / (line.v[k - 1] - line.v[k])) * line.dt;
          UpdatePlanLaw(kernel, committed, {line(peak).u, {}, peak}, &trial, &response);
          committed = trial;
        }
        const PathPoint at = line(k * line.dt);
        UpdatePlanLaw(kernel, committed, {at.u, at.v, k * line.dt}, &trial, &response);
        committed = trial;
        worst = std::max(worst, Norm(march.Force(path) - response.force));
        scale = std::max(scale, Norm(response.force));
      }
      // The heated lead core's temperature is integrated by Runge-Kutta, not exactly.
      const double tolerance = c.name.find("lead_rubber_") == 0 ? 1e-7 : 1e-9;
      EXPECT_LT(worst, tolerance * scale)
          << c.name << " at " << degrees << " deg: largest force difference " << worst;
    }
  }
}

// ---- The circular orbit (circular_orbit_test.cpp for the incremental laws). ----

// From rest onto the circle u = R e(omega t) along a spiral whose radius grows smoothly (r = R
// (3 s^2 - 2 s^3), s = t / ramp) over the first `ramp` seconds: the velocity stays continuous,
// as a structure's does (a velocity that jumps can end a slip where loading only pauses).
Path OntoCircle(double radius, double omega, double ramp) {
  return [=](double t) {
    const Vec2 e{std::cos(omega * t), std::sin(omega * t)};
    const double s = std::min(t / ramp, 1.0);
    const double r = radius * s * s * (3 - 2 * s);
    const double dr = t < ramp ? radius * 6 * s * (1 - s) / ramp : 0.0;
    return PathPoint{r * e, dr * e + (r * omega) * Perpendicular(e)};
  };
}

TEST(PlanRateForm, OnACircularOrbitItDissipatesTheContinuousClosedForm) {
  struct Case {
    const char* name;
    LawParameters law;
    double radius;
  };
  const std::vector<Case> cases = {
      {"bhm2", Math(LawType::kBhm2, {10, 1, 1}), 100},
      {"thm2", Math(LawType::kThm2, {1, 0.2, 0.45, 20, 120}), 300},
      {"thm1", Math(LawType::kThm1, {1, 0.2, 0.45, 20, 120}), 300},
      {"friction_pendulum",
       Math(LawType::kFrictionPendulum, {1000, 2000, 1, NAN, 0.03, 0.09, 0.02}), 150},
      {"bouc_wen", Math(LawType::kBoucWen, {1.0, 0.05, 0.5, 0.5, 1.0}), 200},
  };
  const double omega = 2 * kPi / 3;
  for (const Case& c : cases) {
    const PlanLawKernel kernel = CoupledKernel(c.law);
    // The slider's strength and the link length at which it slips (series: ke x + g(x) across).
    double strength = 0.0, per_revolution = 0.0;
    if (const auto* p = std::get_if<PlanParallelSlider>(&kernel)) {
      const double uy = p->law.fs / p->law.kp;
      strength = p->law.fs;
      per_revolution = 2 * kPi * strength * std::sqrt(c.radius * c.radius - uy * uy);
    } else if (const auto* s = std::get_if<PlanSeriesSlider>(&kernel)) {
      const double kr = s->law.ke * c.radius, fs = s->law.fs;
      double slope = 0.0;
      per_revolution = 2 * kPi * fs *
                       s->law.spring.SolveInSeries(s->law.ke, std::sqrt(kr * kr - fs * fs), &slope);
    } else if (const auto* f = std::get_if<PlanFrictionPendulum>(&kernel)) {
      const double uy = f->law.slider.uy;
      per_revolution = 2 * kPi * f->law.Friction(c.radius * omega) * f->law.weight *
                       std::sqrt(c.radius * c.radius - uy * uy);
    } else {
      const BoucWen& b = std::get<PlanBoucWen>(kernel).law;
      const double z = std::pow(b.alpha / (b.beta * (b.gamma + b.delta)), 1 / b.nu);
      per_revolution = 2 * kPi * z * std::sqrt(c.radius * c.radius - (z / b.alpha) * (z / b.alpha));
    }
    const double period = 2 * kPi / omega, step = period / 4000;
    const Path path = OntoCircle(c.radius, omega, period);
    PlanRateMarch march(kernel);
    march.MoveTo(path, 3 * period, step);
    const double before = march.dissipated();
    march.MoveTo(path, 4 * period, step);
    EXPECT_NEAR(march.dissipated() - before, per_revolution, 1e-8 * per_revolution) << c.name;
  }
}

// ---- Curved paths: stick and slip events off the axes. ----

// Along the Lissajous figure the incremental laws (straight increments, backward Euler) and the
// rate form (the continuous law, Runge-Kutta) converge to one solution: their force difference
// falls at first order in the increment (at second or better for Bouc-Wen's trapezoidal update;
// measured 2.6 and 2.0).
TEST(PlanRateForm, IncrementalLawConvergesToTheMarchedRateFormOnCurvedPaths) {
  for (const PlanLawCase& c : PlanLawCases()) {
    if (c.name != "bhm2" && c.name != "thm1_hard" && c.name != "thm2_soft" &&
        c.name != "friction_pendulum_mu_of_v" && c.name != "lead_rubber_heated" &&
        c.name != "bouc_wen") {
      continue;
    }
    const PlanLawKernel kernel = c.plan();
    const Path path = [&c](double t) {
      const testing::PlanPathPoint at = testing::Lissajous(c.scale, t);
      return PathPoint{at.u, at.v};
    };
    const double duration = testing::kLissajousDuration;
    // The rate form at the sample times of the coarsest increments.
    const int samples = 100;
    std::vector<Vec2> reference;
    PlanRateMarch march(kernel);
    for (int k = 1; k <= samples; ++k) {
      march.MoveTo(path, duration * k / samples, duration / 20000);
      reference.push_back(march.Force(path));
    }
    std::vector<double> differences;
    double scale = 0.0;
    for (const int per_sample : {20, 40, 80}) {
      PlanLawState committed, trial;
      PlanLawResponse response;
      double worst = 0.0;
      for (int k = 1; k <= samples * per_sample; ++k) {
        const double t = duration * k / (samples * per_sample);
        const PathPoint at = path(t);
        UpdatePlanLaw(kernel, committed, {at.u, at.v, t}, &trial, &response);
        committed = trial;
        if (k % per_sample == 0) {
          worst = std::max(worst, Norm(response.force - reference[k / per_sample - 1]));
          scale = std::max(scale, Norm(response.force));
        }
      }
      differences.push_back(worst);
    }
    // At least the order, and for the sliders (backward Euler) no more.
    const double order = c.name == "bouc_wen" ? 2.0 : 1.0;
    for (std::size_t i = 1; i < differences.size(); ++i) {
      const double measured = std::log2(differences[i - 1] / differences[i]);
      EXPECT_GT(measured, order - 0.2)
          << c.name << ": " << differences[i - 1] << " then " << differences[i];
      if (order == 1.0) {
        EXPECT_LT(measured, 1.2) << c.name;
      }
    }
    EXPECT_LT(differences.back(), 0.02 * scale) << c.name;
  }
}

// ---- Switches. ----

TEST(PlanRateForm, StickRootReachedWhileUnloadingKeepsTheSliderStuckAndSlipStartsOnTheSurface) {
  const PlanLawKernel thm1 = CoupledKernel(Math(LawType::kThm1, {1, 0.2, 0.45, 20, 120}));
  const PlanLawKernel bhm2 = CoupledKernel(Math(LawType::kBhm2, {10, 1, 1}));
  const Vec2 n{0.6, 0.8};
  // THM1 from x = 0: slider force ke u = fs n reached at u = 20 n (ke = 1, fs = 20), a hair past.
  const PlanInternalVariables rest{};
  const Vec2 u = (20.0 + 1e-9) * n;
  EXPECT_EQ(SwitchPlanPhase(thm1, PlanRestPhase(thm1), 0, u, -1.0 * n, rest.data()).phase.slip, 0);
  const PlanPhaseSwitch slip =
      SwitchPlanPhase(thm1, PlanRestPhase(thm1), 0, u, n + Vec2{0.3, -0.1}, rest.data());
  ASSERT_EQ(slip.phase.slip, 1);
  const Vec2 x{slip.q[0], slip.q[1]};
  const SeriesSlider& law = std::get<PlanSeriesSlider>(thm1).law;
  const Vec2 slider_force = law.ke * (u - x) - RadialForce(law.spring, x);
  EXPECT_NEAR(Norm(slider_force), law.fs, 1e-12 * law.fs);
  EXPECT_NEAR(Dot(slider_force, n), law.fs, 1e-12 * law.fs);  // along its direction at the switch
  // BHM2: link of reach fs / kp = 1 reached at |u| = 1.
  const Vec2 w = (1.0 + 1e-12) * n;
  EXPECT_EQ(SwitchPlanPhase(bhm2, PlanRestPhase(bhm2), 0, w, {-0.8, 0.6}, rest.data()).phase.slip,
            0);  // v across the link: n . v = 0, not loading
  const PlanPhaseSwitch start = SwitchPlanPhase(bhm2, PlanRestPhase(bhm2), 0, w, n, rest.data());
  EXPECT_EQ(start.phase.slip, 1);
  EXPECT_NEAR(Norm(w - Vec2{start.q[0], start.q[1]}), 1.0, 1e-15);
  // Slip ends where loading stops: back to stick, slider on the surface.
  const PlanPhaseSwitch end = SwitchPlanPhase(bhm2, start.phase, 0, w, {-0.8, 0.6}, start.q.data());
  EXPECT_EQ(end.phase.slip, 0);
  EXPECT_NEAR(Norm(w - Vec2{end.q[0], end.q[1]}), 1.0, 1e-15);
}

TEST(PlanRateForm, UncoupledPairIsTheTwoOneDirectionRateForms) {
  const LawParameters lx =
      Math(LawType::kLeadRubber, {60, 1, 6, 100, 200, 1.456e-3, NAN, NAN, NAN, NAN});
  const LawParameters ly = Math(LawType::kThm2, {1, 0.2, 0.05, 20, 120});
  const PlanLawKernel pair = UncoupledKernel(lx, ly);
  const LawKernel kx = lx.Kernel(), ky = ly.Kernel();
  ASSERT_EQ(PlanInternalVariableCount(pair), 3);
  ASSERT_EQ(PlanPhaseRootCount(pair), 3);
  PlanLawPhase phase = PlanRestPhase(pair);
  phase.along_x.slip = 1;
  phase.along_y.segment = 1;
  const double q[] = {3.0, 12.0, 40.0};
  const Vec2 u{9.0, 150.0}, v{5.0, -7.0};
  const PlanRateResponse r = EvaluatePlanRate(pair, phase, u, v, q, 0.7);
  const RateResponse rx = EvaluateRate(kx, phase.along_x, u.x, v.x, q[0], q[1], 0.7);
  const RateResponse ry = EvaluateRate(ky, phase.along_y, u.y, v.y, q[2], 0.0, 0.7);
  EXPECT_EQ(r.force.x, rx.force);
  EXPECT_EQ(r.force.y, ry.force);
  EXPECT_EQ(r.rate[0], rx.rate);
  EXPECT_EQ(r.rate[1], rx.w_rate);
  EXPECT_EQ(r.rate[2], ry.rate);
  EXPECT_EQ(r.force_q[0][1], rx.force_w);
  EXPECT_EQ(r.force_q[1][2], ry.force_z);
  EXPECT_EQ(r.hysteretic_power, rx.hysteretic_power + ry.hysteretic_power);
  double roots[kMaxPlanPhaseRoots], one[kMaxPhaseRoots];
  PlanPhaseRoots(pair, phase, u, v, q, roots);
  PhaseRoots(ky, phase.along_y, u.y, v.y, q[2], one);
  EXPECT_EQ(roots[1], one[0]);
  EXPECT_EQ(roots[2], one[1]);
  const PlanPhaseSwitch next = SwitchPlanPhase(pair, phase, 2, u, v, q);
  const PhaseSwitch expected = SwitchPhase(ky, phase.along_y, 1, u.y, v.y, q[2]);
  EXPECT_EQ(next.phase.along_y, expected.phase);
  EXPECT_EQ(next.q[2], expected.z);
  EXPECT_EQ(next.q[1], q[1]);
}

}  // namespace
}  // namespace isolab::hysteresis
