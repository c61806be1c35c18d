// Plan model files (plan_model_file.h) and the plan analysis set-up (plan_analysis.h): what a
// valid file becomes, and bad input as a located error (file:line:col, key path, what).
#include "isolab/model/plan_model_file.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "isolab/analysis/plan_analysis.h"
#include "isolab/core/errors.h"
#include "own_test_file.h"

namespace isolab::model {
namespace {

const std::string kGroundMotions = std::string(ISOLAB_SOURCE_DIR) + "/ground_motions/";

// A two-story plan model; `replace` swaps one line of it for another (the line must exist).
std::string Model(const std::string& line = "", const std::string& with = "") {
  std::string text =
      "units: {force: kN, length: mm, time: s}\n"                                         // 1
      "plan:\n"                                                                           // 2
      "  footprint: [[0, 0], [20000, 10000]]\n"                                           // 3
      "  base: {mass: 100 t, centre_of_mass: [10500, 5000], radius_of_gyration: 6000}\n"  // 4
      "  stories:\n"                                                                      // 5
      "    - {name: s1, mass: 100 t, stiffness: {x: 300, y: 200, torsion: 3.0e10}}\n"     // 6
      "    - {name: s2, mass: 80 t, centre_of_mass: [9000, 5000], height: 3000,\n"        // 7
      "       centre_of_stiffness: [10000, 4000], x: [{type: linear_spring, k: 250}],\n"  // 8
      "       y: [{type: bhm2, k0: 250, k1: 20, uy: 5}], torsion: 2.0e10}\n"              // 9
      "  isolators:\n"                                                                    // 10
      "    - {name: a, position: [0, 0], components: [{type: bhm2, k0: 2, k1: 0.25, uy: 20}]}\n"
      "    - {name: b, position: [20000, 10000], coupling: uncoupled,\n"  // 12
      "       components: [{type: degrading_bhm2, k0: 2, k1: 0.25, uy: 20, loss: 0.1, "
      "slip_scale: 500}]}\n"  // 13
      "excitation:\n"         // 14
      "  ground_motion:\n"    // 15
      "    h1: {file: " +
      kGroundMotions +
      "fwn_firm_seed1.at2, scale: 0.5}\n"  // 16
      "    h2: {file: " +
      kGroundMotions +
      "h2_fwn_firm_seed3.at2, scale: 0.5}\n"  // 17
      "    angle: 30\n";                      // 18
  if (!line.empty()) {
    const std::size_t at = text.find(line);
    EXPECT_NE(at, std::string::npos) << line;
    if (at != std::string::npos) text.replace(at, line.size(), with);
  }
  return text;
}

std::string Write(const std::string& text, const std::string& name = "plan.yaml") {
  const std::string path = (testing::OwnTestDirectory() / name).string();
  std::ofstream(path) << text;
  return path;
}

// The InputError's message when loading (and preparing, with `prepare`) the text fails.
std::string ErrorOf(const std::string& text, bool prepare = false) {
  const std::string path = Write(text);
  try {
    const PlanModelFile model = LoadPlanModelFile(path);
    if (prepare) analysis::PreparePlanAnalysis(model, {});
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "no error";
  return {};
}

void ExpectError(const std::string& message, const std::string& location, const std::string& text) {
  EXPECT_EQ(message.rfind((testing::OwnTestDirectory() / "plan.yaml").string() + location, 0), 0u)
      << message;
  EXPECT_NE(message.find(text), std::string::npos) << message;
}

TEST(PlanModelFile, ReadsFloorsStoriesIsolatorsAndBothComponents) {
  const std::string path = Write(Model());
  ASSERT_TRUE(IsPlanModelFile(path));
  const PlanModelFile model = LoadPlanModelFile(path);
  const structure::PlanBuilding& b = model.building;
  EXPECT_DOUBLE_EQ(b.base.mass, 0.1);  // 100 t in kN s^2/mm
  EXPECT_DOUBLE_EQ(b.base.rotational_inertia, 0.1 * 6000.0 * 6000.0);
  ASSERT_EQ(b.stories.size(), 2u);
  // Defaults: centre of mass and of stiffness at the footprint's centre, the inertia of a
  // uniform slab over the footprint.
  EXPECT_EQ(b.stories[0].floor.centre_of_mass, (hysteresis::Vec2{10000, 5000}));
  EXPECT_EQ(b.stories[0].centre_of_stiffness, (hysteresis::Vec2{10000, 5000}));
  EXPECT_DOUBLE_EQ(b.stories[0].floor.rotational_inertia,
                   0.1 * (20000.0 * 20000.0 + 10000.0 * 10000.0) / 12.0);
  EXPECT_EQ(b.stories[1].centre_of_stiffness, (hysteresis::Vec2{10000, 4000}));
  EXPECT_EQ(b.stories[1].y.components()[0].parameters.type(), hysteresis::LawType::kBhm2);
  ASSERT_EQ(b.isolators.size(), 2u);
  EXPECT_FALSE(b.isolators[0].assembly.components()[0].law_y.has_value());  // coupled
  EXPECT_TRUE(b.isolators[1].assembly.components()[0].law_y.has_value());   // uncoupled
  ASSERT_TRUE(model.ground_motion.has_value());
  EXPECT_DOUBLE_EQ(model.ground_motion->angle, 30.0);
  EXPECT_EQ(model.isolation_along_x.size(), 2u);
}

// The kind is read from the top-level keys without parsing the file; the parsed answer is the
// reference for every layout a model may have.
TEST(PlanModelFile, IsPlanModelFileAgreesWithTheParsedMapInEveryLayout) {
  const std::vector<std::pair<std::string, bool>> cases = {
      {"units: {force: kN}\nplan:\n  base: {}\n", true},
      {"# plan: in a comment\n%YAML 1.2\n---\nplan :\n  base: {}\n", true},
      {"\"plan\": {base: {}}\n", true},
      {"'plan': {}\n", true},
      {"{units: {force: kN}, plan: {base: {}}}\n", true},
      {"structure:\n  plan: 3\n", false},  // not top-level
      {"description: |\n  plan: in a block scalar\nstructure: {}\n", false},
      {"planned: 1\nplan_b: 2\n", false},
      {"{structure: {plan: 1}}\n", false},
      {"{unclosed: \n", false},  // not YAML: the one-direction reader says what is wrong
      {"", false}};
  for (const auto& [text, plan] : cases) {
    const std::string path = Write(text, "kind.yaml");
    EXPECT_EQ(IsPlanModelFile(path), plan) << text;
    if (text.find("unclosed") == std::string::npos && !text.empty()) {
      const YAML::Node root = YAML::LoadFile(path);
      EXPECT_EQ(root.IsMap() && root["plan"].IsDefined(), plan) << text;
    }
  }
}

TEST(PlanModelFile, TurnsThePairToTheBuildingsAxes) {
  const PlanModelFile model = LoadPlanModelFile(Write(Model()));
  const analysis::PlanAnalysisSetup setup = analysis::PreparePlanAnalysis(model, {});
  // Each component alone, from the same reader, for the rotation by 30 degrees.
  const PlanModelFile h1_only = LoadPlanModelFile(Write(
      Model("    h2: {file: " + kGroundMotions + "h2_fwn_firm_seed3.at2, scale: 0.5}\n", "")));
  const analysis::PlanAnalysisSetup one = analysis::PreparePlanAnalysis(h1_only, {});
  const PlanModelFile h2_as_h1 = LoadPlanModelFile(
      Write(Model("    h1: {file: " + kGroundMotions +
                      "fwn_firm_seed1.at2, scale: 0.5}\n"
                      "    h2: {file: " +
                      kGroundMotions + "h2_fwn_firm_seed3.at2, scale: 0.5}\n",
                  "    h1: {file: " + kGroundMotions + "h2_fwn_firm_seed3.at2, scale: 0.5}\n")));
  const analysis::PlanAnalysisSetup two = analysis::PreparePlanAnalysis(h2_as_h1, {});
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  ASSERT_EQ(setup.excitation.x.values.size(), 3001u);
  for (std::size_t k = 0; k < 3001; k += 50) {
    // one.x = cos * H1, one.y = sin * H1; two.x = cos * H2, two.y = sin * H2.
    const double h1 = one.excitation.x.values[k] / c, h2 = two.excitation.x.values[k] / c;
    EXPECT_NEAR(setup.excitation.x.values[k], c * h1 - s * h2, 1e-9);
    EXPECT_NEAR(setup.excitation.y.values[k], s * h1 + c * h2, 1e-9);
  }
  EXPECT_EQ(setup.h2.path, kGroundMotions + "h2_fwn_firm_seed3.at2");
}

TEST(PlanModelFile, AnIsolatorOutsideTheFootprintIsALocatedError) {
  ExpectError(ErrorOf(Model("position: [20000, 10000]", "position: [20500, 10000]")),
              ":12:", "plan.isolators[1].position: [20500, 10000] is outside the footprint");
}

TEST(PlanModelFile, ACentreOfMassOutsideTheFootprintIsALocatedError) {
  ExpectError(ErrorOf(Model("centre_of_mass: [9000, 5000]", "centre_of_mass: [9000, -5]")),
              ":7:", "plan.stories[1].centre_of_mass: [9000, -5] is outside the footprint");
}

TEST(PlanModelFile, ASingularRotationalInertiaIsALocatedError) {
  ExpectError(ErrorOf(Model("radius_of_gyration: 6000", "radius_of_gyration: 0")),
              ":4:", "plan.base.radius_of_gyration: 0 (must be > 0)");
  ExpectError(ErrorOf(Model("radius_of_gyration: 6000", "rotational_inertia: -1")),
              ":4:", "plan.base.rotational_inertia: -1 (must be > 0)");
}

TEST(PlanModelFile, MissingKeysAreLocatedErrors) {
  ExpectError(ErrorOf(Model("  isolators:\n", "  isolator:\n")), ":", "isolator");
  ExpectError(ErrorOf(Model("torsion: 2.0e10", "")),
              ":7:", "plan.stories[1]: missing key 'torsion'");
  ExpectError(ErrorOf(Model("position: [0, 0], ", "")),
              ":11:", "plan.isolators[0]: missing key 'position'");
}

// Errors in the uniform shorthand `stories: {count: ...}` were located at 1:1 (the story was read
// from a copy of its node, which has no marks): they are located at the key.
TEST(PlanModelFile, ErrorsInUniformStoriesAreLocatedAtTheKey) {
  const std::string uniform =
      "  stories:\n"
      "    count: 3\n"
      "    mass: 100 t\n"
      "    stiffness: {x: 300, y: -200, torsion: 3.0e10}\n";
  const std::string model = Model("  stories:\n", uniform);
  const std::string text =
      model.substr(0, model.find("    - {name: s1")) + model.substr(model.find("  isolators:"));
  ExpectError(ErrorOf(text), ":8:28:", "plan.stories.stiffness.y: -200 (must be > 0)");
}

TEST(PlanModelFile, ALawWithoutACoupledFormMustBeUncoupled) {
  ExpectError(ErrorOf(Model("coupling: uncoupled,", "")), ":13:",
              "plan.isolators[1].components[0]: degrading_bhm2 has no coupled bidirectional form");
}

TEST(PlanModelFile, APairWithDifferentStepsOrLengthsIsALocatedError) {
  // The El Centro record: 1560 samples at 0.02 s against the noise's 3001 at 0.01 s.
  const std::string other = "    h2: {file: " + kGroundMotions + "elcentro_1940_ns.at2}\n";
  const std::string h2 =
      "    h2: {file: " + kGroundMotions + "h2_fwn_firm_seed3.at2, scale: 0.5}\n";
  ExpectError(ErrorOf(Model(h2, other), true),
              ":17:", "excitation.ground_motion.h2: its step 0.02 differs from h1's 0.01");
  // The same step, a shorter record: the first 1000 samples of seed 3.
  std::ifstream in(kGroundMotions + "h2_fwn_firm_seed3.at2");
  std::string header, line;
  const std::string short_path = (testing::OwnTestDirectory() / "short.at2").string();
  std::ofstream short_record(short_path);
  for (int i = 0; i < 4 && std::getline(in, line); ++i) {
    if (i == 3) line = "NPTS=    1000, DT=   0.01000 SEC,";
    short_record << line << "\n";
  }
  for (int i = 0; i < 200 && std::getline(in, line); ++i) short_record << line << "\n";
  short_record.close();
  ExpectError(ErrorOf(Model(h2, "    h2: {file: " + short_path + "}\n"), true),
              ":17:", "excitation.ground_motion.h2: 1000 samples, h1 has 3001");
}

TEST(PlanModelFile, OneDirectionCommandsRefuseAPlanModelAndSaySo) {
  try {
    LoadModelFile(Write(Model()));
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    ExpectError(error.what(), ":3:", "plan: a plan model");
  }
}

}  // namespace
}  // namespace isolab::model
