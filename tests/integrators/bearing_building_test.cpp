// Newmark against IDA on a building isolated with each bearing preset (friction pendulum with
// constant and velocity-dependent friction, lead-rubber without heating, adiabatic and with
// conduction, HDR bearing from design data), and the rate-form Jacobian of each against finite
// differences of its residual, the lead core's temperature included.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "doc_table_row.h"
#include "integrators/jacobian_check.h"
#include "isolab/integrators/ida.h"
#include "isolab/integrators/newmark.h"
#include "isolab/structure/shear_building.h"
#include "rate_form_system.h"

namespace isolab::integrators {
namespace {

using hysteresis::LawParameters;
using hysteresis::LawType;
using hysteresis::ParameterForm;

struct Device {
  std::string name;
  std::string description;  // as docs/bearings.md's table names it
  LawType type;
  std::vector<double> mechanical;
};

void PrintTo(const Device& d, std::ostream* out) { *out << d.name; }

// kN, mm, s: a 75 t tributary share (W = 735 kN) on one bearing, periods near 2.5 s at 100 mm.
std::vector<Device> Devices() {
  const double no = NAN;
  return {
      {"friction_pendulum",
       "friction pendulum, `mu` = 0.06",
       LawType::kFrictionPendulum,
       {735, 2236, 0.5, 0.06, no, no, no}},
      {"friction_pendulum_mu_of_v",
       "friction pendulum, `mu(v)` 0.03-0.07",
       LawType::kFrictionPendulum,
       {735, 2236, 0.5, no, 0.03, 0.07, 0.02}},
      {"lead_rubber",
       "lead-rubber, no heating",
       LawType::kLeadRubber,
       {40, 0.3, 3, no, no, no, no, no, no, no}},
      {"lead_rubber_adiabatic",
       "lead-rubber, adiabatic",
       LawType::kLeadRubber,
       {40, 0.3, 3, 75, 150, 1.456e-3, no, no, no, no}},
      {"lead_rubber_conduction",
       "lead-rubber, conduction",
       LawType::kLeadRubber,
       {40, 0.3, 3, 75, 150, 1.456e-3, 0.05, 14.1, 27, no}},
      {"hdr_bearing",
       "HDR from design data",
       LawType::kHdrBearing,
       {4e-4, 115000, 100, 0.15, 1.5, no}},
  };
}

structure::Structure Building(const Device& device) {
  structure::ShearBuilding building;
  building.isolated = true;
  building.base_mass = 0.025;  // 25 t in kN s^2 / mm
  building.isolation = hysteresis::ParallelAssembly(
      {{device.name,
        LawParameters::Make(device.type, ParameterForm::kMechanical, device.mechanical)}});
  const auto story = hysteresis::SingleLaw(LawType::kLinearSpring, {76.0});
  building.stories = {{"s1", 0.025, 3200, story}, {"s2", 0.025, 3200, story}};
  building.damping.kind = structure::SuperstructureDamping::Kind::kRayleigh;
  building.damping.rayleigh_ratios[0] = building.damping.rayleigh_ratios[1] = 0.02;
  return structure::BuildShearBuilding(building).structure;
}

// A two-frequency ground acceleration (mm/s^2, peak about 0.2 g) over 8 s, sampled at 0.01 s.
Excitation Shaking() {
  Excitation excitation = Excitation::Uniform({});
  excitation.ground[0].acceleration.dt = 0.01;
  for (int k = 0; k <= 800; ++k) {
    const double t = 0.01 * k;
    excitation.ground[0].acceleration.values.push_back(
        1500.0 * std::sin(std::numbers::pi * t / 8) *
        (std::sin(2 * std::numbers::pi * 0.5 * t) +
         0.5 * std::sin(2 * std::numbers::pi * 2.1 * t)));
  }
  return excitation;
}

class BearingBuilding : public ::testing::TestWithParam<Device> {
 public:
  // docs/bearings.md quotes IdaAgreesWithNewmark's rows (scripts/doc_tables/test_printout.py).
  static void SetUpTestSuite() {
    isolab::testing::PrintTableHeader({"device", "peak isolator [mm]",
                                       "max \\|IDA - Newmark\\| [mm]", "max force difference [kN]",
                                       "events", "energy balance IDA / Newmark"});
  }
};

TEST_P(BearingBuilding, JacobianIsTheDerivativeOfTheResidual) {
  const structure::Structure building = Building(GetParam());
  const Excitation excitation = Shaking();
  RateFormSystem system(building, excitation);
  testing::ExpectJacobianIsTheDerivativeOfTheResidual(system);
}

TEST_P(BearingBuilding, IdaAgreesWithNewmark) {
  const Device& device = GetParam();
  const structure::Structure building = Building(device);
  const Excitation excitation = Shaking();
  IdaOptions tight;
  tight.relative_tolerance = 1e-9;
  tight.absolute_tolerance = 1e-9;
  ResponseHistory ida, newmark;
  const RunSummary ida_summary = RunIda(building, excitation, {0.01, 800}, tight, &ida);
  const RunSummary newmark_summary =
      RunNewmark(building, excitation, {0.0001, 80000, 100}, {}, &newmark);
  ASSERT_TRUE(ida_summary.ok()) << ida_summary.message;
  ASSERT_TRUE(newmark_summary.ok()) << newmark_summary.message;
  const auto base_ida = ida.displacement.col(0), base_newmark = newmark.displacement.col(0);
  const double peak = base_ida.cwiseAbs().maxCoeff();
  const double difference = (base_ida - base_newmark).cwiseAbs().maxCoeff();
  const double force_peak = ida.connection_force.col(0).cwiseAbs().maxCoeff();
  const double force_difference =
      (ida.connection_force.col(0) - newmark.connection_force.col(0)).cwiseAbs().maxCoeff();
  isolab::testing::PrintTableRow(
      {device.description, isolab::testing::Fixed(peak, 2),
       isolab::testing::Scientific(difference, 1), isolab::testing::Scientific(force_difference, 1),
       std::to_string(ida_summary.events),
       isolab::testing::Scientific(ida_summary.energy_balance_error, 1) + " / " +
           isolab::testing::Scientific(newmark_summary.energy_balance_error, 1)});
  EXPECT_GT(peak, 30.0);  // the bearing is well past yield
  EXPECT_GT(ida_summary.events, 4);
  // Measured: displacements within 1e-6 and forces within 2e-5 of their peaks.
  EXPECT_LT(difference, 1e-5 * peak);
  EXPECT_LT(force_difference, 1e-4 * force_peak);
  EXPECT_LT(ida_summary.energy_balance_error, 1e-5);
  EXPECT_LT(newmark_summary.energy_balance_error, 1e-4);
  const Energies& a = ida.energies.back();
  const Energies& b = newmark.energies.back();
  EXPECT_NEAR(a.hysteretic / b.hysteretic, 1.0, 1e-3);
  EXPECT_NEAR(a.input / b.input, 1.0, 1e-3);
}

INSTANTIATE_TEST_SUITE_P(Devices, BearingBuilding, ::testing::ValuesIn(Devices()),
                         [](const auto& info) { return info.param.name; });

// A lead core a million times lighter than lead conducts its heat away faster than any step. The
// split update kept the cold strength in Newmark's force while taking almost none of the work as
// heat (an energy balance error of 0.68; IDA, which integrates the temperature as a state, was
// right); the implicit heat balance of such a step keeps force and dissipation together, and
// Newmark converges to IDA.
TEST(BearingBuildingLightCore, NewmarkClosesItsEnergyBalanceAndConvergesToIda) {
  const Device device{"lead_rubber_light_core",
                      "lead-rubber, a core a million times lighter",
                      LawType::kLeadRubber,
                      {40, 0.3, 3, 75, 150, 1.456e-9, 0.05, 14.1, 27, NAN}};
  const structure::Structure building = Building(device);
  const Excitation excitation = Shaking();
  IdaOptions tight;
  tight.relative_tolerance = 1e-8;
  tight.absolute_tolerance = 1e-8;
  ResponseHistory ida;
  const RunSummary ida_summary = RunIda(building, excitation, {0.01, 800}, tight, &ida);
  ASSERT_TRUE(ida_summary.ok()) << ida_summary.message;
  const double peak_ida = ida.displacement.col(0).cwiseAbs().maxCoeff();
  double previous_error = INFINITY;
  for (const double dt : {0.005, 0.0005}) {
    ResponseHistory newmark;
    const int steps = static_cast<int>(std::lround(8.0 / dt));
    const RunSummary summary = RunNewmark(
        building, excitation, {dt, steps, static_cast<int>(std::lround(0.01 / dt))}, {}, &newmark);
    ASSERT_TRUE(summary.ok()) << summary.message;
    const double peak = newmark.displacement.col(0).cwiseAbs().maxCoeff();
    const double error = std::abs(peak / peak_ida - 1.0);
    std::printf("light core, dt = %g s: peak %.3f mm (IDA %.3f mm, %.2e), energy balance %.1e\n",
                dt, peak, peak_ida, error, summary.energy_balance_error);
    EXPECT_LT(summary.energy_balance_error, 1e-2) << "dt = " << dt;
    EXPECT_LT(error, 0.05) << "dt = " << dt;
    EXPECT_LT(error, previous_error) << "dt = " << dt;  // converging, not just close
    previous_error = error;
  }
  EXPECT_LT(previous_error, 0.01);
}

}  // namespace
}  // namespace isolab::integrators
