// `isolab compare` on buildings in plan: a study of the bundled eccentric plan building and its
// symmetric twin under a record pair reports, per run, what `isolab run` prints for the same
// model and pair (the independent path: the run command), the same whether one thread, two or
// two MPI ranks ran it; a symmetric building under the pair does not twist; bad pairs and
// studies that mix buildings that move in different directions exit 2 naming the study's line.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli/run_isolab.h"
#include "cli/text_file.h"
#include "own_test_file.h"

namespace isolab::testing {
namespace {

namespace fs = std::filesystem;

const std::string kRoot = ISOLAB_SOURCE_DIR;
const std::string kPlan = kRoot + "/models/plan/five_story_table9_plan.yaml";
const std::string kRecords = kRoot + "/ground_motions/";

// A study file in the test's own folder, with a pair entry for `h1` and `h2` (file names in
// ground_motions/) unless `records` gives the list.
fs::path WriteStudy(const fs::path& folder, const std::string& variants,
                    const std::string& records) {
  const fs::path path = folder / "plan_study.yaml";
  std::ofstream(path) << "building: " << kPlan << "\nvariants:\n"
                      << variants << "records:\n"
                      << records << "scales: [0.6]\n";
  return path;
}

std::string Pair(const std::string& h1, const std::string& h2, const std::string& extra = "") {
  return "  - {h1: {file: " + kRecords + h1 + "}, h2: {file: " + kRecords + h2 + "}" + extra +
         "}\n";
}

const std::string kFirmPair = Pair("fwn_firm_seed1.at2", "h2_fwn_firm_seed3.at2");

// ":5:<column>: records[0].h2": where the study's first pair entry `pair` gives h2.
std::string H2Location(const std::string& pair) {
  return ":5:" + std::to_string(pair.find("h2: ") + 5) + ": records[0].h2: ";
}

// The bundled plan model with its centres of mass on the centre of stiffness, its records'
// paths absolute: the eccentric building's symmetric twin.
fs::path WriteSymmetricModel(const fs::path& folder) {
  std::string text = ReadText(kPlan);
  ReplaceOnce(&text, "base: {mass: 100 t, centre_of_mass: [13200, 8000]}",
              "base: {mass: 100 t, centre_of_mass: [12000, 8000]}");
  ReplaceOnce(&text, "    centre_of_mass: [13200, 8000]\n", "    centre_of_mass: [12000, 8000]\n");
  for (int i = 0; i < 2; ++i) ReplaceOnce(&text, "../../ground_motions/", kRecords);
  const fs::path path = folder / "symmetric_plan.yaml";
  std::ofstream(path) << text;
  return path;
}

// What `isolab run` prints on a plan model as the study's seven quantities (kN, mm; g).
std::vector<double> RunQuantities(const nlohmann::json& run) {
  double resultant = 0.0;
  for (const auto& [name, isolator] : run["isolators"].items()) {
    resultant = std::max(resultant, isolator["displacement"]["value"].get<double>());
  }
  const auto& peaks = run["peaks"];
  return {resultant,
          peaks["base_shear"]["value"].get<double>(),
          100.0 * peaks["largest_drift_ratio"].get<double>(),
          peaks["floor_acceleration"]["value"].get<double>() / 9806.65,
          std::abs(run["residual_isolator_displacement"].get<double>()),
          peaks["floor_rotation"]["value"].get<double>(),
          run["torsional_amplification"].get<double>()};
}

constexpr std::size_t kQuantities = 7;
constexpr std::size_t kFileColumn = 4 + 2 * kQuantities + 1;

TEST(PlanCompareCommand, SummaryIsWhatIsolabRunPrintsForEachVariantWhoeverRunsIt) {
  const fs::path folder = FreshTestDirectory();
  const fs::path symmetric = WriteSymmetricModel(folder);
  const fs::path study = WriteStudy(
      folder, "  - {name: eccentric}\n  - {name: symmetric, model: " + symmetric.string() + "}\n",
      kFirmPair);
  const fs::path one = folder / "one", two = folder / "two";
  const Outcome run1 = RunIsolab("compare " + study.string() + " -q -j 1 -o " + one.string());
  const Outcome run2 = RunIsolab("compare " + study.string() + " -q -j 2 -o " + two.string());
  ASSERT_EQ(run1.exit_code, 0) << run1.output;
  ASSERT_EQ(run2.exit_code, 0) << run2.output;
  EXPECT_EQ(ReadText(one / "summary.csv"), ReadText(two / "summary.csv"));
  EXPECT_TRUE(ReadText(one / "summary.h5") == ReadText(two / "summary.h5"));
  EXPECT_NE(run1.output.find("torsion amp. [1]"), std::string::npos) << run1.output;

  const auto rows = CsvRows(one / "summary.csv");
  ASSERT_EQ(rows.size(), 1u + 2u + 2u * 2u);
  EXPECT_EQ(rows[0][4], "isolator_displacement [mm]");
  EXPECT_EQ(rows[0][5], "base_shear [kN]");
  EXPECT_EQ(rows[0][9], "floor_rotation [rad]");
  EXPECT_EQ(rows[0][10], "torsional_amplification [1]");
  EXPECT_EQ(rows[0][kFileColumn], "file");
  // The bundled model's own excitation is this pair at scale 0.6: `isolab run` on each model
  // runs what the study ran.
  for (const auto& [row, model] : {std::pair{1, kPlan}, std::pair{2, symmetric.string()}}) {
    ASSERT_EQ(rows[row][3], "completed") << rows[row][0];
    EXPECT_EQ(rows[row][1], "fwn_firm_seed1");
    EXPECT_TRUE(fs::exists(one / rows[row][kFileColumn])) << rows[row][kFileColumn];
    EXPECT_EQ(rows[row][kFileColumn + 1], "g");
    const Outcome run = RunIsolab("run " + model + " --json -o " + (folder / "run.h5").string());
    ASSERT_EQ(run.exit_code, 0) << run.output;
    const std::vector<double> expected = RunQuantities(nlohmann::json::parse(run.output));
    for (std::size_t q = 0; q < kQuantities; ++q) {
      EXPECT_EQ(std::stod(rows[row][4 + q]), expected[q]) << rows[row][0] << " " << rows[0][4 + q];
    }
  }
  // The eccentric building twists; its symmetric twin, under the same pair, does not.
  EXPECT_GT(std::stod(rows[1][10]), 1.01);
  EXPECT_GT(std::stod(rows[1][9]), 1e-4);
  EXPECT_LT(std::stod(rows[2][9]), 1e-12);
  EXPECT_NEAR(std::stod(rows[2][10]), 1.0, 1e-9);
  EXPECT_GT(std::stod(rows[2][4]), 100.0);  // a real response, in mm

  // The same study on two MPI ranks: mpirun is part of the set-up (scripts/setup.sh installs
  // openmpi-bin), so its absence fails here rather than passing unseen.
  ASSERT_EQ(RunShell("command -v mpirun").exit_code, 0)
      << "no mpirun: install openmpi-bin (scripts/setup.sh does)";
  const fs::path mpi = folder / "mpi";
  const Outcome ranks =
      RunShell("mpirun --allow-run-as-root --oversubscribe -np 2 " + std::string(ISOLAB_BINARY) +
               " compare " + study.string() + " -q -o " + mpi.string());
  ASSERT_EQ(ranks.exit_code, 0) << ranks.output;
  EXPECT_EQ(ReadText(one / "summary.csv"), ReadText(mpi / "summary.csv"));
}

const std::string kBilinear = "{name: b, type: bhm2, ke: 8.0653, kh: 0.80653, fs: 18.146}";

// An isolation variant is the building with every isolator on the variant's laws: the same
// numbers as a plan model file written so, read by the model reader and run by `isolab run`.
TEST(PlanCompareCommand, IsolationVariantIsTheBuildingWithThoseLawsAtEveryIsolator) {
  const fs::path folder = FreshTestDirectory();
  std::string text = ReadText(kPlan);
  const std::size_t from = text.find("components: &table9\n");
  const std::size_t to = text.find("    - {name: se");
  ASSERT_TRUE(from != std::string::npos && to != std::string::npos);
  text.replace(from, to - from, "components: &table9 [" + kBilinear + "]\n");
  for (int i = 0; i < 2; ++i) ReplaceOnce(&text, "../../ground_motions/", kRecords);
  const fs::path bilinear = folder / "bilinear_plan.yaml";
  std::ofstream(bilinear) << text;
  const fs::path study =
      WriteStudy(folder,
                 "  - {name: by_isolation, isolation: {components: [" + kBilinear +
                     "]}}\n  - {name: by_model, model: " + bilinear.string() + "}\n",
                 kFirmPair);
  const Outcome compare =
      RunIsolab("compare " + study.string() + " -q -o " + (folder / "out").string());
  ASSERT_EQ(compare.exit_code, 0) << compare.output;
  const auto rows = CsvRows(folder / "out" / "summary.csv");
  ASSERT_GE(rows.size(), 3u);
  const Outcome run =
      RunIsolab("run " + bilinear.string() + " --json -o " + (folder / "run.h5").string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::vector<double> expected = RunQuantities(nlohmann::json::parse(run.output));
  for (std::size_t q = 0; q < kQuantities; ++q) {
    EXPECT_EQ(rows[1][4 + q], rows[2][4 + q]) << rows[0][4 + q];
    EXPECT_EQ(std::stod(rows[1][4 + q]), expected[q]) << rows[0][4 + q];
  }
  EXPECT_GT(expected[0], 100.0);  // mm: the bilinear bearings move
  // The variant's results file says what replaced the isolation.
  EXPECT_NE(ReadText(folder / "out" / rows[1][kFileColumn])
                .find("variant by_isolation: the isolation above"),
            std::string::npos);
}

// Each bad study exits 2 with "<study>:<line>:<column>: <key path>: <what>", and runs nothing.
TEST(PlanCompareCommand, BadPairsAndMixedStudiesExitTwoWithTheirLocation) {
  const fs::path folder = FreshTestDirectory();
  const std::string eccentric = "  - {name: eccentric}\n";
  const std::string degrading =
      "  - {name: bilinear, isolation: {components: [{type: degrading_bhm2, k0: 2, k1: 0.25, "
      "uy: 20, loss: 0.1, slip_scale: 500}]}}\n";
  const std::string nan_angle =
      Pair("fwn_firm_seed1.at2", "h2_fwn_firm_seed3.at2", ", angle: .nan");
  const std::string huge_angle =
      Pair("fwn_firm_seed1.at2", "h2_fwn_firm_seed3.at2", ", angle: 1e308");
  struct Case {
    std::string variants, records, expected;
  };
  const std::vector<Case> cases = {
      {eccentric, Pair("fwn_firm_seed1.at2", "pulse_tp2.at2"),
       H2Location(Pair("fwn_firm_seed1.at2", "pulse_tp2.at2")) + "'" + kRecords +
           "pulse_tp2.at2' has 1201 samples, h1 '" + kRecords +
           "fwn_firm_seed1.at2' 3001; a pair must have the same length"},
      {eccentric, Pair("fwn_firm_seed1.at2", "elcentro_1940_ns.at2"),
       H2Location(Pair("fwn_firm_seed1.at2", "elcentro_1940_ns.at2")) + "'" + kRecords +
           "elcentro_1940_ns.at2' has a step of 0.02 s, h1 '" + kRecords +
           "fwn_firm_seed1.at2' 0.01 s; a pair must share one step"},
      {degrading, kFirmPair,
       ":3:33: variants[0].isolation: degrading_bhm2 has no coupled bidirectional form: every "
       "isolator of a building in plan takes these laws as coupled laws"},
      {"  - {name: one_direction, model: " + kRoot + "/models/buildings/five_story_table9.yaml}\n",
       kFirmPair,
       ":3:34: variants[0].model: '" + kRoot +
           "/models/buildings/five_story_table9.yaml' moves in one direction and the building '" +
           kPlan + "' in plan (x, y and rotation)"},
      {eccentric, nan_angle,
       ":5:" + std::to_string(nan_angle.find(".nan") + 1) +
           ": records[0].angle: '.nan' is not a finite number"},
      {eccentric, huge_angle,
       ":5:" + std::to_string(huge_angle.find("1e308") + 1) +
           ": records[0].angle: 1e+308 degrees (must be in [-360, 360])"},
  };
  for (const Case& c : cases) {
    const fs::path study = WriteStudy(folder, c.variants, c.records);
    const fs::path output = folder / "out";
    const Outcome run = RunIsolab("compare " + study.string() + " -o " + output.string(), true);
    EXPECT_EQ(run.exit_code, 2) << run.output;
    EXPECT_NE(run.output.find(study.string() + c.expected), std::string::npos)
        << run.output << "\nexpected: " << c.expected;
    EXPECT_FALSE(fs::exists(output));
  }
  // A pair in a one-direction study.
  const fs::path study = folder / "one_direction_study.yaml";
  std::ofstream(study) << "building: " << kRoot
                       << "/models/buildings/five_story_table9.yaml\nvariants: [{name: "
                          "as_built}]\nrecords:\n"
                       << kFirmPair << "scales: [1]\n";
  const Outcome run =
      RunIsolab("compare " + study.string() + " -o " + (folder / "out").string(), true);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.output.find(study.string() + ":4:5: records[0]: a pair of records drives a "
                                             "building in plan"),
            std::string::npos)
      << run.output;
}

// A building in plan takes a single record (along x) and a fixed-base variant, as a building in
// one direction does: the fixed base has no isolator and no base level.
TEST(PlanCompareCommand, SingleRecordsAndAFixedBaseRun) {
  const fs::path folder = FreshTestDirectory();
  const fs::path study =
      WriteStudy(folder, "  - {name: eccentric}\n  - {name: fixed, fixed_base: true}\n",
                 "  - " + kRecords + "fwn_firm_seed1.at2\n");
  const Outcome compare =
      RunIsolab("compare " + study.string() + " -q -o " + (folder / "out").string());
  ASSERT_EQ(compare.exit_code, 0) << compare.output;
  const auto rows = CsvRows(folder / "out" / "summary.csv");
  ASSERT_GE(rows.size(), 3u);
  EXPECT_EQ(rows[1][3], "completed");
  EXPECT_EQ(rows[2][3], "completed");
  EXPECT_GT(std::stod(rows[1][4]), 10.0);                   // the isolators move
  EXPECT_TRUE(rows[2][4].empty());                          // a fixed base has none
  EXPECT_GT(std::stod(rows[2][5]), std::stod(rows[1][5]));  // and takes more base shear
}

}  // namespace
}  // namespace isolab::testing
