// What the data do not separate, read off a fit (identifiability.h), on fits set up by hand so
// the answer is known: a spring of +3.02 beside a THM1 whose stiffness beyond 1 mm is -3.09 cancel
// (their sum is a fiftieth of either), the same THM1 stiffening instead does not; two friction
// elements yielding 1 % apart have stiffnesses the data cannot tell apart; a coordinate at the
// end of its range and a stiffness held at zero are at their bounds.
#include "isolab/identification/identifiability.h"

#include <gtest/gtest.h>

#include "isolab/core/errors.h"
#include "isolab/identification/synthetic_tests.h"

namespace isolab::identification {
namespace {

using hysteresis::LawType;

FitData Bhm2Tests() {
  const auto truth = hysteresis::SingleLaw(LawType::kBhm2, {1.5, 0.25, 8});
  return SelectCycles(SyntheticTests(truth, {{25, 100, 200}, {2.0}, 3, 200, 0.01, 3}), {});
}

// The fit at the given shape coordinates (by name) and amplitudes.
FitResult At(const ModelParametrisation& model, const std::map<std::string, double>& shape,
             std::vector<double> amplitudes) {
  FitResult fit;
  const auto names = model.FreeNames();
  for (int k = 0; k < model.dimension(); ++k) {
    fit.point.push_back(model.free_range(k).Inverse(shape.at(names[k])));
  }
  fit.amplitudes = Eigen::Map<Eigen::VectorXd>(amplitudes.data(), amplitudes.size());
  fit.mathematical = model.Mathematical(fit.point, fit.amplitudes);
  return fit;
}

TEST(Identifiability, ASpringAndATHM1OfOppositeStiffnessCancel) {
  const FitData data = Bhm2Tests();
  const ModelParametrisation model(
      {{"spring", LawType::kLinearSpring, {}, {}, {}}, {"soft", LawType::kThm1, {}, {}, {}}},
      ScalesOf(data));
  const std::map<std::string, double> soft = {
      {"soft.k1_ratio", 0.5}, {"soft.uy", 0.5}, {"soft.uyh_gap", 0.5}, {"soft.k2_ratio", -3.0}};
  const Identifiability cancelling =
      AssessIdentifiability(model, data, At(model, soft, {3.02, 1.03}));
  ASSERT_EQ(cancelling.cancelling.size(), 1u);
  EXPECT_EQ(cancelling.cancelling[0].a, 0u);
  EXPECT_EQ(cancelling.cancelling[0].b, 1u);
  EXPECT_TRUE(cancelling.Cancels(1));
  // Their secants over the tests are the stiffnesses, +3.02 and about -3.09 (k2 = -3 k0 beyond
  // 1 mm of 25 to 200).
  EXPECT_NEAR(cancelling.components[0].secant, 3.02, 1e-9);
  EXPECT_NEAR(cancelling.components[1].secant, -3.09, 0.1);
  // Each part carries far more than the device (BHM2: 10 + 0.25 u kN, 60 kN at 200 mm).
  EXPECT_GT(cancelling.components[0].peak_force, 2 * cancelling.device_peak_force);
  const auto findings = cancelling.Findings();
  ASSERT_FALSE(findings.empty());
  EXPECT_NE(findings[0].find("spring and soft cancel"), std::string::npos) << findings[0];

  std::map<std::string, double> stiffening = soft;
  stiffening["soft.k2_ratio"] = 0.1;
  EXPECT_TRUE(
      AssessIdentifiability(model, data, At(model, stiffening, {0.2, 1.03})).cancelling.empty());
}

TEST(Identifiability, TwoFrictionElementsYieldingAlikeAreStronglyCorrelated) {
  const FitData data = Bhm2Tests();
  const ModelParametrisation model({{"a", LawType::kElastoplastic, {}, {}, {}},
                                    {"b", LawType::kElastoplastic, {}, {}, {}},
                                    {"spring", LawType::kLinearSpring, {}, {}, {}}},
                                   ScalesOf(data));
  const Identifiability result =
      AssessIdentifiability(model, data, At(model, {{"a.uy", 5.0}, {"b.uy", 5.05}}, {1, 1, 0.25}));
  ASSERT_FALSE(result.correlated.empty());
  const CorrelatedPair& strongest = result.correlated.front();
  EXPECT_GT(std::abs(strongest.correlation), 0.99);
  EXPECT_TRUE(result.cancelling.empty());  // alike, not opposed
}

TEST(Identifiability, CoordinatesAtTheirRangeEndsAndStiffnessesHeldAtZeroAreAtBounds) {
  const FitData data = Bhm2Tests();
  const ModelParametrisation model({{"a", LawType::kElastoplastic, {{"uy", {1, 20, true}}}, {}, {}},
                                    {"b", LawType::kBhm2, {}, {}, {}}},
                                   ScalesOf(data));
  const Identifiability result = AssessIdentifiability(
      model, data, At(model, {{"a.uy", 20.0}, {"b.uy", 8.0}}, {0.5, 0.0, 0.25}));
  ASSERT_EQ(result.at_bounds.size(), 2u);
  EXPECT_EQ(result.at_bounds[0].name, "a.uy");
  EXPECT_NE(result.at_bounds[0].where.find("upper bound (20)"), std::string::npos);
  EXPECT_EQ(result.at_bounds[1].name, "b.k0-k1");
  EXPECT_NE(result.at_bounds[1].where.find("zero"), std::string::npos);
}

TEST(Identifiability, OptionsNameTheFieldAtFault) {
  IdentifiabilityOptions options;
  options.correlation = 0.0;
  try {
    options.Validate();
    ADD_FAILURE() << "no exception";
  } catch (const InvalidParameter& error) {
    EXPECT_EQ(error.violation().key, "correlation");
  }
}

}  // namespace
}  // namespace isolab::identification
