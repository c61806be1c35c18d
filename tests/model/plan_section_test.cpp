// Model files of buildings in plan (the `plan` section, plan_section.cpp) and their preparation
// for a run (problem.h): what a valid file becomes, and bad input as a located error
// (file:line:col, key path, what).
#include "isolab/model/model_file.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "isolab/analysis/problem.h"
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
    const ModelFile model = LoadModelFile(path);
    if (prepare) analysis::Prepare(model, {});
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
  const ModelFile model = LoadModelFile(path);
  ASSERT_TRUE(model.structure.has_value());
  ASSERT_EQ(model.structure->kind, StructureSection::Kind::kPlanBuilding);
  const structure::PlanBuilding& b = model.structure->plan;
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
  ASSERT_EQ(model.excitation.ground_motion.size(), 2u);
  EXPECT_DOUBLE_EQ(model.excitation.angle, 30.0);
  EXPECT_EQ(model.excitation.ground_motion[1].key, "excitation.ground_motion.h2");
  EXPECT_EQ(model.isolation.size(), 0u);  // the isolators carry their laws
}

TEST(PlanModelFile, TurnsThePairToTheBuildingsAxes) {
  const ModelFile model = LoadModelFile(Write(Model()));
  const analysis::Problem setup = analysis::Prepare(model, {});
  // Each component alone, from the same reader, for the rotation by 30 degrees.
  const ModelFile h1_only = LoadModelFile(Write(
      Model("    h2: {file: " + kGroundMotions + "h2_fwn_firm_seed3.at2, scale: 0.5}\n", "")));
  const analysis::Problem one = analysis::Prepare(h1_only, {});
  const ModelFile h2_as_h1 = LoadModelFile(
      Write(Model("    h1: {file: " + kGroundMotions +
                      "fwn_firm_seed1.at2, scale: 0.5}\n"
                      "    h2: {file: " +
                      kGroundMotions + "h2_fwn_firm_seed3.at2, scale: 0.5}\n",
                  "    h1: {file: " + kGroundMotions + "h2_fwn_firm_seed3.at2, scale: 0.5}\n")));
  const analysis::Problem two = analysis::Prepare(h2_as_h1, {});
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  const auto x = [](const analysis::Problem& p) { return p.excitation.ground[0].acceleration; };
  const auto y = [](const analysis::Problem& p) { return p.excitation.ground[1].acceleration; };
  ASSERT_EQ(setup.excitation.ground.size(), 2u);
  ASSERT_EQ(x(setup).values.size(), 3001u);
  for (std::size_t k = 0; k < 3001; k += 50) {
    // one.x = cos * H1, one.y = sin * H1; two.x = cos * H2, two.y = sin * H2.
    const double h1 = x(one).values[k] / c, h2 = x(two).values[k] / c;
    EXPECT_NEAR(x(setup).values[k], c * h1 - s * h2, 1e-9);
    EXPECT_NEAR(y(setup).values[k], s * h1 + c * h2, 1e-9);
  }
  ASSERT_EQ(setup.records.size(), 2u);
  EXPECT_EQ(setup.records[1].path, kGroundMotions + "h2_fwn_firm_seed3.at2");
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

TEST(PlanModelFile, APlanIsABuildingOfItsOwnAndCarriesItsIsolatorsLaws) {
  ExpectError(ErrorOf("structure: {type: sdof, mass: 1}\n" + Model()), ":4:",
              "plan: a model is either a building in plan (plan) or one in one direction");
  ExpectError(ErrorOf(Model() + "isolation: {components: [{type: linear_spring, k: 1}]}\n"),
              ":19:", "isolation: a building in plan carries its isolators' laws");
}

TEST(PlanModelFile, ASlabOnItsIsolatorsNeedsNoStory) {
  std::string text = Model();
  const std::size_t first = text.find("  stories:\n");
  const std::size_t last = text.find("  isolators:\n");
  text.erase(first, last - first);
  const ModelFile model = LoadModelFile(Write(text));
  EXPECT_TRUE(model.structure->plan.stories.empty());
  const analysis::Problem problem = analysis::Prepare(model, {});
  EXPECT_EQ(problem.structure.dofs(), 3);
  EXPECT_EQ(problem.layout.levels.size(), 1u);
  EXPECT_TRUE(problem.summary.fixed_base_modes.empty());
}

TEST(PlanModelFile, ASecondComponentOnAOneDirectionModelIsALocatedError) {
  const std::string text =
      "units: {force: kN, length: mm}\n"
      "isolation: {components: [{type: linear_spring, k: 1}]}\n"
      "structure: {type: sdof, mass: 0.1}\n"
      "excitation:\n"
      "  ground_motion:\n"
      "    h1: {file: " + kGroundMotions + "fwn_firm_seed1.at2}\n"
      "    h2: {file: " + kGroundMotions + "h2_fwn_firm_seed3.at2}\n";
  try {
    LoadModelFile(Write(text, "one.yaml"));
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("one.yaml:7:"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("the structure moves along x only"),
              std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace isolab::model
