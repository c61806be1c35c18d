// The plan sliders' stick-or-slip decision (plan_slip_decision.h): a slider that slipped to reach
// its committed state starts the next increment, and an iterate with du = 0, on the slip
// tangent whatever the round-off of its trial force, and a reversal sticks at once. The slopes
// are the laws' own closed forms: along the slip direction a slipping parallel-form slider adds
// nothing to its hardening spring (BHM2: k1), a friction pendulum's interface nothing to W/R, a
// lead core nothing to Kd; sticking adds kp = k0 - k1, mu W / uy and Qd / Dy. A series-form
// slider (BHM1, THM1, elastoplastic) slips on ke kh / (ke + kh) = k1 and sticks on ke = k0.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "isolab/hysteresis/plan_assembly.h"

namespace isolab::hysteresis {
namespace {

struct SliderCase {
  std::string name;
  LawType type;
  std::vector<double> math;
  double slip_slope, stick_slope, yield;  // closed forms, and where the slider starts to slip
};

std::vector<SliderCase> Cases() {
  const double w = 1471, r = 4338, uy = 0.5, mu = 0.06;
  const double qd = 88, kd = 0.34, ku = 3.4, dy = qd / (ku - kd);
  return {
      {"bhm2", LawType::kBhm2, {1.0, 0.2, 20.0}, 0.2, 1.0, 20.0},
      // The series form: post-yield slope ke kh / (ke + kh) = k1 for BHM1 and THM1 inside uyh, 0
      // for the elastoplastic element; ke = k0 sticking.
      {"bhm1", LawType::kBhm1, {1.0, 0.2, 20.0}, 0.2, 1.0, 20.0},
      {"thm1", LawType::kThm1, {1.0, 0.2, 0.45, 20.0, 1000.0}, 0.2, 1.0, 20.0},
      {"elastoplastic", LawType::kElastoplastic, {3.225241, 0.597}, 0.0, 3.225241, 0.597},
      {"friction_pendulum",
       LawType::kFrictionPendulum,
       {w, r, uy, mu, NAN, NAN, NAN},
       w / r,
       w / r + mu * w / uy,
       uy},
      {"lead_rubber",
       LawType::kLeadRubber,
       {qd, kd, dy, NAN, NAN, NAN, NAN, NAN, NAN, NAN},
       kd,
       ku,
       dy},
  };
}

double Along(const Mat2& k, Vec2 d) { return Dot(d, k * d); }

TEST(PlanSlipDecision, AContinuingSlipStartsOnTheSlipTangentAndAReversalSticks) {
  const Vec2 d{std::cos(0.3), std::sin(0.3)};  // any direction, not an axis
  for (const SliderCase& c : Cases()) {
    SCOPED_TRACE(c.name);
    const PlanAssembly assembly(
        {{c.name, LawParameters::Make(c.type, ParameterForm::kMathematical, c.math),
          std::nullopt}});
    std::vector<PlanLawState> committed(1), trial(1);
    std::vector<PlanLawResponse> responses(1);
    // Loaded along d to six times its yield displacement in steps of irregular size, so the
    // committed slider lands on its circle with whatever round-off each step leaves.
    const int steps = 300;
    int checked = 0;
    for (int k = 1; k <= steps; ++k) {
      const double a = 6.0 * c.yield * std::pow(static_cast<double>(k) / steps, 0.7);
      assembly.Update(committed, {a * d, 0.01 * d, 0.01 * k}, trial, responses);
      std::swap(committed, trial);
      if (a < 1.5 * c.yield) continue;
      ASSERT_EQ(committed[0].x.slip, 1) << "step " << k;
      // An iterate at the committed state (du = 0): the slip side, every time.
      const PlanResponse predictor =
          assembly.Update(committed, {a * d, 0.01 * d, 0.01 * k}, trial, responses);
      EXPECT_NEAR(Along(predictor.stiffness, d), c.slip_slope, 1e-9 * c.stick_slope)
          << "step " << k;
      // A small reversal sticks: the elastic slope.
      const PlanResponse reversal = assembly.Update(
          committed, {(a - 1e-3 * c.yield) * d, -0.01 * d, 0.01 * k}, trial, responses);
      EXPECT_NEAR(Along(reversal.stiffness, d), c.stick_slope, 1e-9 * c.stick_slope)
          << "step " << k;
      EXPECT_EQ(trial[0].x.slip, 0);
      ++checked;
    }
    EXPECT_GT(checked, 200);
  }
}

}  // namespace
}  // namespace isolab::hysteresis
