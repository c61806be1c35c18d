// A model driven along a given path (path_replay.h) against independent numbers:
//  * along a seismic-like history, the force identification computes for the same model
//    (SimulateForce, what a fit predicts), to the last digit: one update sequence;
//  * along the sinusoid of RunCyclicTest, its loop's force, for a rate-independent model;
//  * round a circle, the coupled elastoplastic slider's closed forms (circular_orbit_test.cpp,
//    docs/bidirectional.md): the force magnitude is fs exactly while it slips, the force lags the
//    direction of motion by asin(u_y / R), and the slider dissipates 2 pi fs rho a revolution
//    (rho = sqrt(R^2 - u_y^2)), the discrete polygon's 2 N fs rho_N sin(pi / N) to round-off;
//  * against a measured force 1.1 times the model's, e^2 = (0.1 / 1.1)^2.
#include "isolab/cyclic/path_replay.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "isolab/core/errors.h"
#include "isolab/hysteresis/cyclic_test.h"
#include "isolab/hysteresis/parallel_assembly.h"
#include "isolab/identification/cyclic_data.h"
#include "isolab/model/model_file.h"

namespace isolab::cyclic {
namespace {

using hysteresis::LawType;

io::DisplacementPath SeismicLikePath() {
  io::DisplacementPath path;
  path.name = "seismic";
  for (int k = 0; k < 4000; ++k) {
    const double t = 0.01 * k, envelope = std::sin(std::numbers::pi * t / 40.0);
    path.time.push_back(t);
    path.displacement.push_back(
        {envelope * (120 * std::sin(2.1 * t) + 50 * std::sin(3.7 * t + 1)) + 5 * std::sin(0.1 * t),
         0.0});
  }
  return path;
}

TEST(PathReplay, AlongAHistoryItIsWhatIdentificationPredicts) {
  // The two-effect truth: a BHM2, a hardening spring and a dashpot (rate-dependent, so the
  // velocity's backward differences matter too).
  const model::ModelFile model =
      model::LoadModelFile(std::string(ISOLAB_SOURCE_DIR) + "/models/diagnosis/two_effects.yaml");
  const io::DisplacementPath path = SeismicLikePath();
  const ReplayResult replay = Replay(model.isolation, path);
  identification::CyclicTestData test;
  test.time = path.time;
  for (const auto& u : path.displacement) test.displacement.push_back(u.x);
  const std::vector<double> force = identification::SimulateForce(model.isolation, test);
  ASSERT_EQ(replay.force.size(), force.size());
  for (std::size_t k = 0; k < force.size(); ++k) {
    ASSERT_EQ(replay.force[k].x, force[k]) << k;
    ASSERT_EQ(replay.force[k].y, 0.0);
  }
  EXPECT_FALSE(replay.comparison);
  EXPECT_GT(replay.dissipated.back(), 0.0);
}

TEST(PathReplay, AlongCyclicsSinusoidItIsCyclicsLoop) {
  const auto model = hysteresis::SingleLaw(LawType::kThm1, {1, 0.2, 0.45, 20, 120});
  const hysteresis::CyclicResult loop = hysteresis::RunCyclicTest(model, {200, 1.0, 2, 400});
  io::DisplacementPath path;
  path.time = loop.loop.time;
  for (const double u : loop.loop.displacement) path.displacement.push_back({u, 0.0});
  const ReplayResult replay = Replay(model, path);
  for (std::size_t k = 0; k < path.time.size(); ++k) {
    ASSERT_EQ(replay.force[k].x, loop.loop.force[k]) << k;
  }
  EXPECT_NEAR(replay.dissipated.back(), loop.cycles[0].dissipated + loop.cycles[1].dissipated,
              1e-9 * loop.cycles[1].dissipated);
}

// Laws that take several states (sliders in series: the double and triple pendulums) keep every
// element's state along a path, in one direction and in their coupled form in two: along the
// cyclic test's sinusoid, to the last digit its loop in one direction, and to round-off in two
// (a straight path: the coupled sliders' return is along the line, as in one direction). (The
// replay once sized its states by the number of components, and wrote past them for these laws.)
TEST(PathReplay, SeriesLawsAlongCyclicsSinusoidAreCyclicsLoop) {
  // docs/bearings.md's triple pendulum (mechanical form: w, r1..r4, mu1..mu4, d1..d4, uy), and a
  // double pendulum.
  const auto triple = hysteresis::ParallelAssembly(
      {{"tfp", hysteresis::LawParameters::Make(
                   LawType::kTripleFrictionPendulum, hysteresis::ParameterForm::kMechanical,
                   std::vector<double>{1000, 2100, 280, 280, 2100, 0.06, 0.02, 0.02, 0.10, 400, 50,
                                       50, 400, 0.5})},
       {"dfp", hysteresis::LawParameters::Make(
                   LawType::kDoubleFrictionPendulum, hysteresis::ParameterForm::kMechanical,
                   std::vector<double>{500, 1500, 1500, 0.04, 0.07, 150, 150, 0.5})}});
  ASSERT_GT(triple.state_size(), triple.size());
  // 700 mm: past regime III of the triple pendulum, and the double's restrainers.
  const hysteresis::CyclicResult loop = hysteresis::RunCyclicTest(triple, {700, 2.0, 2, 400});
  io::DisplacementPath path;
  path.time = loop.loop.time;
  for (const double u : loop.loop.displacement) path.displacement.push_back({u, 0.0});
  const ReplayResult one = Replay(triple, path);
  path.plan = true;
  const ReplayResult coupled = Replay(PlanFromIsolation(triple, true), path);
  for (std::size_t k = 0; k < path.time.size(); ++k) {
    ASSERT_EQ(one.force[k].x, loop.loop.force[k]) << k;
    ASSERT_NEAR(coupled.force[k].x, loop.loop.force[k], 1e-9 * loop.cycles[1].peak_force) << k;
    ASSERT_NEAR(coupled.force[k].y, 0.0, 1e-12 * loop.cycles[1].peak_force) << k;
  }
  EXPECT_NEAR(one.dissipated.back(), loop.cycles[0].dissipated + loop.cycles[1].dissipated,
              1e-9 * loop.cycles[1].dissipated);
}

TEST(PathReplay, RoundACircleTheSliderMeetsItsClosedForms) {
  const double k0 = 9.0, uy = 1.0, fs = k0 * uy, radius = 10.0;
  const int steps = 2000;
  const hysteresis::PlanAssembly slider =
      PlanFromIsolation(hysteresis::SingleLaw(LawType::kElastoplastic, {k0, uy}), true);
  std::vector<std::size_t> cycles;
  const io::DisplacementPath path =
      OrbitPath({OrbitShape::kCircle, radius, 1.0, 3, steps}, &cycles);
  ASSERT_EQ(cycles.size(), 4u);
  const ReplayResult r = Replay(slider, path, cycles);
  ASSERT_EQ(r.cycles.size(), 3u);
  const ReplayCycle& last = r.cycles.back();
  // Slipping, the force is fs along the link: exactly fs.
  EXPECT_NEAR(Norm(last.force_at_end), fs, 1e-12 * fs);
  // At (R, 0) the motion is along +y; the force lags it by asin(u_y / R), within a step's angle.
  const double lag = std::numbers::pi / 2 - std::atan2(last.force_at_end.y, last.force_at_end.x);
  EXPECT_NEAR(lag, std::asin(uy / radius), 2 * std::numbers::pi / steps);
  // Per revolution: the polygon of the return map to round-off, the circle to first order.
  const double s = std::sin(std::numbers::pi / steps);
  const double rho_n = -uy * s + std::sqrt(uy * uy * s * s + radius * radius - uy * uy);
  EXPECT_NEAR(last.dissipated, 2 * steps * fs * rho_n * s, 1e-10 * last.dissipated);
  const double rho = std::sqrt(radius * radius - uy * uy);
  const double first_order = std::numbers::pi * uy / (steps * rho);
  EXPECT_NEAR(last.dissipated / (2 * std::numbers::pi * fs * rho), 1.0, 2 * first_order);
}

TEST(PathReplay, AgainstAMeasuredForceItReportsE2NrmseAndPeaks) {
  const auto model = hysteresis::SingleLaw(LawType::kBhm2, {1.5, 0.25, 8});
  io::DisplacementPath path = SeismicLikePath();
  const ReplayResult plain = Replay(model, path);
  for (const auto& f : plain.force) path.force.push_back(1.1 * f);
  const ReplayResult r = Replay(model, path);
  ASSERT_TRUE(r.comparison);
  EXPECT_NEAR(r.comparison->e2, std::pow(0.1 / 1.1, 2), 1e-12);
  EXPECT_NEAR(r.comparison->peak_measured, 1.1 * r.comparison->peak_modelled, 1e-9);
  double low = INFINITY, high = -INFINITY, square = 0.0;
  for (const auto& f : plain.force) {
    low = std::min(low, 1.1 * f.x), high = std::max(high, 1.1 * f.x), square += 0.01 * f.x * f.x;
  }
  EXPECT_NEAR(r.comparison->error_over_range, std::sqrt(square / plain.force.size()) / (high - low),
              1e-12);
  // RMS-normalised: the error is 0.1 of the model's force, 0.1 / 1.1 of the measured.
  EXPECT_NEAR(r.comparison->nrmse, 0.1 / 1.1, 1e-12);
}

TEST(PathReplay, ATwoDirectionPathNeedsAPlanModelAndLawsWithoutACoupledFormAreNamed) {
  const auto degrading =
      hysteresis::SingleLaw(LawType::kDegradingBhm2, {1, 0.2, 20, 0.4, 300}, "scragging");
  std::vector<std::size_t> cycles;
  const io::DisplacementPath circle = OrbitPath({OrbitShape::kCircle, 50, 1, 1, 100}, &cycles);
  EXPECT_THROW(Replay(degrading, circle), std::invalid_argument);
  try {
    PlanFromIsolation(degrading, true);
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("scragging (degrading_bhm2)"), std::string::npos);
  }
  // Uncoupled, each direction carries the one-direction law: along x alone, the same force.
  const ReplayResult pair = Replay(PlanFromIsolation(degrading, false), SeismicLikePath());
  const ReplayResult one = Replay(degrading, SeismicLikePath());
  for (std::size_t k = 0; k < one.force.size(); k += 37) EXPECT_EQ(pair.force[k].x, one.force[k].x);
}

TEST(PathReplay, OrbitOptionsNameTheFieldAtFault) {
  OrbitProtocol protocol;
  protocol.amplitude = 10;
  protocol.steps_per_cycle = 10;
  try {
    protocol.Validate();
    ADD_FAILURE() << "no exception";
  } catch (const InvalidParameter& error) {
    EXPECT_EQ(error.violation().key, "steps_per_cycle");
  }
}

}  // namespace
}  // namespace isolab::cyclic
