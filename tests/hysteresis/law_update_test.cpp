// The update contract of every rate-independent law: exact for any monotone increment, tangent
// equal to the derivative of the update actually computed (in every phase, loading and
// unloading), pure trials, and work = stored + dissipated energy.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "isolab/hysteresis/law_parameters.h"

namespace isolab::hysteresis {
namespace {

struct LawCase {
  std::string name;
  LawKernel kernel;
  double scale;                        // displacement range the path explores
  std::vector<double> phase_tangents;  // slopes of every phase, from the paper's k0, k1, k2, k01
};

LawKernel Math(LawType type, std::vector<double> values) {
  return LawParameters::Make(type, ParameterForm::kMathematical, values).Kernel();
}

void PrintTo(const LawCase& c, std::ostream* out) { *out << c.name; }

std::vector<LawCase> Cases() {
  return {
      {"thm1_hard", Math(LawType::kThm1, {1, 0.2, 0.45, 20, 120}), 250, {1, 0.2, 0.45}},
      {"thm1_soft", Math(LawType::kThm1, {1, 0.2, 0.05, 20, 120}), 250, {1, 0.2, 0.05}},
      {"thm1_negative_k2",
       Math(LawType::kThm1, {0.863754, 0.402485, -0.792654, 7.146, 125.542}),
       200,
       {0.863754, 0.402485, -0.792654}},
      {"thm1_spring_limit",
       Math(LawType::kThm1, {1e6, 0.283532, 0.489882, 0, 64.809}),
       150,
       {0.283532, 0.489882}},
      {"thm2_hard", Math(LawType::kThm2, {1, 0.2, 0.45, 20, 120}), 250, {1, 1.25, 0.2, 0.45}},
      {"thm2_soft", Math(LawType::kThm2, {1, 0.2, 0.05, 20, 120}), 250, {1, 0.85, 0.2, 0.05}},
      {"thm2_uyh_below_uy",
       Math(LawType::kThm2, {1, 0.2, 0.45, 20, 10}),
       250,
       {1, 1.25, 0.2, 0.45}},
      {"thm2_zero_yield", Math(LawType::kThm2, {1, 0.2, 0.45, 0, 120}), 250, {0.2, 0.45}},
      {"thm1_equal_slopes_no_uyh", Math(LawType::kThm1, {1, 0.2, 0.2, 20, NAN}), 250, {1, 0.2}},
      {"thm1_mechanical_form",
       LawParameters::Make(LawType::kThm1, ParameterForm::kMechanical,
                           std::vector<double>{1, 0.25, 9.0 / 11.0, 20, 80})
           .Kernel(),
       250,
       {1, 0.2, 0.45}},
      {"bhm1", Math(LawType::kBhm1, {1, 0.2, 20}), 250, {1, 0.2}},
      {"bhm2", Math(LawType::kBhm2, {1, 0.2, 20}), 250, {1, 0.2}},
      {"elastoplastic", Math(LawType::kElastoplastic, {3.225241, 0.597}), 10, {3.225241, 0.0}},
      {"trilinear_elastic",
       Math(LawType::kTrilinearElastic, {0.283532, 0.489882, 64.809}),
       150,
       {0.283532, 0.489882}},
      {"linear_spring", Math(LawType::kLinearSpring, {0.7}), 100, {0.7}},
      // Only the virgin slopes are fixed numbers; after slip every slope carries phi(kappa).
      {"degrading_bhm2", Math(LawType::kDegradingBhm2, {1, 0.2, 20, 0.4, 300}), 250, {1}},
      {"degrading_elastoplastic", Math(LawType::kDegradingBhm2, {2, 0, 5, 0.6, 40}), 100, {2}},
      // The bearing presets at v = 0 and t = 0 (mu = mu_slow; the lead core heats
      // adiabatically), where they are rate-independent.
      {"friction_pendulum",
       Math(LawType::kFrictionPendulum, {1000, 2000, 1, 0.05, NAN, NAN, NAN}),
       250,
       {50.5, 0.5}},
      {"friction_pendulum_mu_of_v",
       Math(LawType::kFrictionPendulum, {1000, 2000, 2, NAN, 0.03, 0.09, 0.02}),
       250,
       {15.5, 0.5}},
      {"lead_rubber",
       Math(LawType::kLeadRubber, {60, 1, 6, NAN, NAN, NAN, NAN, NAN, NAN, NAN}),
       250,
       {11, 1}},
      // Only the virgin slope is fixed: heating lowers the strength, so the pre-yield slope.
      {"lead_rubber_heated",
       Math(LawType::kLeadRubber, {60, 1, 6, 100, 200, 1.456e-3, NAN, NAN, NAN, NAN}),
       250,
       {11}},
      {"hdr_bearing", Math(LawType::kHdrBearing, {4e-4, 331831, 150, 0.15, 1.5, NAN}), 250, {}},
      // Sliders in series, through every regime and beyond the last stop (capacity 900 mm):
      // ke = 0.02 W / u_y = 40, then 1 / (1/ke + (R_a + R_b) / W) with the radii of the regime's
      // two sliding surfaces (multiple_pendulum.h).
      {"triple_friction_pendulum",
       Math(LawType::kTripleFrictionPendulum,
            {1000, 2100, 280, 280, 2100, 0.06, 0.02, 0.02, 0.10, 400, 50, 50, 400, 0.5}),
       800,
       {40, 1 / (1 / 40.0 + 0.56), 1 / (1 / 40.0 + 2.38), 1 / (1 / 40.0 + 4.2)}},
      {"triple_friction_pendulum_unequal",
       Math(LawType::kTripleFrictionPendulum,
            {1200, 1800, 300, 250, 2400, 0.05, 0.01, 0.03, 0.09, 250, 60, 40, 350, 1.0}),
       700,
       {12, 1 / (1 / 12.0 + 0.25), 1 / (1 / 12.0 + 0.55 / 1.2), 1 / (1 / 12.0 + 2.05 / 1.2)}},
      {"double_friction_pendulum",
       Math(LawType::kDoubleFrictionPendulum, {800, 2000, 1500, 0.04, 0.07, 300, 250, 1}),
       500,
       {32, 1 / (1 / 32.0 + 2.5), 1 / (1 / 32.0 + 3500 / 800.0), 1 / (1 / 32.0 + 1.875)}},
      // Engaged, then slipping; the clearance adds a third phase of slope 0 between contacts.
      // Values off the path's grid, so no step lands exactly on a yield point.
      {"asymmetric_elastoplastic",
       Math(LawType::kAsymmetricElastoplastic, {2.13, 3.17, 6.71}),
       40,
       {2.13, 0}},
      {"backlash_elastoplastic",
       Math(LawType::kBacklashElastoplastic, {2.13, 3.17, 9.71}),
       40,
       {2.13, 0}},
      {"backlash_no_gap", Math(LawType::kBacklashElastoplastic, {2.13, 3.17, 0}), 40, {2.13, 0}},
  };
}

// Reversals at growing and shrinking amplitudes, so every phase is entered loading and unloading.
std::vector<double> Turns(double scale) {
  return {0.0, scale, -scale, 0.6 * scale, -0.3 * scale, 1.2 * scale, -1.2 * scale, 0.1 * scale};
}

std::vector<double> Path(double scale, int steps_per_unit_scale) {
  std::vector<double> path;
  const auto turns = Turns(scale);
  for (std::size_t i = 0; i + 1 < turns.size(); ++i) {
    const int n = static_cast<int>(
        std::ceil(std::abs(turns[i + 1] - turns[i]) / scale * steps_per_unit_scale));
    for (int k = (i == 0 ? 0 : 1); k <= n; ++k) {
      path.push_back(turns[i] + (turns[i + 1] - turns[i]) * k / n);
    }
  }
  return path;
}

// A law's whole state: StateSlots(kernel) LawStates, the law's own first (law_kernel.h).
using State = std::vector<LawState>;
State Rest(const LawKernel& kernel) { return State(StateSlots(kernel)); }

struct Step {
  State state;
  LawResponse response;
};

Step Trial(const LawKernel& kernel, const State& committed, double u) {
  Step step{State(committed.size()), {}};
  UpdateLaw(kernel, committed, {u, 0.0}, step.state, &step.response);
  return step;
}

// The committed state after following `path` from rest.
State Follow(const LawKernel& kernel, const std::vector<double>& path) {
  State state = Rest(kernel);
  for (const double u : path) state = Trial(kernel, state, u).state;
  return state;
}

void ExpectRelativelyEqual(double a, double b, double reference, const std::string& what) {
  EXPECT_NEAR(a, b, 1e-12 * std::max({std::abs(a), std::abs(b), reference})) << what;
}

class LawUpdate : public ::testing::TestWithParam<LawCase> {};

TEST_P(LawUpdate, OneCallEqualsAThousandSubIncrements) {
  const LawCase& c = GetParam();
  const double s = c.scale;
  // Start states: rest, after a positive excursion, after a negative one and a partial return.
  const std::vector<std::vector<double>> histories = {
      {0.0}, {0.5 * s, 1.1 * s}, {-1.1 * s, -0.4 * s}, {1.1 * s, -1.1 * s, -0.9 * s}};
  for (const auto& history : histories) {
    const State start = Follow(c.kernel, history);
    for (const double target : {1.3 * s, -1.3 * s, 0.05 * s, 0.7 * s}) {
      const Step one = Trial(c.kernel, start, target);
      State sub = start;
      Step last;
      for (int k = 1; k <= 1000; ++k) {
        last = Trial(c.kernel, sub, start[0].u + (target - start[0].u) * k / 1000.0);
        sub = last.state;
      }
      const std::string where =
          c.name + " from " + std::to_string(start[0].u) + " to " + std::to_string(target);
      ExpectRelativelyEqual(one.response.force, last.response.force, 1e-3 * s, where + " force");
      ExpectRelativelyEqual(one.state[0].slider, sub[0].slider, 1e-3 * s, where + " slider");
      ExpectRelativelyEqual(one.state[0].dissipated, sub[0].dissipated, 1e-3 * s,
                            where + " dissipated");
      ExpectRelativelyEqual(one.response.stiffness, last.response.stiffness, 1e-6,
                            where + " tangent");
    }
  }
}

TEST_P(LawUpdate, TangentIsTheDerivativeOfTheUpdateInEveryPhase) {
  const LawCase& c = GetParam();
  // Steps far above round-off: the stiff THM1 spring limit computes ke (u - u_h) with ke = 1e6.
  const double h = 1e-4 * c.scale;
  std::set<double> phases_seen;
  int checked = 0;
  State committed = Rest(c.kernel);
  for (const double u : Path(c.scale, 97)) {
    const Step at = Trial(c.kernel, committed, u);
    const double ahead = Trial(c.kernel, committed, u + h).response.force;
    const double behind = Trial(c.kernel, committed, u - h).response.force;
    const double right = (ahead - at.response.force) / h;
    const double left = (at.response.force - behind) / h;
    const double size = std::max({1.0, std::abs(left), std::abs(right)});
    if (std::abs(right - left) < 1e-5 * size) {  // no breakpoint within +-h: the update is smooth
      EXPECT_NEAR(at.response.stiffness, 0.5 * (left + right), 1e-5 * size)
          << c.name << " at u = " << u << " from committed u = " << committed[0].u;
      phases_seen.insert(std::round(at.response.stiffness * 1e4) / 1e4);
      ++checked;
    }
    committed = at.state;
  }
  EXPECT_GT(checked, 500);
  for (const double slope : c.phase_tangents) {
    EXPECT_TRUE(phases_seen.count(std::round(slope * 1e4) / 1e4))
        << c.name << ": no checked step in the phase of slope " << slope;
  }
}

// An iterate with no increment evaluates a law at its committed state. After a slipping
// increment that point is a corner of the update (slip on one side, stick on the other); the
// tangent there must be the one-sided derivative on the side the motion came from, so a slip
// that goes on starts on the slip tangent, whatever the round-off in the stick test.
TEST_P(LawUpdate, AtNoIncrementTheTangentIsTheDerivativeOfContinuedMotion) {
  const LawCase& c = GetParam();
  const double h = 1e-4 * c.scale;
  int checked = 0, slipping = 0;
  State committed = Rest(c.kernel);
  for (const double u : Path(c.scale, 97)) {
    const Step step = Trial(c.kernel, committed, u);
    const double direction = u >= committed[0].u ? 1.0 : -1.0;
    const bool slipped = step.state[0].slider != committed[0].slider;
    committed = step.state;
    const double at = Trial(c.kernel, committed, u).response.force;
    const double one = Trial(c.kernel, committed, u + direction * h).response.force;
    const double two = Trial(c.kernel, committed, u + 2 * direction * h).response.force;
    const double near = (one - at) / (direction * h), far = (two - one) / (direction * h);
    const double size = std::max({1.0, std::abs(near), std::abs(far)});
    if (std::abs(near - far) >= 1e-5 * size) continue;  // a breakpoint within 2h ahead
    EXPECT_NEAR(Trial(c.kernel, committed, u).response.stiffness, near, 1e-5 * size)
        << c.name << " at u = " << u << (slipped ? " after a slipping increment" : "");
    ++checked;
    slipping += slipped;
  }
  EXPECT_GT(checked, 500);
  const bool has_slider = std::holds_alternative<SeriesSlider>(c.kernel) ||
                          std::holds_alternative<ParallelSlider>(c.kernel) ||
                          std::holds_alternative<DegradingSlider>(c.kernel) ||
                          std::holds_alternative<FrictionPendulum>(c.kernel) ||
                          std::holds_alternative<LeadRubber>(c.kernel) ||
                          std::holds_alternative<SeriesArrangement>(c.kernel) ||
                          std::holds_alternative<PlaySlider>(c.kernel);
  if (has_slider) {
    EXPECT_GT(slipping, 100) << c.name << ": too few corners after a slip";
  }
}

// The slider's own laws, checked on the kernel's parts rather than its update formula: the
// slider force never exceeds fs; a slider that moved carries +-fs in the direction it moved; its
// work is fs times its travel.
void ExpectAdmissibleSlider(double slider_force, double fs, double travel, double work,
                            const std::string& where) {
  const double tolerance = 1e-9 * (fs + 1.0);
  EXPECT_LE(std::abs(slider_force), fs + tolerance) << where;
  if (std::abs(travel) > 1e-12) {
    EXPECT_NEAR(slider_force, travel > 0 ? fs : -fs, tolerance) << where;
  }
  EXPECT_NEAR(work, fs * std::abs(travel), 1e-9 * (1.0 + work)) << where;
}

TEST_P(LawUpdate, SliderStaysAdmissibleAndDissipatesFsTimesItsTravel) {
  const LawCase& c = GetParam();
  State state = Rest(c.kernel);
  for (const double u : Path(c.scale, 37)) {
    const Step next = Trial(c.kernel, state, u);
    const std::string where = c.name + " at u = " + std::to_string(u);
    const double travel = next.state[0].slider - state[0].slider;
    const double work = next.state[0].dissipated - state[0].dissipated;
    if (const auto* series = std::get_if<SeriesSlider>(&c.kernel)) {
      const double slider_force = next.response.force - series->spring.Force(next.state[0].slider);
      if (series->fs > 0) ExpectAdmissibleSlider(slider_force, series->fs, travel, work, where);
      // Element 1 carries the force; ke (u - u_h) loses about eps ke |u| to cancellation.
      EXPECT_NEAR(next.response.force, series->ke * (u - next.state[0].slider),
                  1e-9 * (1 + std::abs(next.response.force)) + 1e-14 * series->ke * std::abs(u))
          << where;
    } else if (const auto* parallel = std::get_if<ParallelSlider>(&c.kernel)) {
      const double branch_force = parallel->kp * (u - next.state[0].slider);
      if (parallel->fs > 0) ExpectAdmissibleSlider(branch_force, parallel->fs, travel, work, where);
      EXPECT_NEAR(next.response.force,
                  branch_force * (parallel->fs > 0) + parallel->spring.Force(u),
                  1e-9 * (1 + std::abs(next.response.force)))
          << where;
    } else if (const auto* degrading = std::get_if<DegradingSlider>(&c.kernel)) {
      // The undamaged branch is an elastoplastic slider; the damage only scales its force.
      const double branch_force = degrading->kp * (u - next.state[0].slider);
      const double phi = degrading->Factor(next.state[0].accumulated_slip);
      EXPECT_LE(std::abs(branch_force), degrading->fs * (1 + 1e-12)) << where;
      EXPECT_NEAR(next.state[0].accumulated_slip - state[0].accumulated_slip, std::abs(travel),
                  1e-12)
          << where;
      EXPECT_NEAR(next.response.force, phi * (branch_force + degrading->kh * u),
                  1e-9 * (1 + std::abs(next.response.force)))
          << where;
      EXPECT_GE(work, -1e-9 * (1 + std::abs(next.state[0].dissipated))) << where;
    } else if (const auto* chain = std::get_if<SeriesArrangement>(&c.kernel)) {
      // Every element carries the force: its slider force F - k z within +-f away from its stop,
      // +-f in the direction it moved unless it ended at its stop, and outward at the stop.
      double element_work = 0.0;
      for (int k = 0; k < chain->count; ++k) {
        const SeriesElement& e = chain->elements[k];
        const double z = next.state[k + 1].slider, moved = z - state[k + 1].slider;
        const double slider_force = next.response.force - e.stiffness * z;
        const double tolerance = 1e-9 * (e.strength + std::abs(next.response.force));
        EXPECT_LE(std::abs(z), e.stop) << where;
        if (std::abs(z) < e.stop) {
          EXPECT_LE(std::abs(slider_force), e.strength + tolerance) << where << " element " << k;
          if (std::abs(moved) > 1e-12) {
            EXPECT_NEAR(slider_force, moved > 0 ? e.strength : -e.strength, tolerance) << where;
          }
        } else {
          EXPECT_GE(slider_force * (z > 0 ? 1 : -1), -e.strength - tolerance) << where;
        }
        element_work += e.strength * std::abs(moved);
      }
      EXPECT_NEAR(work, element_work, 1e-9 * (1.0 + work)) << where;
      EXPECT_NEAR(next.state[0].slider, u - next.response.force / chain->ke,
                  1e-9 * (1 + std::abs(u)))
          << where;
    } else if (const auto* play = std::get_if<PlaySlider>(&c.kernel)) {
      // The contact carries the force; a slider that moved sits on the limit of its direction and
      // dissipates that limit times its travel.
      EXPECT_NEAR(next.response.force, play->k * play->Contact(u, next.state[0].slider),
                  1e-9 * (1 + std::abs(next.response.force)))
          << where;
      EXPECT_LE(next.response.force, play->fs_pos * (1 + 1e-12)) << where;
      EXPECT_GE(next.response.force, -play->fs_neg * (1 + 1e-12)) << where;
      if (std::abs(travel) > 1e-12) {
        const double strength = travel > 0 ? play->fs_pos : play->fs_neg;
        EXPECT_NEAR(next.response.force, travel > 0 ? strength : -strength, 1e-9 * strength)
            << where;
        EXPECT_NEAR(work, strength * std::abs(travel), 1e-9 * (1.0 + work)) << where;
      } else {
        EXPECT_EQ(work, 0.0) << where;
      }
    } else if (std::holds_alternative<FrictionPendulum>(c.kernel) ||
               std::holds_alternative<LeadRubber>(c.kernel)) {
      // The interface variable stays in [-1, 1]; a slider that moved sits at z = +-1 in the
      // direction it moved, and its travel is what the state accumulates.
      const UnitSlider& slider = std::holds_alternative<LeadRubber>(c.kernel)
                                     ? std::get<LeadRubber>(c.kernel).slider
                                     : std::get<FrictionPendulum>(c.kernel).slider;
      const double z = slider.Z(u, next.state[0].slider);
      EXPECT_LE(std::abs(z), 1 + 1e-9) << where;
      if (std::abs(travel) > 1e-12) {
        EXPECT_NEAR(z, travel > 0 ? 1 : -1, 1e-9) << where;
      }
      EXPECT_NEAR(next.state[0].accumulated_slip - state[0].accumulated_slip, std::abs(travel),
                  1e-12)
          << where;
    } else {
      EXPECT_EQ(work, 0.0) << where;
    }
    state = next.state;
  }
}

TEST_P(LawUpdate, WorkDoneEqualsStoredPlusDissipatedEnergy) {
  const LawCase& c = GetParam();
  State state = Rest(c.kernel);
  double work = 0.0, work_scale = 0.0, force = 0.0;
  for (const double u : Path(c.scale, 20000)) {
    const Step next = Trial(c.kernel, state, u);
    const double du = u - state[0].u;
    work += 0.5 * (force + next.response.force) * du;
    work_scale += std::abs(0.5 * (force + next.response.force) * du);
    force = next.response.force;
    state = next.state;
  }
  EXPECT_NEAR(work, StoredEnergy(c.kernel, state) + state[0].dissipated, 1e-6 * work_scale)
      << c.name;
}

INSTANTIATE_TEST_SUITE_P(AllLaws, LawUpdate, ::testing::ValuesIn(Cases()),
                         [](const auto& info) { return info.param.name; });

TEST(Dashpot, ForceIsCTimesVelocityAndCycleEnergyIsPiCOmegaASquared) {
  const LawKernel dashpot = Math(LawType::kDashpot, {0.02});
  const double amplitude = 100.0, omega = 2.0 * M_PI / 2.0;
  const int n = 4000;
  LawState state;
  LawResponse response;
  for (int k = 0; k <= n; ++k) {
    const double phase = 2.0 * M_PI * k / n;
    LawState trial;
    UpdateLaw(dashpot, state, {amplitude * std::sin(phase), amplitude * omega * std::cos(phase)},
              &trial, &response);
    state = trial;
  }
  EXPECT_DOUBLE_EQ(response.force, 0.02 * amplitude * omega);
  EXPECT_EQ(response.damping, 0.02);
  EXPECT_EQ(response.stiffness, 0.0);
  const double exact = M_PI * 0.02 * omega * amplitude * amplitude;
  EXPECT_NEAR(state.dissipated, exact, 1e-6 * exact);
}

TEST(DegenerateForms, Thm1SpringLimitStaysAccurateForVeryLargeK0) {
  // Table 9 component 2 with k0 = 1e10: the series spring changes the force by about k1/k0 =
  // 3e-14 relative, so any larger difference is round-off in the update.
  const LawKernel thm1 = Math(LawType::kThm1, {1e10, 0.000282, 0.905635, 0, 136.491});
  const LawKernel spring = Math(LawType::kTrilinearElastic, {0.000282, 0.905635, 136.491});
  State a = Rest(thm1), b = Rest(spring);
  for (const double u : Path(200.0, 50)) {
    const Step sa = Trial(thm1, a, u), sb = Trial(spring, b, u);
    EXPECT_NEAR(sa.response.force, sb.response.force, 1e-8 * (1e-3 + std::abs(sb.response.force)))
        << "u = " << u;
    EXPECT_NEAR(StoredEnergy(thm1, sa.state), StoredEnergy(spring, sb.state),
                1e-8 * (1e-3 + StoredEnergy(spring, sb.state)))
        << "u = " << u;
    a = sa.state;
    b = sb.state;
  }
}

TEST(DegenerateForms, Thm1WithZeroYieldAndStiffK0IsTheTrilinearSpring) {
  const LawKernel thm1 = Math(LawType::kThm1, {1e6, 0.283532, 0.489882, 0, 64.809});
  const LawKernel spring = Math(LawType::kTrilinearElastic, {0.283532, 0.489882, 64.809});
  State a = Rest(thm1), b = Rest(spring);
  for (const double u : Path(150.0, 50)) {
    const Step sa = Trial(thm1, a, u), sb = Trial(spring, b, u);
    EXPECT_NEAR(sa.response.force, sb.response.force, 2e-6 * (1 + std::abs(sb.response.force)));
    EXPECT_EQ(sa.state[0].dissipated, 0.0);
    a = sa.state;
    b = sb.state;
  }
}

}  // namespace
}  // namespace isolab::hysteresis
