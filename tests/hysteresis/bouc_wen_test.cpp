// The Bouc-Wen law: tangent of the discrete update, second-order accuracy of the trapezoidal
// integration against the closed-form loading curve (nu = 1), and the energy split.
#include "isolab/hysteresis/bouc_wen.h"

#include <gtest/gtest.h>

#include <cmath>

namespace isolab::hysteresis {
namespace {

// The benchmark's parameters (Noel & Schoukens 2016), SI.
const BoucWen kBenchmark{5e4, 1e3, 0.8, -1.1, 1.0};

LawState Step(const BoucWen& law, const LawState& from, double u, LawResponse* response) {
  LawState to;
  law.Update(from, {u, 0.0}, &to, response);
  return to;
}

TEST(BoucWen, TangentIsTheDerivativeOfTheDiscreteUpdate) {
  for (const BoucWen& law :
       {kBenchmark, BoucWen{1.0, 0.05, 0.5, 0.5, 1.0}, BoucWen{1.0, 0.02, 0.6, 0.4, 2.0}}) {
    LawState committed;
    LawResponse response;
    const double scale = 1.0 / law.alpha * (law.alpha > 10 ? 5.0 : 50.0);  // a few yield lengths
    // Loading, reversal, reloading; increments of both signs from each committed state.
    for (const double u : {0.3 * scale, 0.8 * scale, 0.2 * scale, -0.5 * scale, -0.1 * scale}) {
      for (const double du : {0.05 * scale, -0.05 * scale}) {
        const double h = 1e-7 * scale;
        LawResponse plus, minus;
        Step(law, committed, committed.u + du + h, &plus);
        Step(law, committed, committed.u + du - h, &minus);
        Step(law, committed, committed.u + du, &response);
        EXPECT_NEAR(response.stiffness, (plus.force - minus.force) / (2 * h),
                    1e-6 * (std::abs(response.stiffness) + law.alpha * 1e-3));
      }
      committed = Step(law, committed, u, &response);
    }
  }
}

TEST(BoucWen, LoadingCurveConvergesAtSecondOrderToTheClosedForm) {
  // nu = 1, loading from z = 0 with z > 0: dz/du = alpha - beta (gamma + delta) z, so
  // z(u) = alpha / k (1 - exp(-k u)) with k = beta (gamma + delta).
  const BoucWen law{1.0, 0.05, 0.5, 0.5, 1.0};
  const double k = law.beta * (law.gamma + law.delta), u_end = 60.0;
  const double exact = law.alpha / k * (1 - std::exp(-k * u_end));
  std::vector<double> errors;
  for (const int steps : {20, 40, 80}) {
    LawState state;
    LawResponse response;
    for (int i = 1; i <= steps; ++i) state = Step(law, state, u_end * i / steps, &response);
    errors.push_back(std::abs(state.force - exact));
  }
  EXPECT_NEAR(std::log2(errors[0] / errors[1]), 2.0, 0.1);
  EXPECT_NEAR(std::log2(errors[1] / errors[2]), 2.0, 0.1);
}

TEST(BoucWen, WorkIsStoredPlusDissipatedAndACycleDissipates) {
  const BoucWen law{1.0, 0.05, 0.5, 0.5, 1.0};
  LawState state;
  LawResponse response;
  double work = 0.0;
  for (int i = 1; i <= 4000; ++i) {
    const double u = 40.0 * std::sin(2 * M_PI * i / 2000.0);
    const LawState next = Step(law, state, u, &response);
    work += 0.5 * (state.force + next.force) * (u - state.u);
    state = next;
  }
  EXPECT_NEAR(work, law.StoredEnergy(state) + state.dissipated, 1e-9 * work);
  EXPECT_GT(state.dissipated, 0.5 * work);
}

}  // namespace
}  // namespace isolab::hysteresis
