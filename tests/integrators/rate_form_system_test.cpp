// The implicit system IDA integrates (src/integrators/rate_form_system.h): its Jacobian is the
// derivative of its residual, checked by central differences on a structure that uses every law
// kernel on grounded and story connections; and IDA on that structure agrees with Newmark.
#include "rate_form_system.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "integrators/jacobian_check.h"
#include "isolab/integrators/ida.h"
#include "isolab/integrators/newmark.h"
#include "isolab/structure/shear_building.h"

namespace isolab::integrators {
namespace {

using hysteresis::Component;
using hysteresis::LawParameters;
using hysteresis::LawType;
using hysteresis::ParameterForm;

Component Law(std::string name, LawType type, std::vector<double> math) {
  return {std::move(name), LawParameters::Make(type, ParameterForm::kMathematical, math)};
}

// Two stories on an isolation layer (kN, mm, s): THM1 + elastoplastic + dashpot at the base;
// stories carrying THM2, Bouc-Wen, a trilinear spring and a dashpot.
structure::Structure EveryKernelBuilding() {
  structure::ShearBuilding building;
  building.isolated = true;
  building.base_mass = 25.0;
  building.isolation = hysteresis::ParallelAssembly(
      {Law("thm1", LawType::kThm1, {1.0, 0.2, 0.45, 20, 60}),
       Law("lead", LawType::kElastoplastic, {3.0, 0.6}), Law("damper", LawType::kDashpot, {0.05})});
  const hysteresis::ParallelAssembly story({
      Law("thm2", LawType::kThm2, {10, 2, 5, 0.3, 0.8}),
      Law("bouc_wen", LawType::kBoucWen, {8, 0.5, 0.6, 0.4, 1.5}),
      Law("spring", LawType::kTrilinearElastic, {5, 1.5, 0.6}),
      Law("damper", LawType::kDashpot, {0.2}),
  });
  building.stories = {{"s1", 25.0, 3200, story}, {"s2", 25.0, 3200, story}};
  building.damping.kind = structure::SuperstructureDamping::Kind::kRayleigh;
  building.damping.rayleigh_ratios[0] = building.damping.rayleigh_ratios[1] = 0.02;
  return structure::BuildShearBuilding(building).structure;
}

// A two-frequency ground acceleration (mm/s^2) over 8 s, sampled at 0.01 s.
Excitation Shaking() {
  Excitation excitation = Excitation::Uniform({});
  excitation.ground[0].acceleration.dt = 0.01;
  for (int k = 0; k <= 800; ++k) {
    const double t = 0.01 * k;
    excitation.ground[0].acceleration.values.push_back(
        3000.0 * std::sin(std::numbers::pi * t / 8) *
        (std::sin(2 * std::numbers::pi * 0.6 * t) +
         0.5 * std::sin(2 * std::numbers::pi * 3.1 * t)));
  }
  return excitation;
}

TEST(RateFormSystem, JacobianIsTheDerivativeOfTheResidual) {
  const structure::Structure building = EveryKernelBuilding();
  const Excitation excitation = Shaking();
  RateFormSystem system(building, excitation);
  testing::ExpectJacobianIsTheDerivativeOfTheResidual(system);
}

TEST(RateFormSystem, IdaAgreesWithNewmarkWhenEveryKernelIsPresent) {
  const structure::Structure building = EveryKernelBuilding();
  const Excitation excitation = Shaking();
  const TimeGrid grid{0.0005, 16000, 20};  // output every 0.01 s
  IdaOptions tight;
  tight.relative_tolerance = 1e-9;
  tight.absolute_tolerance = 1e-11;
  ResponseHistory ida, newmark;
  const RunSummary ida_summary = RunIda(building, excitation, {0.01, 800}, tight, &ida);
  const RunSummary newmark_summary = RunNewmark(building, excitation, grid, {}, &newmark);
  ASSERT_TRUE(ida_summary.ok()) << ida_summary.message;
  ASSERT_TRUE(newmark_summary.ok()) << newmark_summary.message;
  const double scale = ida.displacement.cwiseAbs().maxCoeff();
  const double difference = (ida.displacement - newmark.displacement).cwiseAbs().maxCoeff();
  // Story drifts compared on their own scale, so an error in a story law is not hidden by the
  // much larger base displacement.
  const auto drifts = [](const ResponseHistory& r) {
    Eigen::MatrixXd d(r.displacement.rows(), 2);
    d.col(0) = r.displacement.col(1) - r.displacement.col(0);
    d.col(1) = r.displacement.col(2) - r.displacement.col(1);
    return d;
  };
  const Eigen::MatrixXd ida_drift = drifts(ida), newmark_drift = drifts(newmark);
  const double drift_scale = ida_drift.cwiseAbs().maxCoeff();
  const double drift_difference = (ida_drift - newmark_drift).cwiseAbs().maxCoeff();
  std::printf(
      "every-kernel building: peak %.3f mm, max |IDA - Newmark(0.0005 s)| %.2e mm; peak "
      "drift %.3f mm, difference %.2e mm; %ld events, energy balance IDA %.1e\n",
      scale, difference, drift_scale, drift_difference, ida_summary.events,
      ida_summary.energy_balance_error);
  EXPECT_GT(ida_summary.events, 10);
  // The stories yield too: their drift passes the THM2's uyh = 0.8 mm and the spring's 0.6 mm.
  EXPECT_GT(drift_scale, 0.8);
  EXPECT_LT(difference, 1e-5 * scale);
  EXPECT_LT(drift_difference, 1e-4 * drift_scale);
  EXPECT_LT(ida_summary.energy_balance_error, 1e-5);
  // Energy terms agree between the integrators, term by term.
  const Energies& a = ida.energies.back();
  const Energies& b = newmark.energies.back();
  EXPECT_NEAR(a.hysteretic / b.hysteretic, 1.0, 1e-4);
  EXPECT_NEAR(a.damping / b.damping, 1.0, 1e-4);
  EXPECT_NEAR(a.input / b.input, 1.0, 1e-4);
}

}  // namespace
}  // namespace isolab::integrators
