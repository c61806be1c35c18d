// `isolab design` end to end on the worked example's building with a short synthetic suite: the
// files it writes, D_TM against D_M with accidental eccentricity, the ELF floor applied to the
// design values, and bad input as located errors with exit code 2.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli/design_values.h"
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
        "design.html", "design_checks.csv", "design_parts.csv", "design_bearings.csv",
        "models/five_story_lrb_plan_upper.yaml", "records/pair1_h2.at2"}) {
    EXPECT_TRUE(fs::is_regular_file(folder / "out" / name)) << name;
  }
  const std::map<std::string, double> v =
      testing::ReadDesignValues(folder / "out" / "design_values.csv");
  for (const char* bound : {"nominal", "upper", "lower"}) {
    const std::string b(bound);
    // The worst bearing of the worst eccentricity moves more than the centre without it.
    EXPECT_GT(v.at(b + "/D_TM/max"), v.at(b + "/D_M/max")) << bound;
    // The ELF procedure's D_TM includes the plan's torsion (Eq. 17.5-3): above 1.15 D_M.
    EXPECT_GE(v.at(b + "/D_TM/elf"), 1.15 * v.at(b + "/D_M/elf") * (1 - 1e-12)) << bound;
  }
  EXPECT_GT(v.at("lower/D_M/elf"), v.at("nominal/D_M/elf"));
  EXPECT_GT(v.at("nominal/D_M/elf"), v.at("upper/D_M/elf"));

  // Every row of design_runs.csv says the `isolab run` that reproduces it from the output folder,
  // on a model written there: a run with accidental eccentricity, run again as written, gives the
  // row's isolator displacement to the 12 digits the file keeps.
  std::ifstream runs(folder / "out" / "design_runs.csv");
  std::string header, row;
  std::getline(runs, header);
  const auto fields = [](const std::string& line) {
    std::vector<std::string> out;
    std::stringstream in(line);
    for (std::string field; std::getline(in, field, ',');) out.push_back(field);
    return out;
  };
  const std::vector<std::string> columns = fields(header);
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(columns.begin(), columns.end(), name) -
                                    columns.begin());
  };
  std::string eccentric;
  while (std::getline(runs, row)) {
    if (fields(row)[column("eccentricity")] == "ex-ey+") eccentric = row;  // the last such row
  }
  ASSERT_FALSE(eccentric.empty());
  const std::vector<std::string> cells = fields(eccentric);
  const std::string command = cells[column("command")];
  ASSERT_EQ(command.rfind("isolab run models/five_story_lrb_plan_", 0), 0u) << command;
  EXPECT_NE(command.find("_ex-ey+.yaml --record records/pair"), std::string::npos) << command;
  // Each pair runs H1 along x, then along y: the last row of a case is the pair turned by 90
  // degrees, and its command turns it.
  EXPECT_EQ(cells[column("orientation")], "90");
  EXPECT_NE(command.find(" --angle 90 "), std::string::npos) << command;
  const testing::Outcome again = testing::RunCommandLine(
      "cd " + (folder / "out").string() + " && " + std::string(ISOLAB_BINARY) +
      command.substr(std::string("isolab").size()) + " --json -q -o " +
      (folder / "again.h5").string());
  ASSERT_EQ(again.exit_code, 0) << command;
  const double peak =
      nlohmann::json::parse(again.output)["peaks"]["isolator_displacement"]["value"];
  const double listed = std::stod(cells[column("isolator_displacement [mm]")]);
  EXPECT_NEAR(peak, listed, 1e-11 * listed) << command;
}

std::string ReadFile(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Every file under `folder`, by its path relative to it, with its contents.
std::map<std::string, std::string> FilesUnder(const fs::path& folder) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(folder)) {
    if (e.is_regular_file())
      files[e.path().lexically_relative(folder).string()] = ReadFile(e.path());
  }
  return files;
}

// A design of the two-story building on the three bundled records, no figures: a few seconds.
std::string QuickDesign(const fs::path& folder, const std::string& extra = "") {
  const std::string motions = std::string(ISOLAB_SOURCE_DIR) + "/ground_motions/";
  const fs::path path = folder / "design.yaml";
  std::ofstream(path) << "model: " << ISOLAB_TEST_DATA_DIR << "/study/data/two_story_lrb.yaml\n"
                      << "target: {asce7: {sms: 1.2 g, sm1: 0.6 g}}\nsuite:\n  records: ["
                      << motions << "fwn_firm_seed1.at2, " << motions << "fwn_soft_seed2.at2, "
                      << motions << "elcentro_1940_ns.at2]\n"
                      << extra;
  return path.string();
}

// A design replaces an earlier design's folder (every file listed in its manifest) and nothing
// else: a folder with anything more, or anything changed, is refused before any work and left as
// it was.
TEST(DesignCommand, ReplacesOnlyAnEarlierDesignsFolder) {
  const fs::path folder = testing::FreshTestDirectory();
  const fs::path out = folder / "out";
  const std::string command =
      "design " + QuickDesign(folder) + " -q --no-figures -o " + out.string();
  ASSERT_EQ(testing::RunIsolab(command).exit_code, 0);
  ASSERT_TRUE(fs::is_regular_file(out / "design_manifest.txt"));
  EXPECT_NE(ReadFile(out / "design_manifest.txt").find(" design_values.csv\n"), std::string::npos);
  ASSERT_EQ(testing::RunIsolab(command).exit_code, 0);  // its own earlier design: replaced
  const std::string values = ReadFile(out / "design_values.csv");

  // A file the design did not write, anywhere in the folder: refused, untouched.
  const fs::path note = out / "histories" / "notes.txt";
  std::ofstream(note) << "the engineer's";
  const testing::Outcome refused = testing::RunIsolab(command, true);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.output.find("holds 'histories/notes.txt', which the earlier design did not "
                                "write"),
            std::string::npos)
      << refused.output;
  EXPECT_EQ(ReadFile(note), "the engineer's");
  EXPECT_EQ(ReadFile(out / "design_values.csv"), values);
  fs::remove(note);

  // A file of the design's, changed since: refused.
  std::ofstream(out / "design.md", std::ios::app) << "\nReviewed.\n";
  const testing::Outcome changed = testing::RunIsolab(command, true);
  EXPECT_EQ(changed.exit_code, 2);
  EXPECT_NE(changed.output.find("'design.md' has changed since the earlier design wrote it"),
            std::string::npos)
      << changed.output;
  EXPECT_NE(ReadFile(out / "design.md").find("Reviewed."), std::string::npos);
}

// A user's project folder that happens to hold folders named as a design's (models/, records/)
// and no manifest is not an earlier design: refused, nothing in it touched.
TEST(DesignCommand, RefusesAProjectFolderWithTheDesignsFolderNames) {
  const fs::path folder = testing::FreshTestDirectory();
  const fs::path project = folder / "project";
  fs::create_directories(project / "models");
  fs::create_directories(project / "records");
  std::ofstream(project / "models" / "building.yaml") << "mine";
  std::ofstream(project / "records" / "site.at2") << "mine too";
  const testing::Outcome refused = testing::RunIsolab(
      "design " + QuickDesign(folder) + " -q --no-figures -o " + project.string(), true);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.output.find("and no design_manifest.txt: it is not a folder an earlier "
                                "design wrote"),
            std::string::npos)
      << refused.output;
  EXPECT_EQ(ReadFile(project / "models" / "building.yaml"), "mine");
  EXPECT_EQ(ReadFile(project / "records" / "site.at2"), "mine too");
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::recursive_directory_iterator(project)) ++entries;
  EXPECT_EQ(entries, 4u);
}

// A design refused after it claimed the folder (its suite cannot be scaled) leaves the earlier
// design exactly as it was, and nothing beside it.
TEST(DesignCommand, ARefusedDesignLeavesTheEarlierOneUntouched) {
  const fs::path folder = testing::FreshTestDirectory();
  const fs::path out = folder / "out";
  ASSERT_EQ(
      testing::RunIsolab("design " + QuickDesign(folder) + " -q --no-figures -o " + out.string())
          .exit_code,
      0);
  const std::map<std::string, std::string> before = FilesUnder(out);
  // A period range far past the target's: refused once the bounds' T_M are known.
  const fs::path bad = folder / "bad";
  fs::create_directories(bad);
  const std::string refused_design = QuickDesign(bad, "  period_range: [0.75, 400]\n");
  const testing::Outcome refused =
      testing::RunIsolab("design " + refused_design + " -q --no-figures -o " + out.string(), true);
  EXPECT_EQ(refused.exit_code, 2) << refused.output;
  EXPECT_EQ(FilesUnder(out), before);
  for (const auto& e : fs::directory_iterator(folder)) {
    const std::string name = e.path().filename().string();
    EXPECT_TRUE(name == "out" || name == "bad" || name == "design.yaml") << name;
  }
}

// A synthetic design writes its pairs into its folder. A second design that takes them as its
// suite and writes into the same folder would move them aside with the earlier design before
// reading them: refused first at the entry, naming the folder and the option or key that chose
// it, the earlier design untouched.
TEST(DesignCommand, ASuiteInsideTheFolderTheDesignReplacesIsRefusedAtItsEntry) {
  const fs::path folder = testing::FreshTestDirectory();
  const fs::path out = folder / "out";
  const std::string model =
      "model: " + std::string(ISOLAB_TEST_DATA_DIR) + "/study/data/two_story_lrb.yaml\n";
  const std::string target = "target: {asce7: {sms: 1.2 g, sm1: 0.6 g}}\n";
  std::ofstream(folder / "synthetic.yaml") << model << target << "suite: {synthetic: {count: 3}}\n";
  ASSERT_EQ(testing::RunIsolab("design " + (folder / "synthetic.yaml").string() +
                               " -q --no-figures -o " + out.string())
                .exit_code,
            0);
  const auto before = FilesUnder(out);
  ASSERT_EQ(before.count("records/pair1_h1.at2"), 1u);
  // A record named through ".." (the reader normalises it), the folder by -o or by the design's
  // output.directory.
  const std::string records =
      "suite:\n  records: [out/../out/records/pair1_h1.at2, "
      "out/records/pair2_h1.at2, out/records/pair3_h1.at2]\n";
  struct Case {
    std::string extra, option, expected_option;
  };
  for (const Case& c : {Case{"", " -o out/", "--output"},
                        Case{"output: {directory: out}\n", "", "output.directory"}}) {
    std::ofstream(folder / "again.yaml") << model << target << records << c.extra;
    const testing::Outcome refused = testing::RunCommandLine(
        "cd " + folder.string() + " && " + ISOLAB_BINARY + " design again.yaml -q --no-figures" +
        c.option + " 2>&1 >/dev/null");
    EXPECT_EQ(refused.exit_code, 2) << refused.output;
    EXPECT_NE(refused.output.find("again.yaml:4:13: suite.records[0]: "
                                  "'out/records/pair1_h1.at2' is inside 'out"),
              std::string::npos)
        << refused.output;
    EXPECT_NE(
        refused.output.find("the earlier design this design replaces (" + c.expected_option + ")"),
        std::string::npos)
        << refused.output;
    EXPECT_EQ(FilesUnder(out), before) << c.expected_option;
  }
}

// A disk that fills while the design writes its histories (megabytes, where everything before
// them is tens of kilobytes): the design fails by name with exit 3 and the earlier design comes
// back untouched. The full disk is a file size limit on the design's process (ulimit -f, 200 KiB)
// with SIGXFSZ ignored, so that a write past it fails with EFBIG as one on a full disk fails with
// ENOSPC: both reach the writer as a failed write.
TEST(DesignCommand, ADiskThatFillsFailsTheDesignAndKeepsTheEarlierOne) {
  const fs::path folder = testing::FreshTestDirectory();
  const fs::path out = folder / "out";
  const std::string command =
      "design " + QuickDesign(folder) + " -q --no-figures -o " + out.string();
  ASSERT_EQ(testing::RunIsolab(command).exit_code, 0);
  const std::map<std::string, std::string> before = FilesUnder(out);
  const testing::Outcome full =
      testing::RunCommandLine("bash -c \"trap '' XFSZ; ulimit -f 200; exec " +
                              std::string(ISOLAB_BINARY) + " " + command + "\" 2>&1 >/dev/null");
  EXPECT_EQ(full.exit_code, 3) << full.output;
  EXPECT_NE(full.output.find("the histories kept for the figures could not be written"),
            std::string::npos)
      << full.output;
  EXPECT_NE(full.output.find("File too large"), std::string::npos) << full.output;
  EXPECT_EQ(FilesUnder(out), before);
  for (const auto& e : fs::directory_iterator(folder)) {
    const std::string name = e.path().filename().string();
    EXPECT_TRUE(name == "out" || name == "design.yaml") << name;
  }
}

// One design at a time into a folder: a lock beside it, held by a running process, refuses the
// second; a lock left by a process that is gone is taken over.
TEST(DesignCommand, ASecondDesignIntoTheSameFolderIsRefused) {
  const fs::path folder = testing::FreshTestDirectory();
  const fs::path out = folder / "out";
  const std::string command =
      "design " + QuickDesign(folder) + " -q --no-figures -o " + out.string();
  const fs::path lock = folder / ".out.design-lock";
  std::ofstream(lock) << getpid() << "\n";  // this test's process: running
  const testing::Outcome refused = testing::RunIsolab(command, true);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.output.find("another design (process " + std::to_string(getpid()) +
                                ") is writing into"),
            std::string::npos)
      << refused.output;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_TRUE(fs::exists(lock));  // not ours to remove

  // The pid of a shell that has exited: a design killed while it ran.
  const std::string gone = testing::RunCommandLine("sh -c 'echo $$'").output;
  std::ofstream(lock) << gone;
  const testing::Outcome taken = testing::RunIsolab(command, true);
  EXPECT_EQ(taken.exit_code, 0) << taken.output;
  EXPECT_TRUE(fs::is_regular_file(out / "design_values.csv"));
  EXPECT_FALSE(fs::exists(lock));
}

// The rule for the pendulums' weights is printed with its numbers, and a building whose
// pendulums are given a weight 60 % short of its own is warned about: in the first line of the
// summary, in design.md's Warnings, naming both weights.
TEST(DesignCommand, BearingWeightsAreStatedAndAMismatchWarnedFirst) {
  const fs::path folder = testing::FreshTestDirectory();
  const fs::path model = folder / "pendulums.yaml";
  // 110 t + 4 x 100 t = 510 t: 5001.4 kN. Four pendulums of w = 500 kN carry 2000 kN.
  std::ofstream(model)
      << "units: {force: kN, length: mm, time: s}\n"
         "isolation:\n  count: 4\n"
         "  components: [{name: fp, type: friction_pendulum, w: 500, r: 2235, mu: 0.06, uy: 0.5}]\n"
         "  modification: {fp: {mu: {min: 0.8, max: 1.3}}}\n"
         "structure: {type: shear_building, base_mass: 110 t,\n"
         "  stories: {count: 4, mass: 100 t, stiffness: 800 kN/mm, height: 3500}}\n"
         "analysis: {dt: 0.01}\n";
  const std::string motions = std::string(ISOLAB_SOURCE_DIR) + "/ground_motions/";
  const fs::path design = folder / "design.yaml";
  std::ofstream(design) << "model: " << model.string() << "\n"
                        << "target: {asce7: {sms: 1.2 g, sm1: 0.6 g}}\nsuite:\n  records: ["
                        << motions << "fwn_firm_seed1.at2, " << motions << "fwn_soft_seed2.at2, "
                        << motions << "elcentro_1940_ns.at2]\n";
  const fs::path out = folder / "out";
  const testing::Outcome run = testing::RunCommandLine(
      std::string(ISOLAB_BINARY) + " design " + design.string() + " --no-figures -o " +
      out.string() + " 2>" + (folder / "progress.txt").string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(run.output.rfind("WARNING: the runs gave ", 0), 0u) << run.output;
  const std::string weights =
      "friction pendulums' weights w sum to 2000 kN, the structure weighs 5001.4 kN (-60.0 %)";
  EXPECT_NE(run.output.find(weights), std::string::npos) << run.output;
  const std::string progress = ReadFile(folder / "progress.txt");
  EXPECT_NE(progress.find("bearing weights: 4 pendulum bearings carry 2000 kN in all (500 to 500 "
                          "kN each) in the ELF step and the runs alike, their laws' w (no "
                          "axial_load); the building weighs 5001.4 kN"),
            std::string::npos)
      << progress;
  const std::string report = ReadFile(out / "design.md");
  EXPECT_NE(report.find("**WARNING: the runs gave "), std::string::npos);
  const std::size_t section = report.find("## Warnings");
  ASSERT_NE(section, std::string::npos);
  EXPECT_NE(report.find("- upper: the " + weights, section), std::string::npos) << report;
  EXPECT_NE(report.find("| bearing_1 | 500 | 500 |"), std::string::npos) << report;
}

// What the pipeline would refuse late (or fail on as an "internal error", or run out of memory
// on) is refused before any work, located at its key in the design file, and leaves no folder.
TEST(DesignCommand, InputThePipelineCannotUseIsRefusedFirstWithItsPlace) {
  const fs::path folder = testing::FreshTestDirectory();
  const std::string building = std::string(ISOLAB_TEST_DATA_DIR) + "/study/data/two_story_lrb.yaml";
  const std::string motions = std::string(ISOLAB_SOURCE_DIR) + "/ground_motions/";
  const fs::path zero = folder / "zero.at2";
  {
    std::ofstream out(zero);
    out << "PEER\nall zeros\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS=  3000, DT=   .0100 "
           "SEC\n";
    for (int k = 0; k < 600; ++k) out << "0.0 0.0 0.0 0.0 0.0\n";
  }
  const fs::path long_target = folder / "long_target.csv";
  {
    std::ofstream out(long_target);
    out << "period_s,sa_g\n";
    for (int k = 1; k <= 10001; ++k) out << 1e-3 * k << ",1\n";
  }
  struct Case {
    Case(std::string s, std::string m, std::string text = "")
        : suite_or_target(std::move(s)), message(std::move(m)), model(std::move(text)) {}
    std::string suite_or_target, message;
    std::string model;  // the model's text, when not the two-story building
  };
  // A plan building on one isolator, and a model asking for the vertical component's axial loads
  // (a design's suite is horizontal).
  const std::string one_isolator =
      "units: {force: kN, length: mm, time: s}\nplan:\n  footprint: [[0, 0], [20000, 10000]]\n"
      "  base: {mass: 400 t}\n  isolators:\n    - {name: b, position: [10000, 5000],\n"
      "       components: [{name: b, type: bhm2, k0: 13.6, k1: 1.36, uy: 28.9}],\n"
      "       modification: {b: {k1: {min: 0.9, max: 1.1}}}}\nanalysis: {dt: 0.01}\n";
  const std::string vertical =
      "units: {force: kN, length: mm, time: s}\nisolation:\n  count: 4\n"
      "  components: [{name: fp, type: friction_pendulum, w: 1000, r: 2235, mu: 0.06, uy: 0.5}]\n"
      "  modification: {fp: {mu: {min: 0.8, max: 1.3}}}\n"
      "structure: {type: shear_building, base_mass: 408 t}\nanalysis: {dt: 0.01}\n"
      "axial_load: {vertical: true}\n";
  const std::string asce = "target: {asce7: {sms: 1.2 g, sm1: 0.6 g}}\n";
  const std::vector<Case> cases = {
      {asce + "suite: {synthetic: {count: 3, dt: 0.005 s, duration: 20 s}}\n",
       "design.yaml:3:35: suite.synthetic.dt: 0.005 s is finer than the model's analysis.dt, "
       "0.01 s"},
      {"target: {asce7: {sms: 1.2 g, sm1: 1e-9 g}}\nsuite: {synthetic: {count: 3}}\n",
       "design.yaml:2:9: target: the ELF procedure on the nominal bound: no displacement"},
      {asce + "suite: {synthetic: {count: 3, dt: 1.9 s, duration: 200 s}}\n",
       "design.yaml:3:35: suite.synthetic.dt: 1.9 s (at most 0.02 s"},
      {asce + "suite: {synthetic: {count: 3, duration: 1e7 s}}\n",
       "design.yaml:3:41: suite.synthetic.duration: 1e+07 s at dt = 0.01 s is 1e+09 samples a "
       "record; at most 1e+06"},
      {asce + "suite: {synthetic: {count: 1000000}}\n",
       "design.yaml:3:28: suite.synthetic.count: 1000000 (at most 100 pairs"},
      {asce + "suite: {synthetic: {count: 2000000000}}\n",
       "design.yaml:3:28: suite.synthetic.count: '2000000000' is beyond the whole numbers a "
       "model takes"},
      {asce + "suite: {records: [" + zero.string() + ", " + motions + "fwn_firm_seed1.at2, " +
           motions + "fwn_soft_seed2.at2]}\n",
       "design.yaml:3:19: suite.records[0]: '" + zero.string() + "' is all zeros"},
      {"target: {file: " + long_target.string() + "}\nsuite: {synthetic: {count: 3}}\n",
       "long_target.csv:10002: more than 10000 rows"},
      {asce + "suite: {synthetic: {count: 3}}\n",
       "design.yaml:1:8: model: '" + (folder / "case.yaml").string() +
           "' stands on one isolator at one point of its plan",
       one_isolator},
      {asce + "suite: {synthetic: {count: 3}}\n",
       "design.yaml:1:8: model: '" + (folder / "case.yaml").string() +
           "' asks for the vertical component's axial loads",
       vertical},
  };
  for (const Case& c : cases) {
    const fs::path design = folder / "design.yaml";
    if (!c.model.empty()) std::ofstream(folder / "case.yaml") << c.model;
    std::ofstream(design) << "model: "
                          << (c.model.empty() ? building : (folder / "case.yaml").string()) << "\n"
                          << c.suite_or_target;
    const fs::path out = folder / "out";
    const testing::Outcome refused = testing::RunIsolab(
        "design " + design.string() + " -q --no-figures -o " + out.string(), true);
    EXPECT_EQ(refused.exit_code, 2) << c.suite_or_target << refused.output;
    EXPECT_NE(refused.output.find(c.message), std::string::npos)
        << c.suite_or_target << refused.output;
    EXPECT_EQ(refused.output.find("internal error"), std::string::npos) << refused.output;
    EXPECT_FALSE(fs::exists(out)) << c.suite_or_target;
  }
}

// D_TM against each bearing's displacement capacity: a triple pendulum's d1 + d2 + d3 + d4 (here
// 100 + 50 + 50 + 100 = 300 mm, exceeded by this target: the slider runs on against its
// restrainers at the bearing's elastic stiffness), an HDR bearing's rubber thickness times
// the design's shear_strain_limit (100 mm x 2.5 = 250 mm), and a lead-rubber bearing's, which its
// law does not give: said, not guessed.
TEST(DesignCommand, DisplacementCapacitiesAreCheckedAgainstTheDesignDtm) {
  const fs::path folder = testing::FreshTestDirectory();
  const std::string motions = std::string(ISOLAB_SOURCE_DIR) + "/ground_motions/";
  const auto design_of = [&](const std::string& name, const std::string& components,
                             const std::string& modified, const std::string& extra) {
    std::ofstream(folder / (name + ".yaml"))
        << "units: {force: kN, length: mm, time: s}\nisolation:\n  count: 4\n  components: ["
        << components << "]\n  modification: {b: {" << modified
        << ": {min: 0.9, max: 1.1}}}\n"
           "structure: {type: shear_building, base_mass: 110 t,\n"
           "  stories: {count: 2, mass: 200 t, stiffness: 800 kN/mm, height: 3500}}\n"
           "analysis: {dt: 0.01}\n";
    const fs::path design = folder / (name + "_design.yaml");
    std::ofstream(design) << "model: " << name << ".yaml\n"
                          << "target: {asce7: {sms: 1.2 g, sm1: 0.6 g}}\nsuite:\n  records: ["
                          << motions << "fwn_firm_seed1.at2, " << motions << "fwn_soft_seed2.at2, "
                          << motions << "elcentro_1940_ns.at2]\n"
                          << extra;
    return testing::RunIsolab("design " + design.string() + " -q --no-figures -o " +
                              (folder / name).string());
  };
  const testing::Outcome tfp = design_of(
      "tfp",
      "{name: b, type: triple_friction_pendulum, w: 1250, r1: 2100, r2: 280, r3: 280, r4: 2100, "
      "mu1: 0.06, mu2: 0.02, mu3: 0.02, mu4: 0.10, d1: 100, d2: 50, d3: 50, d4: 100, uy: 0.5}",
      "mu1", "");
  ASSERT_EQ(tfp.exit_code, 0) << tfp.output;
  EXPECT_NE(tfp.output.find("D_TM <= displacement capacity of every bearing of the layer: "),
            std::string::npos)
      << tfp.output;
  EXPECT_NE(tfp.output.find("against 300 mm (d1 + d2 + d3 + d4 of b; ASCE 7-16 17.2.4): EXCEEDED"),
            std::string::npos)
      << tfp.output;
  EXPECT_NE(
      ReadFile(folder / "tfp" / "design.md").find("| 300 mm | d1 + d2 + d3 + d4 of b | EXCEEDED |"),
      std::string::npos);

  const std::string hdr =
      "{name: b, type: hdr_bearing, g: 4.0e-4, area: 231875, tr: 100, damping: 0.089, strain: "
      "1.5}";
  const testing::Outcome rubber = design_of("hdr", hdr, "g", "shear_strain_limit: 2.5\n");
  ASSERT_EQ(rubber.exit_code, 0) << rubber.output;
  EXPECT_NE(rubber.output.find("against 250 mm (tr x shear_strain_limit 2.5 of b; "),
            std::string::npos)
      << rubber.output;
  const testing::Outcome unknown = design_of("hdr_no_limit", hdr, "g", "");
  ASSERT_EQ(unknown.exit_code, 0) << unknown.output;
  EXPECT_NE(unknown.output.find("displacement capacity of every bearing of the layer: "),
            std::string::npos)
      << unknown.output;
  EXPECT_NE(unknown.output.find("against - (not known from the laws"), std::string::npos)
      << unknown.output;
  EXPECT_NE(unknown.output.find("ASCE 7-16 17.2.4): not checked"), std::string::npos)
      << unknown.output;
  // A shear strain limit on a layer without HDR bearings would set no capacity: refused.
  const testing::Outcome pendulums = design_of(
      "tfp_limit",
      "{name: b, type: triple_friction_pendulum, w: 1250, r1: 2100, r2: 280, r3: 280, r4: 2100, "
      "mu1: 0.06, mu2: 0.02, mu3: 0.02, mu4: 0.10, d1: 100, d2: 50, d3: 50, d4: 100, uy: 0.5}",
      "mu1", "shear_strain_limit: 2.5\n");
  EXPECT_EQ(pendulums.exit_code, 2);
  const std::string said =
      testing::RunIsolab("design " + (folder / "tfp_limit_design.yaml").string() +
                             " -q --no-figures -o " + (folder / "tfp_limit").string(),
                         true)
          .output;
  EXPECT_NE(said.find("tfp_limit_design.yaml:5:21: shear_strain_limit: sets the displacement "
                      "capacity of HDR bearings (hdr_bearing), and"),
            std::string::npos)
      << said;
  EXPECT_FALSE(fs::exists(folder / "tfp_limit"));
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

  // Workers beyond 8 per hardware thread only share the cores: refused as compare refuses them.
  const std::string good = WriteDesign(folder, "suite: {synthetic: {count: 3}}\n");
  const testing::Outcome crowd =
      testing::RunIsolab("design " + good + " -j 1000000 -o " + (folder / "crowd").string(), true);
  EXPECT_EQ(crowd.exit_code, 2) << crowd.output;
  EXPECT_NE(crowd.output.find("--jobs: 1000000 workers on"), std::string::npos) << crowd.output;
  EXPECT_FALSE(fs::exists(folder / "crowd"));

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
