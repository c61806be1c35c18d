// Bidirectional laws driven round a circle u = R (cos theta, sin theta), N equal steps a
// revolution, against closed forms (docs/bidirectional.md derives them):
//
// * A slider of strength fs behind an elastic link (parallel form: |u - u_s| = u_y = fs / kp)
//   settles on a circle of radius rho = sqrt(R^2 - u_y^2): it moves across its own radius, so
//   the link u - u_s is tangent to the slider's circle. It dissipates 2 pi fs rho a revolution.
// * The return map's steady state is a polygon whose chords, extended by u_y, reach the driving
//   points: rho_N^2 + 2 rho_N u_y s + u_y^2 = R^2, s = sin(pi / N), dissipating 2 N fs rho_N s;
//   the update reproduces it to round-off and converges to the continuous value at first order,
//   with relative error pi u_y / (N rho) + O(N^-2).
// * Series form (slider x, h(x) = ke x + g(x)): ke u = h(x) + fs t with t across x, so
//   h_r(rho) = sqrt(ke^2 R^2 - fs^2); discretely h_r(rho_N) = -fs s + sqrt(fs^2 s^2 + ke^2 R^2 -
//   fs^2). With the trilinear g beyond uc this is the Newton-solved return map.
// * Bouc-Wen settles on its yield circle |z| = Z = (alpha / (beta (gamma + delta)))^(1/nu) with
//   z leading u by the angle whose cosine is Z / (alpha R): 2 pi Z sqrt(R^2 - (Z / alpha)^2) a
//   revolution; the trapezoidal update converges to it at second order.
// * Friction pendulum at constant angular speed: |v| = R omega, so mu(|v|) is constant and the
//   friction dissipates mu(R omega) W times the slider's travel (the discrete polygon above).
// * Lead-rubber heated adiabatically: the core temperature is ln(1 + E2 Qd0 kappa / C) / E2 of
//   the accumulated slip kappa, which grows by the polygon's perimeter each revolution.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "isolab/hysteresis/law_parameters.h"
#include "isolab/hysteresis/plan_law_kernel.h"

namespace isolab::hysteresis {
namespace {

constexpr double kPi = std::numbers::pi;

LawParameters Math(LawType type, std::vector<double> values) {
  return LawParameters::Make(type, ParameterForm::kMathematical, values);
}

struct Orbit {
  PlanLawState state;
  double last_revolution_dissipation = 0.0;
  double last_revolution_slip = 0.0;
};

// From rest to (R, 0) in one radial step, then `revolutions` turns of N steps at angular speed
// omega; the velocity passed is the exact one of the circle.
Orbit DriveOnCircle(const PlanLawKernel& kernel, double radius, int steps, int revolutions,
                    double omega = 1.0) {
  Orbit orbit;
  PlanLawResponse response;
  PlanLawState trial;
  UpdatePlanLaw(kernel, orbit.state, {{radius, 0.0}, {0.0, radius * omega}, 0.0}, &trial,
                &response);
  orbit.state = trial;
  for (int r = 0; r < revolutions; ++r) {
    const double dissipated = Dissipated(orbit.state);
    const double slip = orbit.state.x.accumulated_slip;
    for (int k = 1; k <= steps; ++k) {
      const double theta = 2 * kPi * (r * steps + k) / steps;
      const Vec2 direction{std::cos(theta), std::sin(theta)};
      UpdatePlanLaw(kernel, orbit.state,
                    {radius * direction, radius * omega * Perpendicular(direction), theta / omega},
                    &trial, &response);
      orbit.state = trial;
    }
    orbit.last_revolution_dissipation = Dissipated(orbit.state) - dissipated;
    orbit.last_revolution_slip = orbit.state.x.accumulated_slip - slip;
  }
  return orbit;
}

// The parallel-form polygon's radius rho_N.
double PolygonRadius(double radius, double uy, int steps) {
  const double s = std::sin(kPi / steps);
  return -uy * s + std::sqrt(uy * uy * s * s + radius * radius - uy * uy);
}

TEST(CircularOrbit, ParallelSliderSettlesOnThePolygonOfTheReturnMap) {
  // BHM2 k0 = 10, k1 = 1, uy = 1: kp = 9, fs = 9; R = 100 >> uy.
  const PlanLawKernel bhm2 = CoupledKernel(Math(LawType::kBhm2, {10, 1, 1}));
  const double radius = 100, uy = 1, fs = 9;
  for (const int steps : {16, 100, 1000}) {
    const Orbit orbit = DriveOnCircle(bhm2, radius, steps, 3);
    const double rho = PolygonRadius(radius, uy, steps);
    EXPECT_NEAR(Norm(Slider(orbit.state)), rho, 1e-12 * radius) << steps;
    EXPECT_NEAR(orbit.last_revolution_dissipation, 2 * steps * fs * rho * std::sin(kPi / steps),
                1e-11 * fs * radius)
        << steps;
    // The branch carries fs exactly and the link is tangent to the slider's circle.
    const Vec2 link = Displacement(orbit.state) - Slider(orbit.state);
    EXPECT_NEAR(Norm(link), uy, 1e-12 * radius);
  }
}

// The polygon's perimeter falls short of its circle's by the chord term pi^2 / (6 N^2) relative
// (N sin(pi/N) / pi), the slider's lag adds the first-order term: the relative error of the
// dissipation is e_N = a / N + pi^2 / (6 N^2) + ..., with a = pi u_y / rho for the parallel form.
// For R / u_y = 100 the two terms are equal near N = 50, so the chord term is taken out before
// the order is measured.
double FirstOrderPart(double relative_error, int steps) {
  return relative_error - kPi * kPi / (6.0 * steps * steps);
}

TEST(CircularOrbit, ParallelSliderDissipationConvergesAtFirstOrderToTwoPiFsRho) {
  const PlanLawKernel bhm2 = CoupledKernel(Math(LawType::kBhm2, {10, 1, 1}));
  const double radius = 100, uy = 1, fs = 9;
  const double rho = std::sqrt(radius * radius - uy * uy);
  const double exact = 2 * kPi * fs * rho;
  std::vector<double> errors;
  for (const int steps : {100, 200, 400, 800}) {
    const double error = FirstOrderPart(
        1 - DriveOnCircle(bhm2, radius, steps, 2).last_revolution_dissipation / exact, steps);
    EXPECT_NEAR(error * steps * rho / (kPi * uy), 1.0, 0.01) << steps;
    errors.push_back(error);
  }
  for (std::size_t i = 1; i < errors.size(); ++i) {
    EXPECT_NEAR(std::log2(errors[i - 1] / errors[i]), 1.0, 0.01);
  }
  // The continuous value itself, at N = 10^5 (error 3.1e-7), once the start's transient is past.
  EXPECT_NEAR(DriveOnCircle(bhm2, radius, 100000, 2).last_revolution_dissipation, exact,
              4e-7 * exact);
}

// h_r^-1: the radius with ke rho + g_r(rho) = value.
double SeriesRadius(const SeriesSlider& law, double value) {
  double slope = 0.0;
  return law.spring.SolveInSeries(law.ke, value, &slope);
}

TEST(CircularOrbit, SeriesSlidersSettleOnTheirPolygonsAndConvergeAtFirstOrder) {
  struct Case {
    const char* name;
    LawParameters law;
    double radius;
  };
  const std::vector<Case> cases = {
      {"elastoplastic", Math(LawType::kElastoplastic, {3.225241, 0.597}), 30},
      {"bhm1", Math(LawType::kBhm1, {1, 0.2, 20}), 300},
      // Beyond uc on the whole orbit: the Newton-solved return map.
      {"thm1_hard", Math(LawType::kThm1, {1, 0.2, 0.45, 20, 120}), 300},
      {"thm1_negative_k2", Math(LawType::kThm1, {0.863754, 0.402485, -0.792654, 7.146, 125.542}),
       200},
  };
  for (const Case& c : cases) {
    const PlanLawKernel kernel = CoupledKernel(c.law);
    const SeriesSlider& law = std::get<PlanSeriesSlider>(kernel).law;
    const double ke = law.ke, fs = law.fs, kr = ke * c.radius;
    const double rho = SeriesRadius(law, std::sqrt(kr * kr - fs * fs));
    const double exact = 2 * kPi * fs * rho;
    std::vector<double> errors;
    for (const int steps : {200, 400, 800}) {
      const Orbit orbit = DriveOnCircle(kernel, c.radius, steps, 3);
      const double s = std::sin(kPi / steps);
      const double rho_n =
          SeriesRadius(law, -fs * s + std::sqrt(fs * fs * s * s + kr * kr - fs * fs));
      EXPECT_NEAR(Norm(Slider(orbit.state)), rho_n, 1e-11 * c.radius) << c.name << " N " << steps;
      EXPECT_NEAR(orbit.last_revolution_dissipation, 2 * steps * fs * rho_n * s,
                  1e-10 * fs * c.radius)
          << c.name << " N " << steps;
      errors.push_back(FirstOrderPart(1 - orbit.last_revolution_dissipation / exact, steps));
    }
    EXPECT_GT(rho, std::get<PlanSeriesSlider>(kernel).law.spring.uc == INFINITY
                       ? 0.0
                       : std::get<PlanSeriesSlider>(kernel).law.spring.uc)
        << c.name << ": the orbit should keep g beyond uc";
    for (std::size_t i = 1; i < errors.size(); ++i) {
      EXPECT_NEAR(std::log2(errors[i - 1] / errors[i]), 1.0, 0.05) << c.name;
    }
  }
}

TEST(CircularOrbit, BoucWenSettlesOnItsYieldCircleAndConvergesAtSecondOrder) {
  for (const auto& values : {std::vector<double>{1.0, 0.05, 0.5, 0.5, 1.0},
                             std::vector<double>{1.0, 0.02, 0.3, 0.7, 2.0}}) {
    const PlanLawKernel kernel = CoupledKernel(Math(LawType::kBoucWen, values));
    const BoucWen& law = std::get<PlanBoucWen>(kernel).law;
    const double z_yield = std::pow(law.alpha / (law.beta * (law.gamma + law.delta)), 1 / law.nu);
    const double radius = 200;
    const double uy = z_yield / law.alpha;
    const double exact = 2 * kPi * z_yield * std::sqrt(radius * radius - uy * uy);
    std::vector<double> errors;
    for (const int steps : {200, 400, 800}) {
      const Orbit orbit = DriveOnCircle(kernel, radius, steps, 4);
      EXPECT_NEAR(Norm(Force(orbit.state)), z_yield, 1e-3 * z_yield) << "nu " << law.nu;
      errors.push_back(std::abs(1 - orbit.last_revolution_dissipation / exact));
    }
    EXPECT_LT(errors.back(), 1e-4) << "nu " << law.nu;
    for (std::size_t i = 1; i < errors.size(); ++i) {
      EXPECT_NEAR(std::log2(errors[i - 1] / errors[i]), 2.0, 0.1) << "nu " << law.nu;
    }
  }
}

TEST(CircularOrbit, FrictionPendulumReadsFrictionAtTheResultantVelocity) {
  // W = 1000 kN, R = 2000 mm, u_y = 1 mm; mu from 0.03 to 0.09, a = 0.02 s/mm. Orbit of 150 mm
  // in 3 s: |v| = 314 mm/s, where mu = 0.0899, though each component's speed swings through 0.
  const PlanLawKernel kernel =
      CoupledKernel(Math(LawType::kFrictionPendulum, {1000, 2000, 1, NAN, 0.03, 0.09, 0.02}));
  const FrictionPendulum& law = std::get<PlanFrictionPendulum>(kernel).law;
  const double radius = 150, omega = 2 * kPi / 3, uy = 1;
  const double mu = law.Friction(radius * omega);
  for (const int steps : {100, 1000}) {
    const Orbit orbit = DriveOnCircle(kernel, radius, steps, 3, omega);
    const double rho = PolygonRadius(radius, uy, steps);
    const double perimeter = 2 * steps * rho * std::sin(kPi / steps);
    EXPECT_NEAR(orbit.last_revolution_slip, perimeter, 1e-10 * radius);
    EXPECT_NEAR(orbit.last_revolution_dissipation, mu * law.weight * perimeter,
                1e-10 * law.weight * radius);
    // The friction force is mu W on the circle's tangent-ish link direction.
    const Vec2 friction = Force(orbit.state) - law.stiffness * Displacement(orbit.state);
    EXPECT_NEAR(Norm(friction), mu * law.weight, 1e-10 * law.weight);
  }
}

TEST(CircularOrbit, LeadCoreHeatsWithTheResultantSlipAsTheAdiabaticClosedForm) {
  // Qd = 78.5 kN, Kd = 1.2 kN/mm, Ku = 12 kN/mm, a 100 mm core 200 mm high (bearing_laws_test).
  const LawParameters parameters = LawParameters::Make(
      LawType::kLeadRubber, ParameterForm::kMechanical,
      std::vector<double>{78.5, 1.2, 12, 100, 200, 1.456e-3, NAN, NAN, NAN, NAN});
  const PlanLawKernel kernel = CoupledKernel(parameters);
  const LeadRubber& law = std::get<PlanLeadRubber>(kernel).law;
  const double radius = 150, e2 = law.heating.e2;
  const int steps = 400;
  const Orbit orbit = DriveOnCircle(kernel, radius, steps, 3);
  const double kappa = orbit.state.x.accumulated_slip;
  const double rho = PolygonRadius(radius, law.slider.uy, steps);
  EXPECT_NEAR(orbit.last_revolution_slip, 2 * steps * rho * std::sin(kPi / steps), 1e-9 * radius);
  const double rise = std::log1p(e2 * law.qd * kappa / law.heating.capacity) / e2;
  EXPECT_NEAR(orbit.state.x.temperature, rise, 1e-9 * rise);
  EXPECT_GT(rise, 50.0);  // three turns at 150 mm heat this core by tens of degrees
  const Vec2 lead = Force(orbit.state) - law.kd * Displacement(orbit.state);
  EXPECT_NEAR(Norm(lead), law.qd * std::exp(-e2 * rise), 1e-9 * law.qd);
}

}  // namespace
}  // namespace isolab::hysteresis
