// `isolab design` end to end on the worked example's building with a short synthetic suite: the
// files it writes, D_TM against D_M with accidental eccentricity, the ELF floor applied to the
// design values, and bad input as located errors with exit code 2.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "own_test_file.h"
#include "run_isolab.h"

namespace isolab {
namespace {

namespace fs = std::filesystem;

const std::string kBuilding =
    std::string(ISOLAB_SOURCE_DIR) + "/models/design/five_story_lrb_plan.yaml";

std::string WriteDesign(const fs::path& folder, const std::string& suite,
                        const std::string& extra = "") {
  const fs::path path = folder / "design.yaml";
  std::ofstream(path) << "model: " << kBuilding << "\n"
                      << "target: {asce7: {sms: 1.5 g, sm1: 0.9 g, tl: 8 s}}\n"
                      << suite << extra;
  return path.string();
}

// design_values.csv as {bound/quantity/statistic: value}.
std::map<std::string, double> ReadValues(const fs::path& path) {
  std::map<std::string, double> values;
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::string bound, quantity, unit, statistic, value;
    std::getline(row, bound, ',');
    std::getline(row, quantity, ',');
    std::getline(row, unit, ',');
    std::getline(row, statistic, ',');
    std::getline(row, value, ',');
    values[bound + "/" + quantity + "/" + statistic] = std::stod(value);
  }
  return values;
}

TEST(DesignCommand, DesignsThePlanBuildingOnASyntheticSuite) {
  const fs::path folder = testing::FreshTestDirectory();
  const std::string design = WriteDesign(
      folder, "suite: {synthetic: {count: 3, seed: 2, duration: 24 s}}\neccentricity: 0.05\n");
  const testing::Outcome outcome =
      testing::RunIsolab("design " + design + " -o " + (folder / "out").string() + " -q");
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;
  EXPECT_NE(outcome.output.find("design values (maximum of 3 records"), std::string::npos)
      << outcome.output;
  for (const char* name :
       {"design.md", "design_values.csv", "design_runs.csv", "design_spectra.csv",
        "design_spectra.png", "design_loops.png", "design_orbits.png", "design_drifts.png",
        "models/five_story_lrb_plan_upper.yaml", "records/pair1_h2.at2"}) {
    EXPECT_TRUE(fs::is_regular_file(folder / "out" / name)) << name;
  }
  const std::map<std::string, double> v = ReadValues(folder / "out" / "design_values.csv");
  for (const char* bound : {"nominal", "upper", "lower"}) {
    const std::string b(bound);
    // The worst bearing of the worst eccentricity moves more than the centre without it.
    EXPECT_GT(v.at(b + "/D_TM/max"), v.at(b + "/D_M/max")) << bound;
    // The ELF procedure's D_TM includes the plan's torsion (Eq. 17.5-3): above 1.15 D_M.
    EXPECT_GE(v.at(b + "/D_TM/elf"), 1.15 * v.at(b + "/D_M/elf") * (1 - 1e-12)) << bound;
  }
  EXPECT_GT(v.at("lower/D_M/elf"), v.at("nominal/D_M/elf"));
  EXPECT_GT(v.at("nominal/D_M/elf"), v.at("upper/D_M/elf"));
}

// A folder an earlier design wrote is emptied first (nothing of it is taken for the new design's);
// a folder holding anything else is refused, untouched.
TEST(DesignCommand, ReplacesAnEarlierDesignAndRefusesAFolderOfOtherFiles) {
  const fs::path folder = testing::FreshTestDirectory();
  const std::string motions = std::string(ISOLAB_SOURCE_DIR) + "/ground_motions/";
  const fs::path path = folder / "design.yaml";
  std::ofstream(path) << "model: " << ISOLAB_TEST_DATA_DIR << "/study/data/two_story_lrb.yaml\n"
                      << "target: {asce7: {sms: 1.2 g, sm1: 0.6 g}}\nsuite:\n  records: ["
                      << motions << "fwn_firm_seed1.at2, " << motions << "fwn_soft_seed2.at2, "
                      << motions << "elcentro_1940_ns.at2]\n";
  const fs::path out = folder / "out";
  const std::string command = "design " + path.string() + " -q --no-figures -o " + out.string();
  ASSERT_EQ(testing::RunIsolab(command).exit_code, 0);
  const fs::path stale = out / "histories" / "runs" / "lower" / "earlier_x1.h5";
  std::ofstream(stale) << "an earlier design's history";
  ASSERT_EQ(testing::RunIsolab(command).exit_code, 0);
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::is_regular_file(out / "design_values.csv"));

  std::ofstream(out / "notes.txt") << "the engineer's";
  const testing::Outcome refused = testing::RunIsolab(command, true);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.output.find("holds 'notes.txt', which a design does not write"),
            std::string::npos)
      << refused.output;
  EXPECT_TRUE(fs::is_regular_file(out / "design_values.csv"));
}

TEST(DesignCommand, RefusesBadInputWithItsPlace) {
  const fs::path folder = testing::FreshTestDirectory();
  const std::string design =
      WriteDesign(folder, "suite: {synthetic: {count: 3, duration: 10 s}}\n");
  const testing::Outcome outcome =
      testing::RunIsolab("design " + design + " -o " + (folder / "out").string(), true);
  EXPECT_EQ(outcome.exit_code, 2) << outcome.output;
  EXPECT_NE(outcome.output.find("suite.synthetic.duration: 10 s records cannot hold 4 cycles"),
            std::string::npos)
      << outcome.output;
  EXPECT_FALSE(fs::exists(folder / "out" / "models")) << "a refused design wrote its models";

  const std::string bad_limit = WriteDesign(folder, "suite: {synthetic: {count: 3}}\n",
                                            "eccentricity: 0.05\ndrift_limit: 2\n");
  const testing::Outcome bad = testing::RunIsolab("design " + bad_limit, true);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.output.find("design.yaml:5:14: drift_limit: 2 (a story drift ratio in (0, 1)"),
            std::string::npos)
      << bad.output;
}

}  // namespace
}  // namespace isolab
