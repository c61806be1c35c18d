// `isolab cyclic` end to end: the binary's output, exit codes and files.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

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
  EXPECT_EQ(RunIsolab("cyclic " + BadFile("good_mechanical.yaml"), true).exit_code,
            2);  // no amplitude
  EXPECT_EQ(RunIsolab("cyclic /nonexistent.yaml", true).exit_code, 2);
  EXPECT_EQ(RunIsolab("frobnicate", true).exit_code, 2);
}

}  // namespace
