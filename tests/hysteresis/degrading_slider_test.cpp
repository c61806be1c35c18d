// The degrading BHM2 against closed forms: no loss is BHM2 exactly; monotone loading of the
// degrading elastoplastic element follows fs phi(u - uy); under a constant-amplitude cycle the
// peak force after n half-cycles is fs phi(kappa_n) with kappa_n = (A - uy) + 2 (n - 1)(A - uy).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "isolab/core/errors.h"
#include "isolab/hysteresis/law_parameters.h"

namespace isolab::hysteresis {
namespace {

LawKernel Math(LawType type, std::vector<double> values) {
  return LawParameters::Make(type, ParameterForm::kMathematical, values).Kernel();
}

double Drive(const LawKernel& kernel, LawState* state, double u) {
  LawState trial;
  LawResponse response;
  UpdateLaw(kernel, *state, {u, 0.0}, &trial, &response);
  *state = trial;
  return response.force;
}

TEST(DegradingBhm2, WithoutLossIsBhm2) {
  const LawKernel degrading = Math(LawType::kDegradingBhm2, {1.5, 0.3, 12, 0.0, 50});
  const LawKernel bhm2 = Math(LawType::kBhm2, {1.5, 0.3, 12});
  LawState a, b;
  for (int k = 0; k <= 2000; ++k) {
    const double u = 80.0 * std::sin(0.013 * k) * (1.0 + 0.001 * k);
    EXPECT_NEAR(Drive(degrading, &a, u), Drive(bhm2, &b, u), 1e-12) << "u = " << u;
    EXPECT_NEAR(a.dissipated, b.dissipated, 1e-9 * (1.0 + b.dissipated));
  }
}

TEST(DegradingBhm2, MonotoneLoadingFollowsFsTimesPhiOfTheSlip) {
  const double k0 = 2.0, uy = 5.0, loss = 0.6, scale = 40.0, fs = k0 * uy;
  const LawKernel law = Math(LawType::kDegradingBhm2, {k0, 0.0, uy, loss, scale});
  LawState state;
  EXPECT_DOUBLE_EQ(Drive(law, &state, 0.5 * uy), 0.5 * fs);  // elastic, undamaged
  for (const double u : {6.0, 20.0, 75.0, 400.0}) {
    const double slip = u - uy;
    const double expected = fs * (1.0 - loss * (1.0 - std::exp(-slip / scale)));
    EXPECT_NEAR(Drive(law, &state, u), expected, 1e-12 * fs) << "u = " << u;
    EXPECT_NEAR(state.accumulated_slip, slip, 1e-12);
  }
  // Unloading is elastic with the damaged stiffness phi k0.
  const double phi = 1.0 - loss * (1.0 - std::exp(-(400.0 - uy) / scale));
  const double at_peak = fs * phi;
  EXPECT_NEAR(Drive(law, &state, 399.0), at_peak - phi * k0 * 1.0, 1e-12 * fs);
}

TEST(DegradingBhm2, PeakForceOfEachHalfCycleFollowsTheClosedForm) {
  const double k0 = 1.0, k1 = 0.1, uy = 10.0, loss = 0.3, scale = 200.0, amplitude = 60.0;
  const double fs = (k0 - k1) * uy;
  const LawKernel law = Math(LawType::kDegradingBhm2, {k0, k1, uy, loss, scale});
  LawState state;
  const int steps = 400;
  for (int half = 1; half <= 6; ++half) {
    const double sign = half % 2 == 1 ? 1.0 : -1.0;
    const double from = half == 1 ? 0.0 : -sign * amplitude;
    double force = 0.0;
    for (int k = 1; k <= steps; ++k)
      force = Drive(law, &state, from + (sign * amplitude - from) * k / steps);
    const double kappa = (amplitude - uy) + 2.0 * (half - 1) * (amplitude - uy);
    const double phi = 1.0 - loss * (1.0 - std::exp(-kappa / scale));
    EXPECT_NEAR(force, sign * phi * (fs + k1 * amplitude), 1e-10 * fs) << "half-cycle " << half;
  }
}

TEST(DegradingBhm2, RulesNameTheKey) {
  const auto make = [](std::vector<double> values) {
    return LawParameters::Make(LawType::kDegradingBhm2, ParameterForm::kMathematical, values);
  };
  EXPECT_THROW(make({1, 0.1, 10, 1.0, 50}), InvalidParameter);   // loss must be < 1
  EXPECT_THROW(make({1, 0.1, 10, -0.1, 50}), InvalidParameter);  // loss >= 0
  EXPECT_THROW(make({1, 0.1, 10, 0.2, 0}), InvalidParameter);    // slip_scale > 0
  EXPECT_THROW(make({1, 0.1, 0, 0.2, 50}), InvalidParameter);    // uy > 0
  try {
    make({1, 0.1, 10, 1.5, 50});
  } catch (const InvalidParameter& error) {
    EXPECT_EQ(error.violation().key, "loss");
  }
  const LawParameters law = make({2, 0.5, 10, 0.2, 50});
  EXPECT_EQ(law.Values(ParameterForm::kMechanical), (std::vector<double>{2, 0.5, 15, 0.2, 50}));
}

}  // namespace
}  // namespace isolab::hysteresis
