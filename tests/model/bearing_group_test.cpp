// Bearing groups: a one-direction layer of `count` bearings of one type, and a plan isolator type
// at a list of positions. Each is checked against the model an engineer would write by hand (one
// bearing with N times the forces; the isolators listed one by one), run for run.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "isolab/analysis/problem.h"
#include "isolab/analysis/solve.h"
#include "isolab/core/errors.h"
#include "isolab/model/model_file.h"
#include "own_test_file.h"

namespace isolab::model {
namespace {

const std::string kRecord = std::string(ISOLAB_SOURCE_DIR) + "/ground_motions/fwn_firm_seed1.at2";

std::string Write(const std::string& text, const std::string& name) {
  const std::string path = (testing::OwnTestDirectory() / name).string();
  std::ofstream(path) << text;
  return path;
}

// A two-story shear building on the isolation section `isolation` (its YAML, one line).
std::string ShearBuilding(const std::string& isolation) {
  return "units: {force: kN, length: mm, time: s}\n"  // 1
         "isolation: " +
         isolation +
         "\n"                                                           // 2
         "structure: {type: shear_building, base_mass: 200 t,\n"        // 3
         "  stories: {count: 2, mass: 150 t, stiffness: 400 kN/mm}}\n"  // 4
         "excitation: {ground_motion: {file: " +
         kRecord +
         ", scale: 0.6}}\n"            // 5
         "analysis: {duration: 8}\n";  // 6
}

// The run's summary, and its layout's isolators into `isolators` when given.
analysis::Summary RunModel(const std::string& text, const std::string& name,
                           std::vector<structure::IsolatorLayout>* isolators = nullptr) {
  const ModelFile model = LoadModelFile(Write(text, name));
  const analysis::Problem problem = analysis::Prepare(model, {});
  analysis::SolveOptions options;
  options.analysis = model.analysis;
  if (isolators) *isolators = problem.layout.isolators;
  return analysis::Solve(options, problem);
}

std::string ErrorOf(const std::string& text) {
  try {
    LoadModelFile(Write(text, "bad.yaml"));
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "no error";
  return {};
}

TEST(BearingGroup, LayerOfCountBearingsIsOneBearingWithCountTimesTheForces) {
  // Four BHM2 bearings (k0 = 2, k1 = 0.25 kN/mm, uy = 20 mm) in parallel, against the one bearing
  // an engineer writes by hand: 4 k0, 4 k1 and the same uy (4 times the force at every u).
  std::vector<structure::IsolatorLayout> isolators;
  const analysis::Summary group = RunModel(
      ShearBuilding("{name: lrb, count: 4, components: [{type: bhm2, k0: 2, k1: 0.25, uy: 20}]}"),
      "group.yaml", &isolators);
  const analysis::Summary hand =
      RunModel(ShearBuilding("{components: [{type: bhm2, k0: 8, k1: 1, uy: 20}]}"), "hand.yaml");
  ASSERT_TRUE(group.ok()) << group.run.message;
  ASSERT_TRUE(hand.ok()) << hand.run.message;

  ASSERT_EQ(isolators.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(isolators[i].name, "lrb_" + std::to_string(i + 1));
  }
  const double u = hand.peaks.isolator_displacement.value;
  const double v = hand.peaks.base_shear.value;
  EXPECT_NEAR(group.peaks.isolator_displacement.value, u, 1e-9 * u);
  EXPECT_NEAR(group.peaks.base_shear.value, v, 1e-9 * v);
  EXPECT_NEAR(group.peaks.first_story_shear.value, hand.peaks.first_story_shear.value,
              1e-9 * hand.peaks.first_story_shear.value);
  // Per bearing: a quarter of the layer's force, the layer's displacement.
  ASSERT_EQ(group.peaks.isolator_forces.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(group.peaks.isolator_forces[i].value, v / 4.0, 1e-9 * v);
    EXPECT_NEAR(group.peaks.isolator_displacements[i].value, u, 1e-9 * u);
  }
}

TEST(BearingGroup, SdofOnCountBearingsHasThePeriodOfTheirSum) {
  // A 100 t mass on 16 linear bearings of 0.25 kN/mm: T = 2 pi sqrt(m / (16 k)) = 2 pi
  // sqrt(100 / 4) s with m in kN s^2/mm (100 t = 0.1 kN s^2/mm).
  const std::string text =
      "units: {force: kN, length: mm, time: s}\n"
      "isolation: {count: 16, components: [{type: linear_spring, k: 0.25}]}\n"
      "structure: {type: sdof, mass: 100 t, damping: {ratio: 0.0}}\n"
      "excitation: {ground_motion: {file: " +
      kRecord + "}}\n";
  const ModelFile model = LoadModelFile(Write(text, "sdof.yaml"));
  const analysis::Problem problem = analysis::Prepare(model, {});
  ASSERT_EQ(problem.layout.isolators.size(), 16u);
  EXPECT_EQ(problem.layout.isolators[15].name, "bearing_16");
  EXPECT_NEAR(problem.summary.isolated_period, 2.0 * 3.14159265358979323846 * std::sqrt(0.1 / 4.0),
              1e-12);
}

TEST(BearingGroup, CountZeroAndNameWithoutCountAreLocated) {
  const std::string zero =
      ErrorOf(ShearBuilding("{count: 0, components: [{type: linear_spring, k: 1}]}"));
  EXPECT_NE(zero.find("bad.yaml:2:20: isolation.count: 0 (expected a number of bearings >= 1)"),
            std::string::npos)
      << zero;
  const std::string name =
      ErrorOf(ShearBuilding("{name: lrb, components: [{type: linear_spring, k: 1}]}"));
  EXPECT_NE(name.find("bad.yaml:2:19: isolation.name: names the bearings of a count"),
            std::string::npos)
      << name;
}

// A slab on isolators in plan; `isolators` is the YAML of the list's entries.
std::string Plan(const std::string& isolators) {
  return "units: {force: kN, length: mm, time: s}\n"
         "plan:\n"
         "  footprint: [[0, 0], [20000, 10000]]\n"
         "  base: {mass: 300 t, centre_of_mass: [10500, 5000], radius_of_gyration: 6000}\n"
         "  stories:\n"
         "    - {name: s1, mass: 200 t, stiffness: {x: 300, y: 200, torsion: 3.0e10}}\n"
         "  isolators:\n" +
         isolators +
         "excitation:\n"
         "  ground_motion: {h1: {file: " +
         kRecord +
         ", scale: 0.5}, angle: 30}\n"
         "analysis: {duration: 6}\n";
}

TEST(BearingGroup, PlanPositionsAreTheIsolatorsListedOneByOne) {
  const std::string laws = "components: [{type: bhm2, k0: 2, k1: 0.25, uy: 20}]";
  std::vector<structure::IsolatorLayout> isolators;
  const analysis::Summary group =
      RunModel(Plan("    - {name: c, positions: [[0, 0], [20000, 0], [20000, 10000]], " + laws +
                    "}\n"
                    "    - {name: w, position: [0, 10000], " +
                    laws + "}\n"),
               "group.yaml", &isolators);
  const analysis::Summary hand =
      RunModel(Plan("    - {name: c_1, position: [0, 0], " + laws + "}\n" +
                    "    - {name: c_2, position: [20000, 0], " + laws + "}\n" +
                    "    - {name: c_3, position: [20000, 10000], " + laws + "}\n" +
                    "    - {name: w, position: [0, 10000], " + laws + "}\n"),
               "hand.yaml");
  ASSERT_TRUE(group.ok()) << group.run.message;
  ASSERT_TRUE(hand.ok()) << hand.run.message;
  ASSERT_EQ(isolators.size(), 4u);
  EXPECT_EQ(isolators[1].name, "c_2");
  EXPECT_EQ(isolators[1].position.x, 20000.0);
  EXPECT_EQ(isolators[3].name, "w");
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(group.peaks.isolator_displacements[i].value,
              hand.peaks.isolator_displacements[i].value);
    EXPECT_EQ(group.peaks.isolator_forces[i].value, hand.peaks.isolator_forces[i].value);
  }
  EXPECT_EQ(group.peaks.base_shear.value, hand.peaks.base_shear.value);
}

TEST(BearingGroup, PlanEmptyPositionsAndClashingNamesAreLocated) {
  const std::string laws = "components: [{type: bhm2, k0: 2, k1: 0.25, uy: 20}]";
  const std::string empty = ErrorOf(Plan("    - {name: c, positions: [], " + laws + "}\n"));
  EXPECT_NE(empty.find("bad.yaml:8:28: plan.isolators[0].positions: the list is empty: a group of "
                       "0 bearings"),
            std::string::npos)
      << empty;
  const std::string both =
      ErrorOf(Plan("    - {name: c, position: [0, 0], positions: [[0, 0]], " + laws + "}\n"));
  EXPECT_NE(both.find("plan.isolators[0].positions: give position (one isolator) or positions"),
            std::string::npos)
      << both;
  const std::string clash =
      ErrorOf(Plan("    - {name: c_2, position: [0, 0], " + laws + "}\n" +
                   "    - {name: c, positions: [[0, 0], [10, 0]], " + laws + "}\n"));
  EXPECT_NE(clash.find("plan.isolators[1]: name 'c_2' is already used by isolator 0"),
            std::string::npos)
      << clash;
  const std::string outside =
      ErrorOf(Plan("    - {name: c, positions: [[0, 0], [30000, 0]], " + laws + "}\n"));
  EXPECT_NE(outside.find("plan.isolators[0].positions[1]: [30000, 0] is outside the footprint"),
            std::string::npos)
      << outside;
}

}  // namespace
}  // namespace isolab::model
