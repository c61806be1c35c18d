// Sliders in series in rate form (series_rate_form.h) against the exact incremental law: marched
// along a growing, reversing displacement path with its events located by its own root functions,
// it reproduces the incremental force through every regime of the double and triple pendulums;
// its partial derivatives are the derivatives of what it computes; a stick root touched while
// unloading does not start a slide; its slider work rate is the elements' strengths times their
// speeds.
#include "isolab/hysteresis/series_rate_form.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "isolab/hysteresis/law_parameters.h"
#include "series_law_harness.h"

namespace isolab::hysteresis {
namespace {

SeriesArrangement Series(LawType type, std::vector<double> values) {
  return std::get<SeriesArrangement>(
      LawParameters::Make(type, ParameterForm::kMathematical, values).Kernel());
}
SeriesArrangement Triple() {
  return Series(LawType::kTripleFrictionPendulum,
                {1000, 2100, 280, 280, 2100, 0.06, 0.02, 0.02, 0.10, 400, 50, 50, 400, 0.5});
}
SeriesArrangement TripleUnequal() {
  return Series(LawType::kTripleFrictionPendulum,
                {1200, 1800, 300, 250, 2400, 0.05, 0.01, 0.03, 0.09, 250, 60, 40, 350, 1.0});
}
SeriesArrangement Double() {
  return Series(LawType::kDoubleFrictionPendulum, {800, 2000, 1500, 0.04, 0.07, 300, 250, 1});
}

// v(t) = a d/dt(t sin(2 pi 3 t)), linear between samples, and its exact integral: u peaks where v
// changes sign (rate_form_test.cpp's path).
struct PathPoint {
  double u, v;
};
constexpr double kStep = 1.0 / 4000;
std::vector<PathPoint> GrowingSine(double amplitude) {
  std::vector<PathPoint> path{{0.0, 0.0}};
  const double w = 2 * std::numbers::pi * 3;
  for (int k = 1; k <= 4000; ++k) {
    const double t = k * kStep;
    const double v = amplitude * (std::sin(w * t) + t * w * std::cos(w * t));
    path.push_back({path.back().u + 0.5 * kStep * (path.back().v + v), v});
  }
  return path;
}

// Marches the rate form between samples: on a phase z is linear in u (dz = rate_v du), so a step
// is exact; a root falling through zero inside a step is bisected, the phase switched there and
// the march resumed, as IDA does with its root finder.
class SeriesMarch {
 public:
  explicit SeriesMarch(const SeriesArrangement& law) : law_(law), phase_(SeriesRestPhase(law)) {}

  void MoveTo(const PathPoint& from, const PathPoint& to) {
    double start = 0.0;
    for (int guard = 0; guard < 64 && start < 1.0; ++guard) {
      const double end = FirstCrossing(from, to, start);
      const PathPoint at = Lerp(from, to, end);
      std::array<double, kMaxSeriesElements + 1> before{}, after{};
      const auto z_end = ZAt(from, to, start, end);
      const PathPoint a = Lerp(from, to, start);
      SeriesPhaseRoots(law_, phase_, a.u, a.v, z_.data(), before.data());
      SeriesPhaseRoots(law_, phase_, at.u, at.v, z_end.data(), after.data());
      z_ = z_end;
      // Every root that fell, switched together (as IDA reports them).
      std::array<int, kMaxSeriesElements + 1> found{};
      bool any = false;
      for (int r = 0; r < SeriesPhaseRootCount(law_); ++r) {
        found[r] = before[r] > 0.0 && after[r] <= 0.0;
        any = any || found[r];
      }
      if (any) {
        const SeriesPhaseSwitch next =
            SwitchSeriesPhase(law_, phase_, std::span(found).first(SeriesPhaseRootCount(law_)),
                              at.u, at.v, z_.data());
        for (int k = 0; k < law_.count; ++k) {
          const int slip = next.phase.slip[k];
          if (slip != 0) slid_[k][slip > 0] = true;
          if (std::abs(next.z[k]) == law_.elements[k].stop) stopped_[k][next.z[k] > 0] = true;
        }
        phase_ = next.phase;
        z_ = next.z;
      }
      start = end;
    }
  }
  double Force(const PathPoint& at) const {
    return EvaluateSeriesRate(law_, phase_, at.u, at.v, z_.data()).force;
  }
  // Whether every element slid both ways and reached both its stops.
  bool VisitedEveryPhase() const {
    for (int k = 0; k < law_.count; ++k) {
      if (!(slid_[k][0] && slid_[k][1] && stopped_[k][0] && stopped_[k][1])) return false;
    }
    return true;
  }
  static PathPoint Lerp(const PathPoint& a, const PathPoint& b, double s) {
    return {a.u + kStep * s * (a.v + 0.5 * s * (b.v - a.v)), a.v + s * (b.v - a.v)};
  }

 private:
  std::array<double, kMaxSeriesElements> ZAt(const PathPoint& from, const PathPoint& to,
                                             double start, double end) const {
    const PathPoint a = Lerp(from, to, start), b = Lerp(from, to, end);
    const SeriesRateResponse r = EvaluateSeriesRate(law_, phase_, a.u, a.v, z_.data());
    auto z = z_;
    for (int k = 0; k < law_.count; ++k) z[k] += r.rate_v[k] * (b.u - a.u);
    return z;
  }
  double FirstCrossing(const PathPoint& from, const PathPoint& to, double start) const {
    const auto any_crossed = [&](double end) {
      std::array<double, kMaxSeriesElements + 1> before{}, after{};
      const PathPoint a = Lerp(from, to, start), b = Lerp(from, to, end);
      SeriesPhaseRoots(law_, phase_, a.u, a.v, z_.data(), before.data());
      SeriesPhaseRoots(law_, phase_, b.u, b.v, ZAt(from, to, start, end).data(), after.data());
      for (int r = 0; r < SeriesPhaseRootCount(law_); ++r) {
        if (before[r] > 0.0 && after[r] <= 0.0) return true;
      }
      return false;
    };
    if (!any_crossed(1.0)) return 1.0;
    double low = start, high = 1.0;
    for (int i = 0; i < 200 && high - low > 1e-15; ++i) {
      const double mid = 0.5 * (low + high);
      (any_crossed(mid) ? high : low) = mid;
    }
    return high;
  }

  const SeriesArrangement& law_;
  SeriesPhase phase_;
  std::array<double, kMaxSeriesElements> z_{};
  std::array<std::array<bool, 2>, kMaxSeriesElements> slid_{}, stopped_{};
};

struct RateCase {
  std::string name;
  SeriesArrangement law;
  double amplitude;  // of the path, which reaches beyond every stop
};

TEST(SeriesRateForm, MarchedRateFormReproducesTheIncrementalLaw) {
  for (const RateCase& c :
       {RateCase{"triple", Triple(), 1300}, RateCase{"unequal", TripleUnequal(), 1100},
        RateCase{"double", Double(), 900}}) {
    const auto path = GrowingSine(c.amplitude);
    SeriesMarch march(c.law);
    testing::DrivenLaw law(c.law);
    double worst = 0.0, scale = 0.0;
    for (std::size_t k = 1; k < path.size(); ++k) {
      march.MoveTo(path[k - 1], path[k]);
      const PathPoint &a = path[k - 1], &b = path[k];
      if (a.v * b.v < 0.0) law.MoveTo(SeriesMarch::Lerp(a, b, a.v / (a.v - b.v)).u);
      const double force = law.MoveTo(b.u).response.force;
      worst = std::max(worst, std::abs(march.Force(b) - force));
      scale = std::max(scale, std::abs(force));
    }
    EXPECT_LT(worst, 1e-9 * scale) << c.name << ": largest force difference " << worst;
    EXPECT_TRUE(march.VisitedEveryPhase()) << c.name;
  }
}

TEST(SeriesRateForm, PartialDerivativesMatchFiniteDifferences) {
  const SeriesArrangement law = Triple();
  struct Probe {
    SeriesPhase phase;
    double u, v;
    std::array<double, 4> z;
  };
  const std::vector<Probe> probes = {
      {{{0, 0, 0, 0}}, 3.0, 2.0, {0.0, 1.0, 1.0, 0.0}},
      {{{0, 1, 1, 0}}, 20.0, 2.0, {0.0, 5.0, 5.0, 0.0}},
      {{{1, 1, 1, 0}}, 80.0, -1.5, {30.0, 12.0, 12.0, 0.0}},
      {{{-1, -1, -1, -1}}, -300.0, -3.0, {-150.0, -20.0, -20.0, -60.0}},
      {{{0, 1, 1, 1}}, 600.0, 4.0, {346.0, 40.0, 40.0, 150.0}},
  };
  for (const Probe& p : probes) {
    const SeriesRateResponse r = EvaluateSeriesRate(law, p.phase, p.u, p.v, p.z.data());
    const double h = 1e-6;
    const auto diff = [&](double du, double dv, int k) {
      auto plus = p.z, minus = p.z;
      if (k >= 0) {
        plus[k] += h;
        minus[k] -= h;
      }
      const SeriesRateResponse a =
          EvaluateSeriesRate(law, p.phase, p.u + du, p.v + dv, plus.data());
      const SeriesRateResponse b =
          EvaluateSeriesRate(law, p.phase, p.u - du, p.v - dv, minus.data());
      SeriesRateResponse d;
      d.force = (a.force - b.force) / (2 * h);
      for (int i = 0; i < 4; ++i) d.rate[i] = (a.rate[i] - b.rate[i]) / (2 * h);
      return d;
    };
    const auto near = [](double analytic, double numeric) {
      EXPECT_NEAR(analytic, numeric, 1e-6 * (1.0 + std::abs(numeric)));
    };
    const SeriesRateResponse du = diff(h, 0, -1), dv = diff(0, h, -1);
    near(r.force_u, du.force);
    near(r.force_v, dv.force);
    for (int k = 0; k < 4; ++k) {
      near(r.rate_u[k], du.rate[k]);
      near(r.rate_v[k], dv.rate[k]);
      const SeriesRateResponse dz = diff(0, 0, k);
      near(r.force_z[k], dz.force);
      for (int i = 0; i < 4; ++i) near(r.rate_z[i][k], dz.rate[i]);
    }
  }
}

TEST(SeriesRateForm, StickRootTouchedWhileUnloadingKeepsTheElementStuck) {
  const SeriesArrangement law = Double();
  const SeriesPhase rest = SeriesRestPhase(law);
  // Element 1's friction reaches its strength (F = mu1 W = 32 at z = 0: u = F / ke = 1).
  const std::array<double, 2> z{};
  const std::array<int, 3> first{1, 0, 0};
  EXPECT_EQ(SwitchSeriesPhase(law, rest, first, 1.0, -1.0, z.data()).phase, rest);
  const SeriesPhaseSwitch slide = SwitchSeriesPhase(law, rest, first, 1.0 + 1e-12, 1.0, z.data());
  EXPECT_EQ(slide.phase.slip[0], 1);
  EXPECT_EQ(slide.phase.slip[1], 0);
  // Put on its slip surface F = f + k z with the force u gives.
  const SeriesRateResponse r =
      EvaluateSeriesRate(law, slide.phase, 1.0 + 1e-12, 1.0, slide.z.data());
  EXPECT_NEAR(r.force, 32.0, 1e-9);
}

TEST(SeriesRateForm, SliderWorkRateIsStrengthTimesSpeedAndStopsClampTheElements) {
  const SeriesArrangement law = Triple();
  const SeriesPhase phase{{1, 1, 1, 0}};
  const std::array<double, 4> z{100.0, 30.0, 30.0, 0.0};
  const SeriesRateResponse r = EvaluateSeriesRate(law, phase, 250.0, 2.0, z.data());
  double power = 0.0, speed = 0.0;
  for (int k = 0; k < 4; ++k) {
    power += law.elements[k].strength * r.rate[k];
    speed += r.rate[k];
  }
  EXPECT_NEAR(r.hysteretic_power, power, 1e-12 * power);
  // The rate of u splits among ke (the force's rate, k dz/dt of any sliding element, over ke)
  // and the sliding elements.
  EXPECT_NEAR(law.elements[1].stiffness * r.rate[1] / law.ke + speed, 2.0, 1e-12);
  EXPECT_NEAR(law.elements[0].stiffness * r.rate[0], law.elements[1].stiffness * r.rate[1], 1e-12);
  // Reaching a stop puts the element exactly at it.
  const std::array<int, 5> first{1, 0, 0, 0, 0};
  const SeriesPhaseSwitch at_stop = SwitchSeriesPhase(law, phase, first, 250.0, 2.0, z.data());
  EXPECT_EQ(at_stop.z[0], law.elements[0].stop);
  EXPECT_EQ(at_stop.phase.slip[0], 0);
}

}  // namespace
}  // namespace isolab::hysteresis
