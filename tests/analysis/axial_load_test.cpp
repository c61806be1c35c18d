// The axial loads of friction pendulum bearings, end to end from a model's text to the rows of a
// Newmark run, against numbers computed here independently: a rigid block (a plan slab with no
// stories) on four friction pendulums under a vertical harmonic a_v sin(w t) and a horizontal
// harmonic; the overturning of a two-story building against its story forces by hand statics;
// uplift; and the refusals.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "../own_test_file.h"
#include "isolab/analysis/problem.h"
#include "isolab/analysis/run_report.h"
#include "isolab/analysis/run_text.h"
#include "isolab/analysis/solve.h"
#include "isolab/core/errors.h"
#include "isolab/cyclic/cyclic_campaign.h"
#include "isolab/cyclic/model_replay.h"
#include "isolab/model/model_file.h"

namespace isolab::analysis {
namespace {

constexpr double kG = 9.80665;  // m/s^2
constexpr double kDt = 0.005;   // s, the records' step and the analysis step
constexpr double kPi = std::numbers::pi;

// A two-column record (time, acceleration in m/s^2) of f at k dt, k = 0..duration/dt, in the
// test's own directory.
template <class F>
std::string WriteRecord(const std::string& name, double duration, F f) {
  const std::string path = (isolab::testing::OwnTestDirectory() / name).string();
  std::ofstream out(path);
  out.precision(17);
  const int steps = static_cast<int>(std::lround(duration / kDt));
  for (int k = 0; k <= steps; ++k) out << k * kDt << " " << f(k * kDt) << "\n";
  return path;
}

// Every row a run hands out, copied.
struct Row {
  double t;
  std::vector<double> u, absolute, force, axial;
};
class Rows final : public integrators::ResponseObserver {
 public:
  void Observe(const integrators::ResponseRow& row) override {
    rows.push_back({row.time,
                    {row.displacement.begin(), row.displacement.end()},
                    {row.absolute_acceleration.begin(), row.absolute_acceleration.end()},
                    {row.connection_force.begin(), row.connection_force.end()},
                    {row.axial_load.begin(), row.axial_load.end()}});
  }
  std::vector<Row> rows;
};

struct Solution {
  Problem problem;
  Summary summary;
  std::vector<Row> rows;
};

Solution Solved(const std::string& text) {
  const std::string path = (isolab::testing::OwnTestDirectory() / "model.yaml").string();
  std::ofstream(path) << text;
  Solution run{Prepare(model::LoadModelFile(path), {}), {}, {}};
  Rows rows;
  integrators::ResponseObserver* observers[] = {&rows};
  SolveOptions options;
  options.analysis = run.problem.model.analysis;
  run.summary = Solve(options, run.problem, observers);
  run.rows = std::move(rows.rows);
  return run;
}

// The block: 400 t at the centroid of four bearings at (+-4, +-2) m, each W = 981 kN (its
// quarter of the weight, rounded), R = 2 m, mu = 0.05, u_y = 0.5 mm.
constexpr double kMass = 400.0;  // t
constexpr double kR = 2.0, kMu = 0.05, kUy = 0.0005;

std::string Block(const std::string& h1, const std::string& v, const std::string& axial) {
  return "units: {force: kN, length: m, time: s}\n"
         "plan:\n"
         "  footprint: [[-5, -3], [5, 3]]\n"
         "  base: {mass: 400 t, centre_of_mass: [0, 0], radius_of_gyration: 3}\n"
         "  isolators:\n"
         "    - {name: sw, position: [-4, -2], components: &fp [{name: fp, type: "
         "friction_pendulum, w: 981, r: 2, mu: 0.05, uy: 0.0005}]}\n"
         "    - {name: se, position: [4, -2], components: *fp}\n"
         "    - {name: nw, position: [-4, 2], components: *fp}\n"
         "    - {name: ne, position: [4, 2], components: *fp}\n"
         "excitation:\n"
         "  ground_motion:\n"
         "    h1: {file: " +
         h1 + ", units: m/s^2}\n" +
         (v.empty() ? std::string() : "    v: {file: " + v + ", units: m/s^2}\n") +
         "analysis: {dt: 0.005, free_vibration: 0}\n" + axial;
}

// A rigid block under a_v sin(w t): N_j(t) = m (g + a_v(t)) / 4 on each bearing, and the
// friction force F - N u / R is mu N z, with z from an elastoplastic slider of yield displacement
// u_y tracked here (the motion stays along x: the block is symmetric and the record along x), so
// |F - N u / R| = mu N exactly at every step on which the slider slides.
TEST(AxialLoad, RigidBlockFrictionIsMuNUnderVerticalShaking) {
  const double av = 0.5 * kG, wv = 2.0 * kPi * 2.0;
  const std::string h1 =
      WriteRecord("h1.txt", 6.0, [](double t) { return 3.0 * std::sin(2.0 * kPi * 0.5 * t); });
  const std::string v = WriteRecord("v.txt", 6.0, [&](double t) { return av * std::sin(wv * t); });
  const Solution run = Solved(Block(h1, v, "axial_load: {vertical: true}\n"));
  ASSERT_TRUE(run.summary.run.ok()) << run.summary.run.message;
  EXPECT_LT(run.summary.run.energy_balance_error, 1e-2);
  const structure::Structure& s = run.problem.structure;
  ASSERT_EQ(s.axial_loads().bearings.size(), 4u);
  ASSERT_EQ(run.rows.size(), 1201u);
  std::vector<double> elastic(4, 0.0), previous(4, 0.0);
  int sliding = 0;
  double largest_error = 0.0;
  for (std::size_t n = 1; n < run.rows.size(); ++n) {
    const Row& row = run.rows[n];
    const double load = kMass * (kG + av * std::sin(wv * row.t)) / 4.0;
    for (std::size_t j = 0; j < 4; ++j) {
      ASSERT_NEAR(row.axial[j], load, 1e-9 * load) << "t = " << row.t;
      const double u = s.SlotDeformation(s.coupled_slot(j), row.u).x;
      const double trial = elastic[j] + (u - previous[j]);
      const bool slides = std::abs(trial) >= kUy;
      elastic[j] = std::clamp(trial, -kUy, kUy);
      previous[j] = u;
      const double friction = row.force[s.slot_force_column(s.coupled_slot(j))] - load * u / kR;
      largest_error = std::max(largest_error,
                               std::abs(friction - kMu * load * elastic[j] / kUy) / (kMu * load));
      if (slides) {
        ++sliding;
        EXPECT_NEAR(std::abs(friction), kMu * load, 1e-7 * kMu * load) << "t = " << row.t;
      }
    }
  }
  EXPECT_LT(largest_error, 1e-7);
  EXPECT_GT(sliding, 4 * 600);  // it slides most of the time, through the vertical's cycles
  // The vertical component changes the answer: the same block at constant load slides otherwise.
  const Solution constant = Solved(Block(h1, "", ""));
  ASSERT_TRUE(constant.summary.run.ok());
  EXPECT_GT(std::abs(constant.summary.peaks.isolator_displacement.value -
                     run.summary.peaks.isolator_displacement.value),
            1e-4);
}

// With axial_load: {} and no vertical shaking, a one-direction slab's layer carries the whole
// weight m g (not its law's W): friction at sliding is mu m g.
TEST(AxialLoad, OneDirectionLayerCarriesTheWholeWeight) {
  const std::string h1 =
      WriteRecord("h1.txt", 4.0, [](double t) { return 3.0 * std::sin(2.0 * kPi * 0.5 * t); });
  const Solution run = Solved(
      "units: {force: kN, length: m, time: s}\n"
      "isolation:\n"
      "  components: [{name: fp, type: friction_pendulum, w: 3000, r: 2, mu: 0.05, uy: 0.0005}]\n"
      "structure: {type: shear_building, base_mass: 400 t}\n"
      "excitation:\n"
      "  ground_motion: {file: " +
      h1 +
      ", units: m/s^2}\n"
      "analysis: {dt: 0.005, free_vibration: 0}\n"
      "axial_load: {}\n");
  ASSERT_TRUE(run.summary.run.ok()) << run.summary.run.message;
  const double weight = kMass * kG;
  double largest_friction = 0.0;
  for (const Row& row : run.rows) {
    ASSERT_DOUBLE_EQ(row.axial[0], weight);
    const double u = run.problem.structure.MemberDeformation(0, row.u);
    largest_friction = std::max(largest_friction, std::abs(row.force[0] - weight * u / kR));
  }
  EXPECT_NEAR(largest_friction, kMu * weight, 1e-9 * weight);
}

// An uncoupled pair (a pendulum's x and y laws) is one bearing: it carries its share once. The
// block of four such pairs at rest, with axial_load: {} (each N = m g / 4), runs as the same
// block at constant load with w = m g / 4: the same displacements to round-off. (Its weight was
// once counted twice, x and y, halving every force.)
TEST(AxialLoad, AnUncoupledPairCarriesItsShareOnce) {
  const std::string h1 =
      WriteRecord("h1.txt", 6.0, [](double t) { return 3.0 * std::sin(2.0 * kPi * 0.5 * t); });
  const auto uncoupled = [](std::string text) {
    for (std::size_t at = text.find("components:"); at != std::string::npos;
         at = text.find("components:", at + 40)) {
      text.insert(at, "coupling: uncoupled, ");
    }
    text.replace(text.find("w: 981"), 6, "w: 980.665");
    return text;
  };
  const Solution loaded = Solved(uncoupled(Block(h1, "", "axial_load: {}\n")));
  ASSERT_TRUE(loaded.summary.run.ok()) << loaded.summary.run.message;
  ASSERT_EQ(loaded.problem.structure.axial_loads().bearings.size(), 4u);
  EXPECT_NEAR(loaded.problem.structure.axial_loads().bearings[0].weight, kMass * kG / 4.0, 1e-9);
  const Solution constant = Solved(uncoupled(Block(h1, "", "")));
  ASSERT_TRUE(constant.summary.run.ok());
  ASSERT_EQ(loaded.rows.size(), constant.rows.size());
  const double peak = constant.summary.peaks.isolator_displacement.value;
  ASSERT_GT(peak, 0.01);  // it slides
  for (std::size_t n = 0; n < loaded.rows.size(); ++n) {
    for (std::size_t i = 0; i < loaded.rows[n].u.size(); ++i) {
      ASSERT_NEAR(loaded.rows[n].u[i], constant.rows[n].u[i], 1e-9 * peak) << n;
    }
  }
}

// Vertical shaking at twice a pendulum's frequency pumps energy into a swinging block through
// the axial load (parametric resonance: N u^2 / (2 R) raised while displaced): after a short
// horizontal push the block's kinetic energy grows far beyond the horizontal input, all of it
// the axial loads' work. The run is not a blow-up: the balance input + axial = kinetic + ...
// closes, and the blow-up check weighs the kinetic energy against the work supplied, both terms.
TEST(AxialLoad, EnergyTheVerticalShakingSuppliesIsNotABlowUp) {
  const double fp = std::sqrt(kG / kR) / (2.0 * kPi);  // the pendulum's frequency, Hz
  const std::string h1 =
      WriteRecord("push.txt", 20.0, [](double t) { return t < 1.0 ? 2.0 : 0.0; });
  const std::string v = WriteRecord(
      "v_resonant.txt", 20.0, [fp](double t) { return 0.6 * kG * std::sin(2 * kPi * 2 * fp * t); });
  std::string text = Block(h1, v, "axial_load: {vertical: true}\n");
  text.replace(text.find("mu: 0.05"), 8, "mu: 0.002");  // little friction to resist the pumping
  const Solution run = Solved(text);
  ASSERT_TRUE(run.summary.run.ok()) << run.summary.run.message;
  const integrators::Energies& e = run.summary.peaks.energies;  // at the last step
  EXPECT_GT(e.kinetic, 10.0 * std::abs(e.input));  // out of the horizontal input's reach
  EXPECT_GT(e.axial, e.kinetic);
  EXPECT_LT(run.summary.run.energy_balance_error, 1e-3);
}

// Overturning: a two-story building on four bearings at (+-6, +-4) m, its masses at the
// bearings' centroid at heights 0.5 (base), 3.5 and 6.5 m. By hand statics of the rigid slab,
// N_j = P / 4 + x_j S_x / (4 a^2) + y_j S_y / (4 b^2), S = -sum_i m_i z_i a_i, from the story
// inertial forces of the step's start (the previous row's absolute accelerations), and the
// bearings' loads balance the overturning moment of those story forces.
TEST(AxialLoad, OverturningFromStoryForcesByRigidSlabStatics) {
  const std::string h1 =
      WriteRecord("h1.txt", 4.0, [](double t) { return 2.5 * std::sin(2.0 * kPi * 0.6 * t); });
  const std::string h2 =
      WriteRecord("h2.txt", 4.0, [](double t) { return 1.5 * std::sin(2.0 * kPi * 0.9 * t); });
  const Solution run = Solved(
      "units: {force: kN, length: m, time: s}\n"
      "plan:\n"
      "  footprint: [[-7, -5], [7, 5]]\n"
      "  base: {mass: 200 t, centre_of_mass: [0, 0], radius_of_gyration: 4}\n"
      "  stories:\n"
      "    count: 2\n"
      "    mass: 150 t\n"
      "    centre_of_mass: [0, 0]\n"
      "    centre_of_stiffness: [0, 0]\n"
      "    radius_of_gyration: 4\n"
      "    height: 3\n"
      "    stiffness: {x: 200000, y: 200000, torsion: 1.0e7}\n"
      "  isolators:\n"
      "    - {name: sw, position: [-6, -4], components: &fp [{name: fp, type: "
      "friction_pendulum, w: 1226, r: 2, mu: 0.05, uy: 0.0005}]}\n"
      "    - {name: se, position: [6, -4], components: *fp}\n"
      "    - {name: nw, position: [-6, 4], components: *fp}\n"
      "    - {name: ne, position: [6, 4], components: *fp}\n"
      "excitation:\n"
      "  ground_motion:\n"
      "    h1: {file: " +
      h1 +
      ", units: m/s^2}\n"
      "    h2: {file: " +
      h2 +
      ", units: m/s^2}\n"
      "analysis: {dt: 0.005, free_vibration: 0}\n"
      "axial_load: {overturning: true, base_height: 0.5}\n");
  ASSERT_TRUE(run.summary.run.ok()) << run.summary.run.message;
  const double a = 6.0, b = 4.0;
  const double masses[] = {200.0, 150.0, 150.0}, heights[] = {0.5, 3.5, 6.5};
  const double weight = 500.0 * kG;
  const double x[] = {-a, a, -a, a}, y[] = {-b, -b, b, b};
  double largest_moment = 0.0, largest_error = 0.0;
  for (std::size_t n = 1; n < run.rows.size(); ++n) {
    const Row& before = run.rows[n - 1];
    const Row& row = run.rows[n];
    // The story inertial forces m_i a_i (level i's dofs 3i, 3i + 1) and their moments.
    double moment_x = 0.0, moment_y = 0.0;  // sum m z a_x, sum m z a_y
    for (int i = 0; i < 3; ++i) {
      moment_x += masses[i] * heights[i] * before.absolute[3 * i];
      moment_y += masses[i] * heights[i] * before.absolute[3 * i + 1];
    }
    largest_moment = std::max(largest_moment, std::abs(moment_x));
    double sum = 0.0, sum_x = 0.0, sum_y = 0.0;
    for (int j = 0; j < 4; ++j) {
      const double hand =
          weight / 4.0 - x[j] * moment_x / (4.0 * a * a) - y[j] * moment_y / (4.0 * b * b);
      largest_error = std::max(largest_error, std::abs(row.axial[j] - hand) / weight);
      sum += row.axial[j];
      sum_x += x[j] * row.axial[j];
      sum_y += y[j] * row.axial[j];
    }
    EXPECT_NEAR(sum, weight, 1e-9 * weight);
    // Moment equilibrium about the bearing plane: the loads' moment balances the story forces'.
    EXPECT_NEAR(sum_x, -moment_x, 1e-9 * weight);
    EXPECT_NEAR(sum_y, -moment_y, 1e-9 * weight);
  }
  EXPECT_LT(largest_error, 1e-12);
  EXPECT_GT(largest_moment, 0.02 * weight * a);  // the overturning is not negligible
}

// Uplift: a_v = 1.3 g sin(w t) lifts the block off its bearings while sin(w t) < -1 / 1.3: the
// bearings carry no shear then, the run warns with the time, and the uplift lasts the fraction
// (pi - 2 asin(1 / 1.3)) / (2 pi) of each cycle.
TEST(AxialLoad, UpliftCarriesNoShearAndWarns) {
  const double av = 1.3 * kG, wv = 2.0 * kPi * 1.0;
  const std::string h1 =
      WriteRecord("h1.txt", 4.0, [](double t) { return 3.0 * std::sin(2.0 * kPi * 0.5 * t); });
  const std::string v = WriteRecord("v.txt", 4.0, [&](double t) { return av * std::sin(wv * t); });
  const Solution run = Solved(Block(h1, v, "axial_load: {vertical: true}\n"));
  ASSERT_TRUE(run.summary.run.ok()) << run.summary.run.message;
  const structure::Structure& s = run.problem.structure;
  int uplifted = 0;
  for (const Row& row : run.rows) {
    for (std::size_t j = 0; j < 4; ++j) {
      if (row.axial[j] > 0.0) continue;
      ++uplifted;
      EXPECT_EQ(row.force[s.slot_force_column(s.coupled_slot(j))], 0.0) << "t = " << row.t;
      EXPECT_EQ(row.force[s.slot_force_column(s.coupled_slot(j)) + 1], 0.0) << "t = " << row.t;
    }
  }
  EXPECT_GT(uplifted, 0);
  const double fraction = (kPi - 2.0 * std::asin(1.0 / 1.3)) / (2.0 * kPi);
  const ResponsePeaks& peaks = run.summary.peaks;
  ASSERT_EQ(peaks.uplift_durations.size(), 4u);
  EXPECT_NEAR(peaks.uplift_durations[0], 4.0 * fraction, 4 * 2 * kDt);
  const double first = 0.5 + std::asin(1.0 / 1.3) / (2.0 * kPi);  // sin(w t) = -1 / 1.3
  EXPECT_NEAR(peaks.first_uplift_times[0], first, kDt);
  EXPECT_NEAR(peaks.axial_load_minima[0].value, kMass * (kG - av) / 4.0, 1e-3 * kMass * kG);
  const bool warned = std::any_of(
      run.summary.warnings.begin(), run.summary.warnings.end(), [](const std::string& warning) {
        return warning.find("isolator sw uplifted") != std::string::npos &&
               warning.find("first at t = ") != std::string::npos;
      });
  EXPECT_TRUE(warned);
}

// A triple pendulum driven past its outer surface's capacity: the surface's capacity used reaches
// 1 (its restrainer, d_1 = 0.1 m) and the run warns with the time; under its axial load the
// bearing's force at rest equals its law's times N / w.
TEST(AxialLoad, TriplePendulumCapacityUsedAndStops) {
  const std::string h1 =
      WriteRecord("h1.txt", 6.0, [](double t) { return 4.0 * std::sin(2.0 * kPi * 0.4 * t); });
  const Solution run = Solved(
      "units: {force: kN, length: m, time: s}\n"
      "isolation:\n"
      "  components: [{name: tp, type: triple_friction_pendulum, w: 3923, r1: 2.1, r2: 0.28, "
      "r3: 0.28, r4: 2.1, mu1: 0.06, mu2: 0.02, mu3: 0.02, mu4: 0.10, d1: 0.1, d2: 0.025, d3: "
      "0.025, d4: 0.1, uy: 0.0005}]\n"
      "structure: {type: shear_building, base_mass: 400 t}\n"
      "excitation:\n"
      "  ground_motion: {file: " +
      h1 +
      ", units: m/s^2}\n"
      "analysis: {dt: 0.005, free_vibration: 0}\n"
      "axial_load: {}\n");
  ASSERT_TRUE(run.summary.run.ok()) << run.summary.run.message;
  const ResponsePeaks& peaks = run.summary.peaks;
  ASSERT_EQ(peaks.capacity_used.size(), 1u);
  EXPECT_NEAR(peaks.capacity_used[0][0], 1.0, 1e-9);
  EXPECT_LE(peaks.capacity_used[0][1], 1.0 + 1e-9);
  EXPECT_GT(peaks.first_stop_times[0], 0.0);
  const bool warned = std::any_of(
      run.summary.warnings.begin(), run.summary.warnings.end(), [](const std::string& warning) {
        return warning.find("reached its restrainer") != std::string::npos &&
               warning.find("surfaces 1") != std::string::npos;
      });
  EXPECT_TRUE(warned);
  for (const Row& row : run.rows) ASSERT_DOUBLE_EQ(row.axial[0], kMass * kG);
}

// What cannot be run is refused, naming the key.
TEST(AxialLoad, Refusals) {
  const std::string h1 = WriteRecord("h1.txt", 1.0, [](double) { return 1.0; });
  const std::string v = WriteRecord("v.txt", 1.0, [](double) { return 1.0; });
  const auto refused = [](const std::string& text, const std::string& what) {
    const std::string path = (isolab::testing::OwnTestDirectory() / "refused.yaml").string();
    std::ofstream(path) << text;
    try {
      const model::ModelFile model = model::LoadModelFile(path);
      const Problem problem = Prepare(model, {});
      SolveOptions options;
      options.analysis = model.analysis;
      options.analysis.integrator = model::AnalysisSection::Integrator::kIda;
      Solve(options, problem, {});
      ADD_FAILURE() << "not refused: " << what;
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find(what), std::string::npos) << error.what();
    }
  };
  // A vertical component that nothing takes.
  refused(Block(h1, v, ""), "axial_load: {vertical: true}");
  // The vertical asked for, and no vertical component.
  refused(Block(h1, "", "axial_load: {vertical: true}\n"), "excitation.ground_motion.v");
  // IDA.
  refused(Block(h1, v, "axial_load: {vertical: true}\n"), "axial_load");
  // Overturning in one direction.
  refused(
      "units: {force: kN, length: m, time: s}\n"
      "isolation:\n"
      "  components: [{type: friction_pendulum, w: 3000, r: 2, mu: 0.05, uy: 0.0005}]\n"
      "structure: {type: shear_building, base_mass: 400 t}\n"
      "excitation: {ground_motion: {file: " +
          h1 +
          ", units: m/s^2}}\n"
          "axial_load: {overturning: true}\n",
      "axial_load.overturning");
  // No pendulum to take it.
  refused(
      "units: {force: kN, length: m, time: s}\n"
      "isolation:\n"
      "  components: [{type: bhm2, k0: 20, k1: 2, uy: 0.01}]\n"
      "structure: {type: shear_building, base_mass: 400 t}\n"
      "excitation: {ground_motion: {file: " +
          h1 +
          ", units: m/s^2}}\n"
          "axial_load: {}\n",
      "no isolator is a friction pendulum");
}

// Where nothing would take the axial loads, `axial_load` is refused at its own line and column
// rather than ignored: a model of the isolation alone (a bearing for isolab cyclic or fit), a
// building without isolation, a run on a fixed base, and cyclic tests, paths and orbits, which
// drive the bearings' laws at their own w.
TEST(AxialLoad, RefusedWhereNothingCarriesTheLoad) {
  const std::string h1 = WriteRecord("h1.txt", 1.0, [](double) { return 1.0; });
  const std::string path = (isolab::testing::OwnTestDirectory() / "carried.yaml").string();
  const auto located = [&](const InputError& error, const std::string& what) {
    EXPECT_NE(std::string(error.what()).find(what), std::string::npos) << error.what();
    EXPECT_EQ(error.location().file, path);
    EXPECT_EQ(error.location().line, 5) << error.what();  // axial_load's own line
    EXPECT_EQ(error.location().column, 13) << error.what();
  };
  const auto load = [&](const std::string& text) {
    std::ofstream(path) << text;
    return model::LoadModelFile(path);
  };
  const std::string units = "units: {force: kN, length: m, time: s}\n";
  const std::string pendulum =
      "isolation:\n"
      "  components: [{type: friction_pendulum, w: 3000, r: 2, mu: 0.05, uy: 0.0005}]\n"
      "cyclic: {amplitude: 0.1}\n";
  const std::string motion = "excitation: {ground_motion: {file: " + h1 + ", units: m/s^2}}\n";
  // The isolation alone.
  try {
    load(units + pendulum + "axial_load: {}\n");
    ADD_FAILURE() << "an isolation alone took axial_load";
  } catch (const InputError& error) {
    located(error, "axial_load: needs a structure whose weight the bearings carry");
  }
  // A building without isolation.
  try {
    load(units +
         "structure: {type: shear_building, stories: [{mass: 100 t, stiffness: 200000}]}\n" +
         motion + "\naxial_load: {}\n");
    ADD_FAILURE() << "a fixed-base building took axial_load";
  } catch (const InputError& error) {
    located(error, "axial_load: a building without isolation has no bearings");
  }
  // The same isolation under a building: a run on a fixed base, and cyclic tests and orbits.
  const model::ModelFile model =
      load(units + pendulum + "axial_load: {}\n" +
           "structure: {type: shear_building, base_mass: 300 t, stories: [{mass: 100 t, "
           "stiffness: 200000}]}\n" +
           motion);
  RunOverrides fixed;
  fixed.fixed_base = true;
  try {
    Prepare(model, fixed);
    ADD_FAILURE() << "a fixed-base run took axial_load";
  } catch (const InputError& error) {
    located(error, "axial_load: the run is on a fixed base");
  }
  try {
    cyclic::RunCyclicCampaign(model, {});
    ADD_FAILURE() << "a cyclic test took axial_load";
  } catch (const InputError& error) {
    located(error, "axial_load: a cyclic test drives the bearings by their laws");
  }
  cyclic::ReplayRequest orbit;
  orbit.orbit = "circle";
  orbit.amplitudes = {0.1};
  try {
    cyclic::ReplayModel(model, orbit, cyclic::OptionStyle::kCommandLine);
    ADD_FAILURE() << "an orbit took axial_load";
  } catch (const InputError& error) {
    located(error, "axial_load: a path or an orbit drives the bearings by their laws");
  }
  // Without the fixed base the same model runs, its layer carrying the whole weight.
  EXPECT_EQ(Prepare(model, {}).structure.axial_loads().bearings.size(), 1u);
}

// The regime of a triple pendulum at its peak displacement, against the closed-form backbone of
// the series model (Fenz & Constantinou 2008, Table 1; docs/bearings.md's bearing: W = 1000 kN,
// R = 2100, 280, 280, 2100 mm, mu = 0.06, 0.02, 0.02, 0.10, d = 400, 50, 50, 400 mm, u_y =
// 0.5 mm). A slab of mass W / g on it, undamped, under a constant ground acceleration a_0 from
// rest, moves one way until its first peak, on first loading: the regime there is the one whose
// displacement range on the backbone holds the peak. Each regime begins at a force F_k and slides
// on two surfaces of radii R_a + R_b, so it begins at u_k = F_k / ke + sum over the earlier
// regimes of (force gained) (R_a + R_b) / W. The a_0 put the peak inside each of I to V
// (m a_0 D = the backbone's work to D).
TEST(AxialLoad, TriplePendulumRegimeAtThePeakIsTheBackbones) {
  constexpr double kW = 1000.0, kKe = 0.02 * kW / 0.5;  // kN; kN/mm
  const double r1 = 2100.0, r2 = 280.0, r3 = 280.0, r4 = 2100.0;
  const double from[] = {0.02 * kW, 0.06 * kW, 0.10 * kW, kW * (0.06 + 400.0 / r1),
                         kW * (0.10 + 400.0 / r4)};
  const double radii[] = {r2 + r3, r1 + r3, r1 + r4, r2 + r4, r2 + r3};
  const char* names[] = {"I", "II", "III", "IV", "V"};
  std::vector<double> starts;  // u_k, mm
  double sliding = 0.0;
  for (int k = 0; k < 5; ++k) {
    if (k > 0) sliding += (from[k] - from[k - 1]) * radii[k - 1] / kW;
    starts.push_back(from[k] / kKe + sliding);
  }
  // V ends when the sliders' displacement reaches the capacity d1 + d2 + d3 + d4 (909.73 mm).
  const double capacity = 400.0 + 50.0 + 50.0 + 400.0;
  const double sliding_at_v = starts[4] - from[4] / kKe;
  const double end_of_v = capacity + (from[4] + (capacity - sliding_at_v) * kW / radii[4]) / kKe;
  ASSERT_NEAR(end_of_v, 909.73, 0.005);
  ASSERT_NEAR(starts[1], 23.9, 1e-9);  // docs/bearings.md's boundaries
  ASSERT_NEAR(starts[4], 852.1, 0.05);
  const double accelerations[] = {0.029, 0.0593, 0.1199, 0.1649, 0.1761};  // g
  for (int expected = 0; expected < 5; ++expected) {
    SCOPED_TRACE(names[expected]);
    const double a0 = accelerations[expected];
    const std::string h1 = WriteRecord("step.txt", 6.0, [a0](double) { return a0; });
    const Solution run = Solved(
        "units: {force: kN, length: mm, time: s}\n"
        "isolation:\n"
        "  components: [{name: tp, type: triple_friction_pendulum, w: 1000, r1: 2100, r2: 280, "
        "r3: 280, r4: 2100, mu1: 0.06, mu2: 0.02, mu3: 0.02, mu4: 0.10, d1: 400, d2: 50, d3: 50, "
        "d4: 400, uy: 0.5}]\n"
        "structure: {type: shear_building, base_mass: 101.97162129779283 t, damping: none}\n"
        "excitation:\n"
        "  ground_motion: {file: " +
        h1 +
        ", units: g}\n"
        "analysis: {dt: 0.005, free_vibration: 0}\n");
    ASSERT_TRUE(run.summary.run.ok()) << run.summary.run.message;
    const ResponsePeaks& peaks = run.summary.peaks;
    const double d = peaks.isolator_displacement.value;
    int regime = 0;
    while (regime < 4 && d > starts[regime + 1]) ++regime;
    ASSERT_EQ(regime, expected) << "peak " << d << " mm";
    // Well inside the regime, not at a boundary a step could move it across.
    const double upper = regime < 4 ? starts[regime + 1] : end_of_v;
    EXPECT_GT(std::min(d - starts[regime], upper - d), 5.0) << d;
    ASSERT_EQ(peaks.regimes_at_peak.size(), 1u);
    ASSERT_TRUE(peaks.regimes_at_peak[0].has_value());
    EXPECT_EQ(hysteresis::PendulumRegimeName(*peaks.regimes_at_peak[0]), names[expected]);
    const nlohmann::json json = RunReport(run.problem, run.problem.model.analysis, run.summary);
    EXPECT_EQ(json["isolators"].begin().value()["regime_at_peak"], names[expected]);
    std::ostringstream text;
    PrintSummary(run.problem, run.problem.model.analysis, run.summary, text);
    EXPECT_NE(text.str().find(fmt::format("triple pendulum regime {:>24}", names[expected])),
              std::string::npos)
        << text.str();
  }
}

}  // namespace
}  // namespace isolab::analysis
