// The rate form (rate_form.h) against the exact incremental laws: marched along a displacement
// path with its events located by its own root functions, it reproduces the incremental force
// everywhere; its partial derivatives are the derivatives of what it computes; and a stick root
// touched while unloading does not start a slip.
#include "isolab/hysteresis/rate_form.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "isolab/hysteresis/law_parameters.h"

namespace isolab::hysteresis {
namespace {

LawKernel Math(LawType type, std::vector<double> values) {
  return LawParameters::Make(type, ParameterForm::kMathematical, values).Kernel();
}

struct RateCase {
  std::string name;
  LawKernel kernel;
  double amplitude;
};

std::vector<RateCase> PiecewiseLinearCases() {
  return {
      {"thm1_hard", Math(LawType::kThm1, {1, 0.2, 0.45, 20, 120}), 250},
      {"thm1_negative_k2", Math(LawType::kThm1, {0.863754, 0.402485, -0.792654, 7.146, 125.542}),
       200},
      {"thm1_spring_limit", Math(LawType::kThm1, {1e6, 0.283532, 0.489882, 0, 64.809}), 150},
      {"thm2_soft", Math(LawType::kThm2, {1, 0.2, 0.05, 20, 120}), 250},
      {"thm2_uyh_below_uy", Math(LawType::kThm2, {1, 0.2, 0.45, 20, 10}), 250},
      {"bhm2", Math(LawType::kBhm2, {1, 0.2, 20}), 250},
      {"elastoplastic", Math(LawType::kElastoplastic, {3.225241, 0.597}), 10},
      {"trilinear_elastic", Math(LawType::kTrilinearElastic, {0.283532, 0.489882, 64.809}), 150},
  };
}

// A growing, reversing velocity v(t) = a d/dt(t/T sin(2 pi 3 t/T)), linear between samples, and
// its exact integral u, so that u peaks exactly where v changes sign.
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

// Marches the rate form between samples: on a branch z is linear in u (dz = rate_v du), so a
// step is exact; where a root falls through zero inside a step the crossing is bisected, the
// phase switched there and the march resumed, as IDA does with its root finder.
class RateFormMarch {
 public:
  explicit RateFormMarch(const LawKernel& kernel) : kernel_(kernel), phase_(RestPhase(kernel)) {}

  void MoveTo(const PathPoint& from, const PathPoint& to) {
    double start = 0.0;
    for (int guard = 0; guard < 16 && start < 1.0; ++guard) {
      const double end = FirstCrossing(from, to, start);
      const PathPoint a = Lerp(from, to, start), at = Lerp(from, to, end);
      const double z_end = ZAt(from, to, start, end);
      double before[kMaxPhaseRoots], after[kMaxPhaseRoots];
      PhaseRoots(kernel_, phase_, a.u, a.v, z_, before);
      PhaseRoots(kernel_, phase_, at.u, at.v, z_end, after);
      z_ = z_end;
      const LawPhase phase = phase_;
      for (int r = 0; r < PhaseRootCount(kernel_); ++r) {
        if (before[r] > 0.0 && after[r] <= 0.0) {
          const PhaseSwitch next = SwitchPhase(kernel_, phase, r, at.u, at.v, z_);
          phase_ = {r == 0 ? next.phase.slip : phase_.slip,
                    r == 1 || PhaseRootCount(kernel_) == 1 ? next.phase.segment : phase_.segment};
          z_ = next.z;
        }
      }
      start = end;
    }
  }

  double Force(const PathPoint& at) const {
    return EvaluateRate(kernel_, phase_, at.u, at.v, z_).force;
  }

  static PathPoint Lerp(const PathPoint& a, const PathPoint& b, double s) {
    return {a.u + kStep * s * (a.v + 0.5 * s * (b.v - a.v)), a.v + s * (b.v - a.v)};
  }

 private:
  // z at fraction `end` when the march left fraction `start` with z_.
  double ZAt(const PathPoint& from, const PathPoint& to, double start, double end) const {
    const PathPoint a = Lerp(from, to, start), b = Lerp(from, to, end);
    return z_ + EvaluateRate(kernel_, phase_, a.u, a.v, z_).rate_v * (b.u - a.u);
  }
  // Smallest fraction in (start, 1] where a root falls through zero, or 1.
  double FirstCrossing(const PathPoint& from, const PathPoint& to, double start) const {
    const auto any_crossed = [&](double end) {
      double before[kMaxPhaseRoots], after[kMaxPhaseRoots];
      const PathPoint a = Lerp(from, to, start), b = Lerp(from, to, end);
      PhaseRoots(kernel_, phase_, a.u, a.v, z_, before);
      PhaseRoots(kernel_, phase_, b.u, b.v, ZAt(from, to, start, end), after);
      for (int r = 0; r < PhaseRootCount(kernel_); ++r) {
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

  const LawKernel& kernel_;
  LawPhase phase_;
  double z_ = 0.0;
};

class RateFormTest : public ::testing::TestWithParam<RateCase> {};

TEST_P(RateFormTest, MarchedRateFormReproducesTheIncrementalLaw) {
  const RateCase& c = GetParam();
  const auto path = GrowingSine(c.amplitude);
  RateFormMarch march(c.kernel);
  LawState committed, trial;
  LawResponse response;
  double worst = 0.0, scale = 0.0;
  for (std::size_t k = 1; k < path.size(); ++k) {
    march.MoveTo(path[k - 1], path[k]);
    // The incremental law sees only end points: give it the displacement peak inside the step.
    const PathPoint &a = path[k - 1], &b = path[k];
    if (a.v * b.v < 0.0) {
      const PathPoint peak = RateFormMarch::Lerp(a, b, a.v / (a.v - b.v));
      UpdateLaw(c.kernel, committed, {peak.u, 0.0}, &trial, &response);
      committed = trial;
    }
    UpdateLaw(c.kernel, committed, {b.u, b.v}, &trial, &response);
    committed = trial;
    worst = std::max(worst, std::abs(march.Force(path[k]) - trial.force));
    scale = std::max(scale, std::abs(trial.force));
  }
  EXPECT_LT(worst, 1e-9 * scale) << c.name << ": largest force difference " << worst;
}

INSTANTIATE_TEST_SUITE_P(Laws, RateFormTest, ::testing::ValuesIn(PiecewiseLinearCases()),
                         [](const auto& info) { return info.param.name; });

// Central differences of EvaluateRate in each argument, inside one phase.
TEST(RateForm, PartialDerivativesMatchFiniteDifferences) {
  struct Probe {
    LawKernel kernel;
    LawPhase phase;
    double u, v, z;
  };
  const LawKernel thm1 = Math(LawType::kThm1, {1, 0.2, 0.45, 20, 120});
  const LawKernel thm2 = Math(LawType::kThm2, {1, 0.2, 0.05, 20, 120});
  const LawKernel bouc_wen = LawParameters::Make(LawType::kBoucWen, ParameterForm::kMathematical,
                                                 std::vector<double>{5e4, 1e3, 0.8, 0.2, 1.5})
                                 .Kernel();
  const std::vector<Probe> probes = {
      {thm1, {0, 0}, 10, 3, 2},         {thm1, {1, 0}, 60, 3, 40},
      {thm1, {-1, -1}, -200, -3, -150}, {thm2, {0, 1}, 130, 3, 125},
      {thm2, {1, 1}, 150, 3, 130},      {Math(LawType::kDashpot, {2.5}), {}, 1, 4, 0},
      {bouc_wen, {}, 1e-4, 0.3, 0.5},   {bouc_wen, {}, 1e-4, -0.3, -0.2},
  };
  for (const Probe& p : probes) {
    const RateResponse r = EvaluateRate(p.kernel, p.phase, p.u, p.v, p.z);
    const double h = 1e-6;
    const auto diff = [&](double du, double dv, double dz) {
      const RateResponse plus = EvaluateRate(p.kernel, p.phase, p.u + du, p.v + dv, p.z + dz);
      const RateResponse minus = EvaluateRate(p.kernel, p.phase, p.u - du, p.v - dv, p.z - dz);
      return std::pair{(plus.force - minus.force) / (2 * h), (plus.rate - minus.rate) / (2 * h)};
    };
    const auto [fu, ru] = diff(h, 0, 0);
    const auto [fv, rv] = diff(0, h, 0);
    const auto [fz, rz] = diff(0, 0, h);
    // Each entry against its own scale, so a small entry is not excused by a large one.
    const auto near = [](double analytic, double numeric) {
      EXPECT_NEAR(analytic, numeric, 1e-6 * (1.0 + std::abs(numeric)));
    };
    near(r.force_u, fu);
    near(r.force_v, fv);
    near(r.force_z, fz);
    near(r.rate_u, ru);
    near(r.rate_v, rv);
    near(r.rate_z, rz);
  }
}

TEST(RateForm, StickRootReachedWhileUnloadingKeepsTheSliderStuck) {
  const LawKernel elastoplastic = Math(LawType::kElastoplastic, {10, 0.75});
  const LawPhase stick = RestPhase(elastoplastic);
  ASSERT_EQ(stick.slip, 0);
  // Slider force at +fs (u - z = 0.75) with the deformation already decreasing.
  EXPECT_EQ(SwitchPhase(elastoplastic, stick, 0, 0.75, -1.0, 0.0).phase.slip, 0);
  const PhaseSwitch slip = SwitchPhase(elastoplastic, stick, 0, 0.75 + 1e-12, 1.0, 0.0);
  EXPECT_EQ(slip.phase.slip, 1);
  // Put back on the slip surface ke (u - z) = fs.
  EXPECT_NEAR(10 * (0.75 + 1e-12 - slip.z), 7.5, 1e-12);
}

TEST(RateForm, SlipDissipatesFsTimesSliderSpeed) {
  const LawKernel bhm1 = Math(LawType::kBhm1, {1, 0.2, 20});
  const RateResponse r = EvaluateRate(bhm1, {1, 0}, 30, 2.0, 10);
  // ke = k0 = 1, kh = k1 / (1 - k1/k0) = 0.25, fs = k0 uy = 20: u_h' = v ke / (ke + kh).
  EXPECT_NEAR(r.rate, 2.0 / 1.25, 1e-14);
  EXPECT_NEAR(r.hysteretic_power, 20 * 2.0 / 1.25, 1e-12);
}

}  // namespace
}  // namespace isolab::hysteresis
