// The bearing presets against closed forms: the friction pendulum's energy per cycle 4 mu W (D -
// u_y) at constant friction and, with mu(v), the integral of mu over a sine cycle in Bessel and
// Struve functions; the lead core's adiabatic temperature rise ln(1 + E2 Qd kappa / C) / E2 and
// its decay by conduction; the HDR bearing's secant stiffness and equivalent damping at its
// design strain; the velocity term of the tangent against finite differences.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "isolab/hysteresis/hdr_bearing.h"
#include "isolab/core/errors.h"
#include "isolab/hysteresis/cyclic_test.h"
#include "isolab/hysteresis/law_parameters.h"
#include "isolab/hysteresis/parallel_assembly.h"

namespace isolab::hysteresis {
namespace {

constexpr double kPi = std::numbers::pi;

LawParameters Make(LawType type, ParameterForm form, std::vector<double> values) {
  return LawParameters::Make(type, form, values);
}
ParallelAssembly One(const LawParameters& parameters) {
  return ParallelAssembly({{"bearing", parameters}});
}

// Friction pendulum, kN and mm: W = 2000 kN on R = 2236 mm (T = 3 s), u_y = 0.5 mm.
constexpr double kW = 2000, kR = 2236, kUy = 0.5;
LawParameters ConstantFriction(double mu) {
  return Make(LawType::kFrictionPendulum, ParameterForm::kMechanical,
              {kW, kR, kUy, mu, NAN, NAN, NAN});
}
LawParameters VelocityFriction(double slow, double fast, double a, double uy = kUy) {
  return Make(LawType::kFrictionPendulum, ParameterForm::kMechanical,
              {kW, kR, uy, NAN, slow, fast, a});
}

TEST(FrictionPendulum, ConstantFrictionDissipatesFourMuWTimesDMinusUyPerCycle) {
  for (const double amplitude : {25.0, 100.0, 300.0}) {
    CyclicProtocol protocol;
    protocol.amplitude = amplitude;
    protocol.period = 3.0;
    protocol.cycles = 3;
    const CyclicResult result = RunCyclicTest(One(ConstantFriction(0.06)), protocol);
    const double exact = 4 * 0.06 * kW * (amplitude - kUy);
    for (std::size_t c = 1; c < result.cycles.size(); ++c) {
      EXPECT_NEAR(result.cycles[c].dissipated, exact, 1e-9 * exact) << "D = " << amplitude;
    }
    // Peak force W D / R + mu W.
    EXPECT_NEAR(result.cycles.back().peak_force, kW * amplitude / kR + 0.06 * kW, 1e-9 * kW);
  }
}

TEST(FrictionPendulum, ConstantFrictionIsBhm2) {
  const LawKernel pendulum = ConstantFriction(0.05).Kernel();
  const LawKernel bhm2 = Make(LawType::kBhm2, ParameterForm::kMechanical,
                              {kW / kR + 0.05 * kW / kUy, kW / kR, 0.05 * kW})
                             .Kernel();
  LawState a, b;
  LawResponse ra, rb;
  for (int k = 0; k <= 2000; ++k) {
    const double u = 150 * std::sin(2 * kPi * k / 700.0) * (1 + k / 1000.0);
    LawState ta, tb;
    UpdateLaw(pendulum, a, {u, 10.0, 0.0}, &ta, &ra);
    UpdateLaw(bhm2, b, {u, 10.0, 0.0}, &tb, &rb);
    ASSERT_NEAR(ra.force, rb.force, 1e-9 * kW) << "u = " << u;
    ASSERT_NEAR(ra.stiffness, rb.stiffness, 1e-9 * kW);
    a = ta;
    b = tb;
  }
}

// L_1, the modified Struve function, by its power series (x <= 15 here, long double).
double StruveL1(double x) {
  long double sum = 0.0L, half = x / 2.0L;
  for (int k = 0; k < 200; ++k) {
    sum += std::pow(half, 2 * k + 2) / (std::tgamma(k + 1.5L) * std::tgamma(k + 2.5L));
  }
  return static_cast<double>(sum);
}

// Energy of a sine cycle u = D sin(omega t) for u_y -> 0: 4 W D int_0^(pi/2) mu(D omega cos th)
// cos th d th = 4 W D [mu_fast - (mu_fast - mu_slow) J(a D omega)], with
// J(x) = int_0^(pi/2) exp(-x cos th) cos th d th = 1 - (pi/2) (I_1(x) - L_1(x)).
double CycleEnergy(double slow, double fast, double a, double amplitude, double period) {
  const double x = a * amplitude * 2 * kPi / period;
  const double j = 1.0 - 0.5 * kPi * (std::cyl_bessel_i(1.0, x) - StruveL1(x));
  return 4 * kW * amplitude * (fast - (fast - slow) * j);
}

TEST(FrictionPendulum, VelocityDependentCycleEnergyMatchesTheBesselStruveClosedForm) {
  // mu from 0.04 (slow) to 0.10 (fast), a = 0.02 s/mm (20 s/m); u_y small so the closed form's
  // u_y -> 0 limit holds to about u_y / D.
  const double slow = 0.04, fast = 0.10, a = 0.02, amplitude = 100, uy = 0.005;
  double previous = 0.0;
  for (const double period : {10.0, 2.0, 1.0}) {
    CyclicProtocol protocol;
    protocol.amplitude = amplitude;
    protocol.period = period;
    protocol.cycles = 2;
    protocol.steps_per_cycle = 40000;
    const CyclicResult result = RunCyclicTest(One(VelocityFriction(slow, fast, a, uy)), protocol);
    const double exact = CycleEnergy(slow, fast, a, amplitude, period);
    EXPECT_NEAR(result.cycles.back().dissipated, exact, 2e-4 * exact) << "T = " << period;
    // Faster cycles dissipate more, between the slow and fast constant-friction bounds.
    EXPECT_GT(exact, previous);
    EXPECT_GT(exact, 4 * slow * kW * amplitude);
    EXPECT_LT(exact, 4 * fast * kW * amplitude);
    previous = exact;
  }
}

TEST(FrictionPendulum, VelocityTangentIsTheDerivativeInStickAndSlip) {
  const LawKernel law = VelocityFriction(0.04, 0.10, 0.02).Kernel();
  LawState committed;
  for (const double u : {0.3, -0.2, 40.0}) {  // stick from rest, stick reversed, slip
    for (const double v : {-80.0, 5.0, 300.0}) {
      LawState trial;
      LawResponse at, plus, minus;
      UpdateLaw(law, committed, {u, v, 0.0}, &trial, &at);
      const double h = 1e-4;
      UpdateLaw(law, committed, {u, v + h, 0.0}, &trial, &plus);
      UpdateLaw(law, committed, {u, v - h, 0.0}, &trial, &minus);
      const double numeric = (plus.force - minus.force) / (2 * h);
      EXPECT_NEAR(at.damping, numeric, 1e-6 * (1 + std::abs(numeric))) << u << ", " << v;
      EXPECT_NE(at.damping, 0.0);
    }
  }
}

// Lead-rubber, kN and mm: Qd = 78.5 kN (10 MPa on a 100 mm core), Kd = 1.2 kN/mm, Ku = 12 kN/mm;
// a 200 mm high core, rho c = 1.456e-3 kN/mm^2/degC (11200 kg/m^3 x 130 J/kg/degC).
constexpr double kQd = 78.5, kKd = 1.2, kKu = 12.0, kDiameter = 100, kHeight = 200,
                 kRhoC = 1.456e-3;
const double kCapacity = kRhoC * kPi * 0.25 * kDiameter * kDiameter * kHeight;  // kN mm / degC
const double kDy = kQd / (kKu - kKd);

LawParameters LeadRubberLaw(double conductivity = NAN) {
  const bool conducts = !std::isnan(conductivity);
  return Make(LawType::kLeadRubber, ParameterForm::kMechanical,
              {kQd, kKd, kKu, kDiameter, kHeight, kRhoC, conductivity, conducts ? 14.1 : NAN,
               conducts ? 60.0 : NAN, NAN});
}

TEST(LeadRubber, AdiabaticTemperatureRiseIsTheClosedForm) {
  const double amplitude = 150;
  CyclicProtocol protocol;
  protocol.amplitude = amplitude;
  protocol.period = 2.0;
  protocol.cycles = 5;
  const LawKernel kernel = LeadRubberLaw().Kernel();
  LawState state;
  LawResponse response;
  const int n = protocol.cycles * protocol.steps_per_cycle;
  int peak = 0;
  for (int k = 1; k <= n; ++k) {
    const double phase = 2 * kPi * k / protocol.steps_per_cycle;
    LawState trial;
    UpdateLaw(kernel, state, {amplitude * std::sin(phase), 0.0, k * 2.0 / 400}, &trial, &response);
    state = trial;
    if (k % protocol.steps_per_cycle != protocol.steps_per_cycle / 4) continue;
    ++peak;  // u = +D in cycle `peak`: the core has slipped (4 peak - 3)(D - D_y)
    const double kappa = (4 * peak - 3) * (amplitude - kDy);
    EXPECT_NEAR(state.accumulated_slip, kappa, 1e-9 * kappa);
    const double rise = std::log(1 + 0.0069 * kQd * kappa / kCapacity) / 0.0069;
    EXPECT_NEAR(state.temperature, rise, 1e-9 * rise) << "cycle " << peak;
    EXPECT_NEAR(response.force, kKd * amplitude + kQd * std::exp(-0.0069 * rise), 1e-9 * kQd);
  }
  // Four and a quarter cycles at 150 mm warm this core by about 75 degC, which costs it 40 % of
  // its strength: the order of the rises Kalpakidis & Constantinou measured.
  EXPECT_GT(state.temperature, 50.0);
  EXPECT_LT(state.temperature, 100.0);
}

TEST(LeadRubber, ConductionDecaysTheTemperatureAsExpOfTheIntegratedRate) {
  const LawParameters parameters = LeadRubberLaw(0.05);  // k_s = 50 W/m/degC = 0.05 kN/s/degC
  const LawKernel kernel = parameters.Kernel();
  const auto& law = std::get<LeadRubber>(kernel);
  // Heat by one excursion in 0.5 s, then hold still for 100 s with steps of 0.05 s.
  LawState state;
  LawResponse response;
  for (int k = 1; k <= 50; ++k) {
    LawState trial;
    UpdateLaw(kernel, state, {200.0 * k / 50, 0.0, 0.01 * k}, &trial, &response);
    state = trial;
  }
  const double t_hold = state.t, heated = state.temperature;
  for (int k = 1; k <= 2000; ++k) {
    LawState trial;
    UpdateLaw(kernel, state, {200.0, 0.0, t_hold + 0.05 * k}, &trial, &response);
    state = trial;
  }
  // Reference: T = T_hold exp(-int h dt), the integral by composite Simpson on a fine grid.
  const int m = 200000;
  const double dt = (state.t - t_hold) / m;
  double integral = 0.0;
  for (int k = 0; k <= m; ++k) {
    const double weight = (k == 0 || k == m) ? 1 : (k % 2 ? 4 : 2);
    integral += weight * law.heating.ConductionRate(t_hold + k * dt);
  }
  integral *= dt / 3;
  const double expected = heated * std::exp(-integral);
  EXPECT_NEAR(state.temperature, expected, 1e-4 * heated);
  EXPECT_LT(state.temperature, 0.8 * heated);  // conduction matters over 100 s
  // Holding still dissipates nothing but what the stiffening pre-yield branch takes back.
  EXPECT_NEAR(response.force, kKd * 200 + kQd * std::exp(-0.0069 * state.temperature), 1e-9 * kQd);
}

// A core a million times lighter than lead (rho c = 1.456e-9 kN/mm^2/degC: kN/mm^2 taken for MPa
// twice) conducts its heat away much faster than a step: the split update cooled it to the start
// temperature in each half step, so its loop was the cold one (area 25,100 kN mm a cycle here)
// while it reported 353 kN mm dissipated. The force drawn and the dissipation reported must be
// the same energy: the loop's area (the trapezoidal rule over the samples, an independent sum of
// the forces returned) against the law's dissipated energy, cycle by cycle; and the tangent is
// the derivative of that update.
TEST(LeadRubber, ACoreFarLighterThanLeadDissipatesWhatItsLoopEncloses) {
  const LawParameters parameters =
      Make(LawType::kLeadRubber, ParameterForm::kMechanical,
           {kQd, kKd, kKu, kDiameter, kHeight, kRhoC * 1e-6, 0.05, 14.1, 60.0, NAN});
  CyclicProtocol protocol;
  protocol.amplitude = 100.0;
  protocol.period = 2.0;
  protocol.cycles = 3;
  const CyclicResult result = RunCyclicTest(One(parameters), protocol);
  const int per_cycle = protocol.steps_per_cycle;
  for (int cycle = 0; cycle < protocol.cycles; ++cycle) {
    double area = 0.0;
    for (int k = cycle * per_cycle; k < (cycle + 1) * per_cycle; ++k) {
      area += 0.5 * (result.loop.force[k] + result.loop.force[k + 1]) *
              (result.loop.displacement[k + 1] - result.loop.displacement[k]);
    }
    const double dissipated = result.cycles[cycle].dissipated;
    std::printf("cycle %d: loop area %.1f kN mm, dissipated %.1f kN mm\n", cycle + 1, area,
                dissipated);
    // Held at the temperature its slip rate sustains, the core keeps part of its strength: its
    // loop is well inside the cold one, 4 Qd (D - D_y) (the split update drew the cold loop).
    const double cold = 4 * kQd * (protocol.amplitude - kDy);
    EXPECT_LT(area, 0.7 * cold);
    EXPECT_GT(area, 0.3 * cold);
    // The loop's area is the work done: what was dissipated plus the change of stored energy.
    // The first cycle starts from a virgin core and ends with its elastic part loaded (about 1 %
    // of the work here: 2 % allowed); the later ones start and end in nearly the same state (the
    // core still warming: 5e-5 and 6e-4 measured), so within 1e-3.
    EXPECT_NEAR(dissipated / area, 1.0, cycle == 0 ? 0.02 : 1e-3) << "cycle " << cycle + 1;
  }
  // The tangent of the implicit update against central differences, slipping and sticking.
  const LawKernel kernel = parameters.Kernel();
  LawState state;
  LawResponse response;
  for (int k = 1; k <= 300; ++k) {
    const double t = 0.005 * k, u = 100.0 * std::sin(kPi * t);
    LawState trial;
    UpdateLaw(kernel, state, {u, 0.0, t}, &trial, &response);
    if (k % 25 == 0) {
      for (const double du : {0.3, -0.3}) {
        const double h = 1e-5;
        LawResponse at, plus, minus;
        UpdateLaw(kernel, state, {u + du, 0.0, t}, &trial, &at);
        UpdateLaw(kernel, state, {u + du + h, 0.0, t}, &trial, &plus);
        UpdateLaw(kernel, state, {u + du - h, 0.0, t}, &trial, &minus);
        const double numeric = (plus.force - minus.force) / (2 * h);
        EXPECT_NEAR(at.stiffness, numeric, 1e-5 * (std::abs(numeric) + kKu)) << "t = " << t;
      }
      UpdateLaw(kernel, state, {u, 0.0, t}, &trial, &response);
    }
    state = trial;
    EXPECT_TRUE(std::isfinite(state.temperature) && state.temperature >= 0.0) << "t = " << t;
  }
}

TEST(LeadRubber, EndPlateFunctionIsContinuousAndTendsToItsSteadyState) {
  // The paper's two series for F(tau) meet at tau = 0.6, and F -> 8 / (3 pi) as tau -> inf.
  LeadCoreHeating heating;
  heating.conduction = 1.0;
  heating.diffusion = 1.0;
  const double below = 1.0 / heating.ConductionRate(0.6 - 1e-9);
  const double above = 1.0 / heating.ConductionRate(0.6 + 1e-9);
  EXPECT_NEAR(below, above, 2e-3 * above);
  EXPECT_NEAR(1.0 / heating.ConductionRate(1e8), 8 / (3 * kPi), 1e-4);
}

TEST(LeadRubber, WithoutHeatingIsBhm2AndBothFormsAgree) {
  const auto ku_form = Make(LawType::kLeadRubber, ParameterForm::kMechanical,
                            {kQd, kKd, kKu, NAN, NAN, NAN, NAN, NAN, NAN, NAN});
  const auto dy_form = Make(LawType::kLeadRubber, ParameterForm::kMathematical,
                            {kQd, kKd, kDy, NAN, NAN, NAN, NAN, NAN, NAN, NAN});
  EXPECT_NEAR(dy_form.Values(ParameterForm::kMechanical)[2], kKu, 1e-12);
  EXPECT_NEAR(ku_form.Values(ParameterForm::kMathematical)[2], kDy, 1e-12);
  const LawKernel a = ku_form.Kernel(), b = dy_form.Kernel();
  const LawKernel bhm2 = Make(LawType::kBhm2, ParameterForm::kMechanical, {kKu, kKd, kQd}).Kernel();
  LawState sa, sb, sc;
  for (int k = 0; k <= 1000; ++k) {
    const double u = 120 * std::sin(2 * kPi * k / 300.0);
    LawState ta, tb, tc;
    LawResponse ra, rb, rc;
    UpdateLaw(a, sa, {u, 0, 0}, &ta, &ra);
    UpdateLaw(b, sb, {u, 0, 0}, &tb, &rb);
    UpdateLaw(bhm2, sc, {u, 0, 0}, &tc, &rc);
    ASSERT_NEAR(ra.force, rc.force, 1e-9 * kQd);
    ASSERT_NEAR(rb.force, rc.force, 1e-9 * kQd);
    ASSERT_NEAR(ta.dissipated, tc.dissipated, 1e-9 * (1 + tc.dissipated));
    sa = ta;
    sb = tb;
    sc = tc;
  }
}

TEST(HdrBearing, ReproducesTheDesignStiffnessAndDampingAtTheDesignStrain) {
  // G = 0.4 MPa = 4e-4 kN/mm^2, a 650 mm bearing (A = 331831 mm^2), T_r = 150 mm, 15 % damping
  // at 150 % strain (D = 225 mm).
  const double g = 4e-4, area = kPi * 325 * 325, tr = 150, xi = 0.15, strain = 1.5;
  for (const double yield_strain : std::vector<double>{NAN, 0.05, 0.3}) {
    const auto law = Make(LawType::kHdrBearing, ParameterForm::kMechanical,
                          {g, area, tr, xi, strain, yield_strain});
    CyclicProtocol protocol;
    protocol.amplitude = strain * tr;
    protocol.period = 2.0;
    const CyclicResult result = RunCyclicTest(One(law), protocol);
    const double k_eff = g * area / tr, d = strain * tr;
    const double peak = result.cycles.back().peak_force;
    const double energy = result.cycles.back().dissipated;
    EXPECT_NEAR(peak / d, k_eff, 1e-12 * k_eff);
    EXPECT_NEAR(energy / (2 * kPi * k_eff * d * d), xi, 1e-12);
  }
}

TEST(BearingParameters, RulesNameTheKey) {
  const auto violation = [](LawType type, ParameterForm form, std::vector<double> values) {
    try {
      LawParameters::Make(type, form, values);
    } catch (const InvalidParameter& error) {
      return error.violation();
    }
    ADD_FAILURE() << "no violation";
    return ParameterViolation{};
  };
  const auto mech = ParameterForm::kMechanical, math = ParameterForm::kMathematical;
  EXPECT_EQ(violation(LawType::kFrictionPendulum, mech, {-1, kR, kUy, 0.05, NAN, NAN, NAN}).key,
            "w");
  EXPECT_EQ(violation(LawType::kFrictionPendulum, mech, {kW, 0, kUy, 0.05, NAN, NAN, NAN}).key,
            "r");
  EXPECT_EQ(violation(LawType::kFrictionPendulum, mech, {kW, kR, 0, 0.05, NAN, NAN, NAN}).key,
            "uy");
  EXPECT_EQ(violation(LawType::kFrictionPendulum, mech, {kW, kR, kUy, NAN, NAN, NAN, NAN}).rule,
            "is required (or mu_slow, mu_fast and a)");
  EXPECT_EQ(violation(LawType::kFrictionPendulum, mech, {kW, kR, kUy, 0.05, 0.04, NAN, NAN}).key,
            "mu_slow");
  EXPECT_EQ(violation(LawType::kFrictionPendulum, mech, {kW, kR, kUy, NAN, 0.04, NAN, 1}).key,
            "mu_fast");
  EXPECT_EQ(
      violation(LawType::kFrictionPendulum, mech, {kW, kR, kUy, NAN, 0.1, 0.05, 1}).Describe(),
      "mu_fast = 0.05 (must be >= mu_slow = 0.1)");
  EXPECT_EQ(violation(LawType::kFrictionPendulum, mech, {kW, kR, kUy, NAN, 0.04, 0.1, -1}).key,
            "a");
  const double no = NAN;
  EXPECT_EQ(violation(LawType::kLeadRubber, mech, {0, kKd, kKu, no, no, no, no, no, no, no}).key,
            "qd");
  EXPECT_EQ(
      violation(LawType::kLeadRubber, mech, {kQd, kKd, 1.0, no, no, no, no, no, no, no}).Describe(),
      "ku = 1 (must be > kd = 1.2)");
  EXPECT_EQ(violation(LawType::kLeadRubber, math, {kQd, kKd, -1, no, no, no, no, no, no, no}).key,
            "dy");
  EXPECT_EQ(
      violation(LawType::kLeadRubber, mech, {kQd, kKd, kKu, no, 200, no, no, no, no, no}).rule,
      "is given, so lead_diameter is required (the heating of the lead core)");
  EXPECT_EQ(
      violation(LawType::kLeadRubber, mech, {kQd, kKd, kKu, 100, no, kRhoC, no, no, no, no}).key,
      "lead_height");
  EXPECT_EQ(
      violation(LawType::kLeadRubber, mech, {kQd, kKd, kKu, 100, 200, kRhoC, no, 14, no, no}).rule,
      "is given, so steel_conductivity is required (conduction out of the lead core)");
  EXPECT_EQ(
      violation(LawType::kLeadRubber, mech, {kQd, kKd, kKu, 100, 200, kRhoC, 0.05, 14, no, no}).key,
      "shim_thickness");
  EXPECT_EQ(
      violation(LawType::kLeadRubber, mech, {kQd, kKd, kKu, 100, 200, kRhoC, no, no, no, 0}).key,
      "e2");
  EXPECT_EQ(violation(LawType::kHdrBearing, mech, {4e-4, 1e5, 150, 0.15, 1.5, 1.6}).Describe(),
            "yield_strain = 1.6 (must be < strain = 1.5)");
  EXPECT_EQ(violation(LawType::kHdrBearing, mech, {4e-4, 1e5, 150, 0.6, 1.5, NAN}).key, "damping");
  EXPECT_EQ(violation(LawType::kHdrBearing, mech, {0, 1e5, 150, 0.15, 1.5, NAN}).key, "g");
}

}  // namespace
}  // namespace isolab::hysteresis
