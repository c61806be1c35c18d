// `isolab cyclic` end to end: the binary's output, exit codes and files; --path and --orbit: a
// model driven along cyclic's own sinusoid (its loop again, to the digits the CSV keeps), round a
// circle (the coupled slider's closed forms), a plan model's isolator along a biaxial path, and
// the errors.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli/run_isolab.h"
#include "leftover_temporaries.h"
#include "own_test_file.h"
#include "paper_tables.h"

namespace {

using isolab::testing::Outcome;
using isolab::testing::RunIsolab;

std::string Model(const std::string& name) {
  return std::string(ISOLAB_SOURCE_DIR) + "/models/paper/" + name;
}
std::string BadFile(const std::string& name) {
  return std::string(ISOLAB_TEST_DATA_DIR) + "/io/data/" + name;
}

TEST(CyclicCommand, Table9EnergyPerCycleAtTheTestAmplitudesMatchesClosedForms) {
  std::string amplitudes;
  for (const double ua : isolab::testing::kTestAmplitudes) {
    if (!amplitudes.empty()) amplitudes += ',';
    amplitudes += std::to_string(ua);
  }
  const Outcome run =
      RunIsolab("cyclic " + Model("table9_thm1_system.yaml") + " -a " + amplitudes + " --json");
  ASSERT_EQ(run.exit_code, 0);
  const auto json = nlohmann::json::parse(run.output);
  ASSERT_EQ(json["runs"].size(), std::size(isolab::testing::kTestAmplitudes));
  for (const auto& result : json["runs"]) {
    const double ua = result["protocol"]["amplitude"];
    const auto& third = result["cycles"][2];
    double total = 0.0;
    for (int c = 0; c < 9; ++c) {
      const double expected = isolab::testing::Thm1CycleEnergy(isolab::testing::kTable9[c], ua);
      total += expected;
      EXPECT_NEAR(third["components"][c]["dissipated"].get<double>(), expected,
                  1e-9 * (expected + 1))
          << "component " << c + 1 << " at u_a = " << ua;
    }
    EXPECT_NEAR(third["dissipated"].get<double>(), total, 1e-9 * total) << "u_a = " << ua;
  }
}

TEST(CyclicCommand, Table7DemoPrintsThePapersNumbers) {
  const Outcome run = RunIsolab("cyclic " + Model("table7_thm1_soft.yaml"));
  ASSERT_EQ(run.exit_code, 0);
  EXPECT_NE(run.output.find("kh2=0.0526316 fs=20 uc=80"), std::string::npos) << run.output;
  // Second cycle: W_d = 12480 kN mm, peak |F| = 44 kN, u_ha = 156 mm.
  EXPECT_NE(run.output.find("    2            12480             44           156\n"),
            std::string::npos)
      << run.output;
}

TEST(CyclicCommand, WritesTheLoopToCsvAtomically) {
  const auto directory = isolab::testing::OwnTestDirectory();
  std::filesystem::create_directories(directory);
  const auto csv = directory / "loop.csv";
  std::filesystem::remove(csv);
  const Outcome run = RunIsolab("cyclic " + Model("table10_thm2_system.yaml") +
                                " -a 100 -n 1 --csv " + csv.string());
  ASSERT_EQ(run.exit_code, 0);
  std::ifstream in(csv);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header,
            "time_s,u_mm,force_kN,force_c1_kN,force_c2_kN,force_c3_kN,force_c4_kN,force_c5_kN,"
            "force_c6_kN");
  int rows = 0;
  for (std::string line; std::getline(in, line);) ++rows;
  EXPECT_EQ(rows, 401);
  EXPECT_TRUE(isolab::testing::LeftoverTemporaries(csv).empty());
}

TEST(CyclicCommand, BadModelFilesExitWithCodeTwoAndALocatedMessage) {
  for (const std::string name :
       {"bad_thm1_k1_above_k0.yaml", "bad_unknown_key.yaml", "bad_syntax.yaml",
        "bad_missing_key.yaml", "bad_law_type.yaml", "bad_empty.yaml"}) {
    const Outcome run = RunIsolab("cyclic " + BadFile(name) + " -a 10", true);
    EXPECT_EQ(run.exit_code, 2) << name;
    EXPECT_EQ(run.output.rfind("isolab: " + BadFile(name) + ":", 0), 0u) << run.output;
  }
  const Outcome k1 = RunIsolab("cyclic " + BadFile("bad_thm1_k1_above_k0.yaml") + " -a 10", true);
  EXPECT_NE(k1.output.find(":7:11: isolation.components[0].k1 = 1.2 (must be < k0 = 1)"),
            std::string::npos)
      << k1.output;
}

TEST(CyclicCommand, BadOptionsExitWithCodeTwo) {
  EXPECT_EQ(RunIsolab("cyclic " + Model("table7_thm1_hard.yaml") + " -a -5", true).exit_code, 2);
  EXPECT_EQ(RunIsolab("cyclic " + Model("table7_thm1_hard.yaml") + " --steps-per-cycle 7", true)
                .exit_code,
            2);
  // 0 is a multiple of 4: the message says what is allowed.
  const auto zero =
      RunIsolab("cyclic " + Model("table7_thm1_hard.yaml") + " --steps-per-cycle 0", true);
  EXPECT_EQ(zero.exit_code, 2);
  EXPECT_NE(zero.output.find("must be a multiple of 4, at least 4"), std::string::npos)
      << zero.output;
  EXPECT_EQ(RunIsolab("cyclic " + BadFile("good_mechanical.yaml"), true).exit_code,
            2);  // no amplitude
  EXPECT_EQ(RunIsolab("cyclic /nonexistent.yaml", true).exit_code, 2);
  EXPECT_EQ(RunIsolab("frobnicate", true).exit_code, 2);
}

std::filesystem::path Scratch(const std::string& name) {
  const auto directory = isolab::testing::OwnTestDirectory();
  std::filesystem::create_directories(directory);
  const auto path = directory / name;
  std::filesystem::remove(path);
  return path;
}

// Rows of a CSV with one header line, as numbers.
std::vector<std::vector<double>> ReadRows(const std::filesystem::path& csv, int skip = 1) {
  std::ifstream in(csv);
  std::string line;
  for (int k = 0; k < skip; ++k) std::getline(in, line);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream fields(line);
    for (std::string field; std::getline(fields, field, ',');) row.push_back(std::stod(field));
    rows.push_back(row);
  }
  return rows;
}

TEST(CyclicCommand, APathReplaysCyclicsOwnSinusoidToTheDigitsItsCsvKeeps) {
  const auto loop = Scratch("loop.csv");
  ASSERT_EQ(RunIsolab("cyclic " + Model("table9_thm1_system.yaml") + " -a 150 -n 2 --csv " +
                      loop.string())
                .exit_code,
            0);
  const auto rows = ReadRows(loop);
  const auto path = Scratch("sinusoid_path.csv");
  {
    std::ofstream out(path);
    out.precision(12);  // every digit of the loop's CSV (10 significant)
    out << "# units: force kN, length mm\ntime,displacement,force\n";
    for (const auto& row : rows) out << row[0] << "," << row[1] << "," << row[2] << "\n";
  }
  const auto replayed = Scratch("replayed.csv");
  const Outcome run = RunIsolab("cyclic " + Model("table9_thm1_system.yaml") + " --path " +
                                path.string() + " --json --csv " + replayed.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto json = nlohmann::json::parse(run.output)["runs"][0];
  EXPECT_FALSE(json["plan"].get<bool>());
  // The displacements to the 10 digits the loop's CSV keeps: the same forces to about as many
  // (the series springs' k0 = 1e6 amplify a displacement's last digit a millionfold at most).
  EXPECT_LT(json["comparison"]["e2"].get<double>(), 1e-14);
  const auto again = ReadRows(replayed);
  ASSERT_EQ(again.size(), rows.size());
  for (std::size_t k = 0; k < rows.size(); k += 7) {
    EXPECT_NEAR(again[k][2], rows[k][2], 1e-7 * (1 + std::abs(rows[k][2]))) << k;
  }

  // Measured forces of the opposite sign: the error is twice the measured force, an NRMSE of 2
  // (RMS-normalised, as shaketable's), and the line says the model does worse than zero.
  const auto flipped = Scratch("flipped_path.csv");
  {
    std::ofstream out(flipped);
    out.precision(12);
    out << "# units: force kN, length mm\ntime,displacement,force\n";
    for (const auto& row : rows) out << row[0] << "," << row[1] << "," << -row[2] << "\n";
  }
  const auto json_flipped = RunIsolab("cyclic " + Model("table9_thm1_system.yaml") + " --path " +
                                      flipped.string() + " --json");
  ASSERT_EQ(json_flipped.exit_code, 0) << json_flipped.output;
  const auto comparison = nlohmann::json::parse(json_flipped.output)["runs"][0]["comparison"];
  EXPECT_NEAR(comparison["nrmse"].get<double>(), 2.0, 1e-6);
  EXPECT_NEAR(comparison["e2"].get<double>(), 4.0, 1e-5);
  const auto text =
      RunIsolab("cyclic " + Model("table9_thm1_system.yaml") + " --path " + flipped.string());
  EXPECT_NE(text.output.find("NRMSE = 2 (RMS error over the measured force's RMS; above 1: worse "
                             "than predicting a force of zero)"),
            std::string::npos)
      << text.output;
}

TEST(CyclicCommand, RoundACircleTheCoupledSliderMeetsItsClosedForms) {
  const auto model = Scratch("slider.yaml");
  std::ofstream(model) << "units: {force: kN, length: mm, time: s}\n"
                          "isolation:\n  components:\n"
                          "    - {name: slider, type: elastoplastic, k0: 9, uy: 1}\n";
  const int steps = 2000;
  const Outcome run =
      RunIsolab("cyclic " + model.string() + " --orbit circle -a 10 -T 1 -n 2 --steps-per-cycle " +
                std::to_string(steps) + " --json");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto cycle = nlohmann::json::parse(run.output)["runs"][0]["cycles"][1];
  const double fx = cycle["force_at_end"][0], fy = cycle["force_at_end"][1];
  EXPECT_NEAR(std::hypot(fx, fy), 9.0, 1e-9);  // fs, slipping
  EXPECT_NEAR(M_PI / 2 - std::atan2(fy, fx), std::asin(0.1), 2 * M_PI / steps);
  const double rho = std::sqrt(99.0);
  EXPECT_NEAR(cycle["dissipated"].get<double>() / (2 * M_PI * 9.0 * rho), 1.0,
              2 * M_PI / (steps * rho));
  const Outcome text = RunIsolab("cyclic " + model.string() + " --orbit figure8 -a 10 -n 1");
  EXPECT_EQ(text.exit_code, 0) << text.output;
  EXPECT_NE(text.output.find("two directions"), std::string::npos) << text.output;
}

TEST(CyclicCommand, APlanModelsIsolatorFollowsABiaxialPath) {
  const auto path = Scratch("biaxial.csv");
  {
    std::ofstream out(path);
    out << "# units: force kN, length mm\ntime,displacement_x,displacement_y\n";
    for (int k = 0; k <= 800; ++k) {
      const double t = 0.005 * k;
      out << t << "," << 80 * std::sin(2.1 * t) << "," << 50 * std::sin(3.3 * t) << "\n";
    }
  }
  const std::string plan =
      std::string(ISOLAB_SOURCE_DIR) + "/models/plan/five_story_table9_plan.yaml";
  const Outcome run =
      RunIsolab("cyclic " + plan + " --isolator sw --path " + path.string() + " --json");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto json = nlohmann::json::parse(run.output)["runs"];
  ASSERT_EQ(json.size(), 1u);
  EXPECT_TRUE(json[0]["plan"].get<bool>());
  EXPECT_EQ(json[0]["components"].size(), 9u);
  EXPECT_GT(json[0]["dissipated"].get<double>(), 0.0);
  const Outcome missing =
      RunIsolab("cyclic " + plan + " --isolator nowhere --path " + path.string(), true);
  EXPECT_EQ(missing.exit_code, 2) << missing.output;
  EXPECT_NE(missing.output.find("--isolator: nowhere: "), std::string::npos) << missing.output;
}

// Pendulums with several sliding surfaces (laws of several states) along a path and an orbit, in
// one direction and as a plan model's isolator: each once aborted the process (the replay wrote
// past states sized by the number of components). Along cyclic's own sinusoid the path is the
// loop again; round a circle and a figure eight each completes with its energy.
TEST(CyclicCommand, MultiplePendulumsFollowPathsAndOrbits) {
  const auto model = Scratch("pendulums.yaml");
  std::ofstream(model)
      << "units: {force: kN, length: mm, time: s}\n"
         "isolation:\n  components:\n"
         "    - {name: tfp, type: triple_friction_pendulum, w: 1000, uy: 0.5, r1: 2100, r2: 280,\n"
         "       r3: 280, r4: 2100, mu1: 0.06, mu2: 0.02, mu3: 0.02, mu4: 0.10, d1: 400, d2: 50,\n"
         "       d3: 50, d4: 400}\n"
         "    - {name: dfp, type: double_friction_pendulum, w: 500, uy: 0.5, r1: 1500, r2: 1500,\n"
         "       mu1: 0.04, mu2: 0.07, d1: 150, d2: 150}\n";
  const auto loop = Scratch("pendulum_loop.csv");
  ASSERT_EQ(RunIsolab("cyclic " + model.string() + " -a 600 -n 2 --csv " + loop.string()).exit_code,
            0);
  const auto rows = ReadRows(loop);
  const auto path = Scratch("pendulum_path.csv");
  {
    std::ofstream out(path);
    out.precision(12);
    out << "# units: force kN, length mm\ntime,displacement,force\n";
    for (const auto& row : rows) out << row[0] << "," << row[1] << "," << row[2] << "\n";
  }
  const Outcome replay =
      RunIsolab("cyclic " + model.string() + " --path " + path.string() + " --json");
  ASSERT_EQ(replay.exit_code, 0) << replay.output;
  EXPECT_LT(nlohmann::json::parse(replay.output)["runs"][0]["comparison"]["e2"].get<double>(),
            1e-14);
  for (const char* orbit : {"circle", "figure8"}) {
    const Outcome run =
        RunIsolab("cyclic " + model.string() + " --orbit " + orbit + " -a 300 -n 2 --json");
    ASSERT_EQ(run.exit_code, 0) << orbit << ": " << run.output;
    const double dissipated = nlohmann::json::parse(run.output)["runs"][0]["dissipated"];
    EXPECT_TRUE(std::isfinite(dissipated) && dissipated > 0.0) << orbit;
  }
  // A plan model's isolator: the same bearings at four corners.
  const auto plan = Scratch("pendulum_plan.yaml");
  std::ofstream(plan)
      << "units: {force: kN, length: mm, time: s}\n"
         "plan:\n  footprint: [[0, 0], [20000, 10000]]\n  base: {mass: 400 t}\n"
         "  isolators:\n    - name: tfp\n"
         "      positions: [[0, 0], [20000, 0], [0, 10000], [20000, 10000]]\n"
         "      components: [{name: tfp, type: triple_friction_pendulum, w: 981, uy: 0.5,\n"
         "        r1: 2100, r2: 280, r3: 280, r4: 2100, mu1: 0.06, mu2: 0.02, mu3: 0.02,\n"
         "        mu4: 0.10, d1: 400, d2: 50, d3: 50, d4: 400}]\n";
  const Outcome corner =
      RunIsolab("cyclic " + plan.string() + " --isolator tfp_1 --orbit circle -a 300 -n 1 --json");
  ASSERT_EQ(corner.exit_code, 0) << corner.output;
  EXPECT_TRUE(nlohmann::json::parse(corner.output)["runs"][0]["plan"].get<bool>());
}

// Orbits and paths no bearing reaches overflow the laws' forces (or their error against the
// measured ones): refused with the option or the file to blame, never printed as inf and nan with
// exit code 0.
TEST(CyclicCommand, DisplacementsThatOverflowTheForcesAreRefused) {
  const std::string table7 = Model("table7_thm1_soft.yaml");
  const Outcome orbit = RunIsolab("cyclic " + table7 + " --orbit circle -a 1e300", true);
  EXPECT_EQ(orbit.exit_code, 2) << orbit.output;
  EXPECT_NE(orbit.output.find("--amplitude: the forces along 'circle"), std::string::npos)
      << orbit.output;
  EXPECT_NE(orbit.output.find("are not finite"), std::string::npos) << orbit.output;
  const auto huge = Scratch("huge_path.csv");
  std::ofstream(huge) << "# units: force kN, length mm\ntime,displacement,force\n0,0,0\n"
                         "1,1e300,1e300\n2,-1e300,-1e300\n";
  const Outcome path = RunIsolab("cyclic " + table7 + " --path " + huge.string(), true);
  EXPECT_EQ(path.exit_code, 2) << path.output;
  EXPECT_NE(path.output.find("are not finite"), std::string::npos) << path.output;
  EXPECT_EQ(path.output.find("nan"), std::string::npos) << path.output;
}

TEST(CyclicCommand, PathsAreCheckedAndErrorsLocated) {
  const auto bare = Scratch("bare_path.csv");
  std::ofstream(bare) << "time,displacement\n0,0\n1,5\n2,0\n";
  const std::string table7 = Model("table7_thm1_hard.yaml");
  Outcome run = RunIsolab("cyclic " + table7 + " --path " + bare.string(), true);
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("bare_path.csv: no '# units:"), std::string::npos) << run.output;
  EXPECT_EQ(RunIsolab("cyclic " + table7 + " --path " + bare.string() +
                      " --force-unit kN --length-unit mm")
                .exit_code,
            0);
  run = RunIsolab("cyclic " + table7 + " --path " + bare.string() + " --orbit circle -a 5", true);
  EXPECT_EQ(run.exit_code, 2) << run.output;
  const auto broken = Scratch("broken_path.csv");
  std::ofstream(broken) << "# units: force kN, length mm\ntime,displacement\n0,0\n1,x\n";
  run = RunIsolab("cyclic " + table7 + " --path " + broken.string(), true);
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("broken_path.csv:4: column 2"), std::string::npos) << run.output;
  // An uncoupled pair is for paths in plan: along one direction it would change nothing.
  run = RunIsolab("cyclic " + table7 + " --path " + bare.string() +
                      " --force-unit kN --length-unit mm --uncoupled",
                  true);
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("--uncoupled: bare_path moves along one direction"), std::string::npos)
      << run.output;
  run = RunIsolab("cyclic " + table7 + " --orbit circle", true);  // the file's amplitude is used
  EXPECT_EQ(run.exit_code, 0) << run.output;
  // A length unit given beside a file's line that names another is refused at the line.
  const auto metres = Scratch("metres_path.csv");
  std::ofstream(metres) << "# units: force kN, length m\ntime,displacement\n0,0\n1,0.005\n2,0\n";
  run = RunIsolab("cyclic " + table7 + " --path " + metres.string() + " --length-unit mm", true);
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("metres_path.csv:1: units: the file's line says length m, the length "
                            "unit given beside it says mm"),
            std::string::npos)
      << run.output;
}

}  // namespace
