// Sliders in series in plan, in rate form (plan_series_rate_form.h): every partial derivative
// against central differences in each mode of an element; marched along a line, the 1-D law to
// round-off; marched round a circle, the closed form of steady circular sliding
// (plan_series_arrangement_test.cpp derives it), which the continuous rate form reaches as its
// steps shrink, not at the backward Euler's first order.
#include "isolab/hysteresis/plan_series_rate_form.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "isolab/hysteresis/law_parameters.h"
#include "series_law_harness.h"

namespace isolab::hysteresis {
namespace {

constexpr double kPi = std::numbers::pi;

SeriesArrangement Triple() {
  return std::get<SeriesArrangement>(
      LawParameters::Make(LawType::kTripleFrictionPendulum, ParameterForm::kMathematical,
                          std::vector<double>{1000, 2100, 280, 280, 2100, 0.06, 0.02, 0.02, 0.10,
                                              400, 50, 50, 400, 0.5})
          .Kernel());
}

TEST(PlanSeriesRateForm, PartialDerivativesMatchFiniteDifferences) {
  const SeriesArrangement law = Triple();
  using M = RingMode;
  struct Probe {
    PlanSeriesPhase phase;
    Vec2 u, v;
    std::array<double, 8> q;
  };
  const std::vector<Probe> probes = {
      {{{M::kStuck, M::kStuck, M::kStuck, M::kStuck}, {}},
       {3, 1},
       {2, -1},
       {0, 0, 0.5, 0.2, 0.5, 0.2, 0, 0}},
      {{{M::kStuck, M::kSliding, M::kSliding, M::kStuck}, {}},
       {30, 12},
       {2, 1.5},
       {0, 0, 6, 2.5, 6, 2.5, 0, 0}},
      {{{M::kSliding, M::kSliding, M::kSliding, M::kSliding}, {}},
       {300, -120},
       {-1, 3},
       {150, -60, 25, -9, 24, -11, 90, -30}},
      {{{M::kSlidingOnRing, M::kSliding, M::kSliding, M::kStuckOnRing}, {1, 0, 0, 0}},
       {700, 250},
       {-2, 4},
       {320, 135, 40, 20, 41, 19, 300, 175}},
      {{{M::kSlidingOnRing, M::kSliding, M::kStuck, M::kSlidingOnRing}, {-1, 0, 0, 1}},
       {-650, 380},
       {3, 2},
       {-290, 190, -60, 45, -55, 40, -280, 215}},
  };
  for (std::size_t i = 0; i < probes.size(); ++i) {
    const Probe& p = probes[i];
    const PlanSeriesRateResponse r = EvaluatePlanSeriesRate(law, p.phase, p.u, p.v, p.q.data());
    const double h = 1e-6;
    // Central differences along one argument: u (0, 1), v (2, 3), q (4...).
    const auto diff = [&](int argument) {
      Vec2 u_plus = p.u, u_minus = p.u, v_plus = p.v, v_minus = p.v;
      auto q_plus = p.q, q_minus = p.q;
      if (argument < 2) {
        (argument == 0 ? u_plus.x : u_plus.y) += h;
        (argument == 0 ? u_minus.x : u_minus.y) -= h;
      } else if (argument < 4) {
        (argument == 2 ? v_plus.x : v_plus.y) += h;
        (argument == 2 ? v_minus.x : v_minus.y) -= h;
      } else {
        q_plus[argument - 4] += h;
        q_minus[argument - 4] -= h;
      }
      const PlanSeriesRateResponse a =
          EvaluatePlanSeriesRate(law, p.phase, u_plus, v_plus, q_plus.data());
      const PlanSeriesRateResponse b =
          EvaluatePlanSeriesRate(law, p.phase, u_minus, v_minus, q_minus.data());
      std::array<double, 10> d{};  // force x, y, then the eight rates
      d[0] = (a.force.x - b.force.x) / (2 * h);
      d[1] = (a.force.y - b.force.y) / (2 * h);
      for (int j = 0; j < 8; ++j) d[2 + j] = (a.rate[j] - b.rate[j]) / (2 * h);
      return d;
    };
    const auto near = [&](double analytic, double numeric, const std::string& what) {
      EXPECT_NEAR(analytic, numeric, 1e-6 * (1.0 + std::abs(numeric)))
          << "probe " << i << " " << what;
    };
    for (int argument = 0; argument < 12; ++argument) {
      const auto d = diff(argument);
      const std::string what = "d/d(argument " + std::to_string(argument) + ")";
      if (argument < 2) {
        near(argument == 0 ? r.force_u.xx : r.force_u.xy, d[0], "force_x " + what);
        near(argument == 0 ? r.force_u.yx : r.force_u.yy, d[1], "force_y " + what);
        for (int j = 0; j < 8; ++j) near(r.rate_u[j][argument], d[2 + j], "rate " + what);
      } else if (argument < 4) {
        near(argument == 2 ? r.force_v.xx : r.force_v.xy, d[0], "force_x " + what);
        for (int j = 0; j < 8; ++j) near(r.rate_v[j][argument - 2], d[2 + j], "rate " + what);
      } else {
        near(r.force_q[0][argument - 4], d[0], "force_x " + what);
        near(r.force_q[1][argument - 4], d[1], "force_y " + what);
        for (int j = 0; j < 8; ++j) near(r.rate_q[j][argument - 4], d[2 + j], "rate " + what);
      }
    }
  }
}

// Marches the rate form along a path u(t), v(t): RK4 steps on a fixed phase, a root that falls
// inside a step located by bisection and switched there, as IDA does.
class PlanSeriesMarch {
 public:
  using Path = std::function<std::pair<Vec2, Vec2>(double)>;
  PlanSeriesMarch(const SeriesArrangement& law, Path path)
      : law_(law), path_(std::move(path)), phase_(PlanSeriesRestPhase(law)) {}

  void MarchTo(double t_end, int steps) {
    const double dt = (t_end - t_) / steps;
    for (int i = 0; i < steps; ++i) Step(t_ + dt);
  }
  Vec2 Force() const {
    const auto [u, v] = path_(t_);
    return EvaluatePlanSeriesRate(law_, phase_, u, v, q_.data()).force;
  }
  double dissipated() const { return dissipated_; }
  const std::array<double, 8>& q() const { return q_; }

 private:
  // q and the dissipated energy after integrating from (t_, q_) to t on the current phase.
  std::pair<std::array<double, 8>, double> Integrate(double t) const {
    const auto rate = [&](double time, const std::array<double, 8>& q, double* power) {
      const auto [u, v] = path_(time);
      const PlanSeriesRateResponse r = EvaluatePlanSeriesRate(law_, phase_, u, v, q.data());
      *power = r.hysteretic_power;
      return r.rate;
    };
    const double h = t - t_;
    const auto add = [](const std::array<double, 8>& a, const std::array<double, 8>& b, double s) {
      std::array<double, 8> c{};
      for (int i = 0; i < 8; ++i) c[i] = a[i] + s * b[i];
      return c;
    };
    double p1, p2, p3, p4;
    const auto k1 = rate(t_, q_, &p1);
    const auto k2 = rate(t_ + 0.5 * h, add(q_, k1, 0.5 * h), &p2);
    const auto k3 = rate(t_ + 0.5 * h, add(q_, k2, 0.5 * h), &p3);
    const auto k4 = rate(t, add(q_, k3, h), &p4);
    std::array<double, 8> q = q_;
    for (int i = 0; i < 8; ++i) q[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    return {q, dissipated_ + h / 6 * (p1 + 2 * p2 + 2 * p3 + p4)};
  }
  bool Fell(double t, std::array<int, 8>* found) const {
    std::array<double, 8> before{}, after{};
    const auto [u0, v0] = path_(t_);
    const auto [u1, v1] = path_(t);
    PlanSeriesPhaseRoots(law_, phase_, u0, v0, q_.data(), before.data());
    PlanSeriesPhaseRoots(law_, phase_, u1, v1, Integrate(t).first.data(), after.data());
    bool any = false;
    for (int r = 0; r < PlanSeriesPhaseRootCount(law_); ++r) {
      (*found)[r] = before[r] > 0.0 && after[r] <= 0.0;
      any = any || (*found)[r];
    }
    return any;
  }
  void Step(double t_end) {
    for (int guard = 0; guard < 16 && t_ < t_end; ++guard) {
      std::array<int, 8> found{};
      double t = t_end;
      if (Fell(t, &found)) {
        double low = t_, high = t_end;
        for (int i = 0; i < 60 && high - low > 1e-15 * (1 + std::abs(high)); ++i) {
          const double mid = 0.5 * (low + high);
          (Fell(mid, &found) ? high : low) = mid;
        }
        t = high;
        Fell(t, &found);
      }
      std::tie(q_, dissipated_) = Integrate(t);
      t_ = t;
      if (t < t_end || std::any_of(found.begin(), found.end(), [](int f) { return f != 0; })) {
        const auto [u, v] = path_(t_);
        const PlanSeriesPhaseSwitch next = SwitchPlanSeriesPhase(
            law_, phase_, std::span(found).first(PlanSeriesPhaseRootCount(law_)), u, v, q_.data());
        phase_ = next.phase;
        q_ = next.q;
      }
    }
  }

  const SeriesArrangement& law_;
  Path path_;
  PlanSeriesPhase phase_;
  std::array<double, 8> q_{};
  double t_ = 0.0, dissipated_ = 0.0;
};

TEST(PlanSeriesRateForm, AlongALineItIsTheOneDirectionLaw) {
  const SeriesArrangement law = Triple();
  // v = a d/dt(t sin(6 pi t)) at 2000 samples, linear between them, and u its exact integral
  // (rate_form_test.cpp's path): growing reversals through every regime and beyond the last stop
  // (the capacity is 900), along the direction d. On a line an element's rate is a constant times
  // v, so RK4 integrates it exactly.
  const double a = 1300, step = 1.0 / 2000, degrees = 30;
  const Vec2 d{std::cos(degrees * kPi / 180), std::sin(degrees * kPi / 180)};
  std::vector<std::pair<double, double>> samples{{0.0, 0.0}};  // (u, v)
  for (int k = 1; k <= 2000; ++k) {
    const double t = k * step, w = 6 * kPi;
    const double v = a * (std::sin(w * t) + t * w * std::cos(w * t));
    samples.emplace_back(samples.back().first + 0.5 * step * (samples.back().second + v), v);
  }
  const auto along = [&](double t) {
    const int k = std::min(static_cast<int>(t / step), 1999);
    const double s = t / step - k;
    const auto [u0, v0] = samples[k];
    const double v1 = samples[k + 1].second;
    return std::pair{u0 + step * s * (v0 + 0.5 * s * (v1 - v0)), v0 + s * (v1 - v0)};
  };
  PlanSeriesMarch march(law, [&](double t) {
    const auto [u, v] = along(t);
    return std::pair{u * d, v * d};
  });
  testing::DrivenLaw line(law);
  double worst = 0.0, scale = 1.0;
  for (int k = 1; k <= 2000; ++k) {
    // The motion across the line decays fast while many elements slide (at a rate near
    // (F' / (k f)) (N ke + k)): steps within RK4's stability keep it at round-off.
    march.MarchTo(k * step, 16);
    const auto [u0, v0] = samples[k - 1];
    const auto [u, v] = samples[k];
    if (v0 * v < 0.0) line.MoveTo(along((k - 1 + v0 / (v0 - v)) * step).first);  // the peak
    const double force = line.MoveTo(u).response.force;
    scale = std::max(scale, std::abs(force));
    worst = std::max(worst, Norm(march.Force() - force * d));
  }
  EXPECT_LT(worst, 1e-9 * scale) << "largest force difference " << worst;
}

TEST(PlanSeriesRateForm, RoundACircleItReachesTheClosedFormOfSteadySliding) {
  const SeriesArrangement law = Triple();
  for (const double radius : {600.0, 850.0}) {
    // Out along x in the first second, then round at one revolution a second.
    const auto path = [&](double t) {
      if (t <= 1.0) return std::pair{Vec2{radius * t, 0.0}, Vec2{radius, 0.0}};
      const double theta = 2 * kPi * (t - 1.0);
      return std::pair{radius * Vec2{std::cos(theta), std::sin(theta)},
                       2 * kPi * radius * Vec2{-std::sin(theta), std::cos(theta)}};
    };
    PlanSeriesMarch march(law, path);
    march.MarchTo(1.0, 200);
    march.MarchTo(3.0, 4000);  // two revolutions to settle
    const double before = march.dissipated();
    double force = 0.0;
    for (int k = 1; k <= 2000; ++k) {
      march.MarchTo(3.0 + k / 2000.0, 1);
      force += Norm(march.Force());
    }
    const double per_revolution = march.dissipated() - before;
    // The closed form (plan_series_arrangement_test.cpp's header): |F| from A, then the energy.
    const auto orbit = [&](double f, double* dissipation) {
      double along = f / law.ke, across = 0.0, energy = 0.0;
      for (int k = 0; k < law.count; ++k) {
        const SeriesElement& e = law.elements[k];
        const double sine = e.strength / f,
                     r = std::min(e.stop, std::sqrt(f * f - e.strength * e.strength) / e.stiffness);
        along += r * std::sqrt(1 - sine * sine);
        across += r * sine;
        energy += 2 * kPi * e.strength * r;
      }
      *dissipation = energy;
      return std::hypot(along, across);
    };
    double low = 100.0, high = 1e5, energy = 0.0;
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (low + high);
      (orbit(mid, &energy) < radius ? low : high) = mid;
    }
    const double exact_force = 0.5 * (low + high);
    orbit(exact_force, &energy);
    EXPECT_NEAR(force / 2000, exact_force, 1e-4 * exact_force) << "A = " << radius;
    EXPECT_NEAR(per_revolution, energy, 1e-4 * energy) << "A = " << radius;
  }
}

}  // namespace
}  // namespace isolab::hysteresis
