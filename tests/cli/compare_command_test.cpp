// `isolab compare` end to end: the summary does not depend on the number of workers or MPI
// ranks (byte-identical CSV and HDF5), its numbers are those of `isolab run` on the same model,
// record and scale, failed runs are reported while the others finish, progress goes to stderr,
// and a bad study exits 2 with its location.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli/run_isolab.h"
#include "cli/text_file.h"
#include "own_test_file.h"

namespace {

namespace fs = std::filesystem;
using isolab::testing::CsvRows;
using isolab::testing::Outcome;
using isolab::testing::ReadText;
using isolab::testing::RunIsolab;
using isolab::testing::RunShell;

std::string StudyData(const std::string& name) {
  return std::string(ISOLAB_TEST_DATA_DIR) + "/study/data/" + name;
}
std::string Source(const std::string& relative) {
  return std::string(ISOLAB_SOURCE_DIR) + "/" + relative;
}

fs::path OutputFolder(const std::string& name) {
  const fs::path folder = isolab::testing::OwnTestDirectory() / name;
  fs::remove_all(folder);
  return folder;
}

bool HaveMpirun() { return RunShell("command -v mpirun").exit_code == 0; }

std::string Mpirun(int ranks) {
  // Root in containers needs the first flag; the second lets 2 ranks share fewer cores.
  return "mpirun --allow-run-as-root --oversubscribe -np " + std::to_string(ranks) + " " +
         ISOLAB_BINARY;
}

const std::vector<std::string>* FindRow(const std::vector<std::vector<std::string>>& rows,
                                        const std::string& variant, const std::string& record,
                                        const std::string& scale) {
  for (const auto& row : rows) {
    if (row.size() > 3 && row[0] == variant && row[1] == record && row[2] == scale) return &row;
  }
  return nullptr;
}

void ExpectSameSummaries(const fs::path& a, const fs::path& b) {
  EXPECT_EQ(ReadText(a / "summary.csv"), ReadText(b / "summary.csv")) << a << " vs " << b;
  const std::string h5 = ReadText(a / "summary.h5");
  EXPECT_GT(h5.size(), 1000u);
  EXPECT_TRUE(h5 == ReadText(b / "summary.h5")) << a << " vs " << b;
}

// Every per-run file of `a` is in `b` with the same bytes, and `b` has no other.
void ExpectSameRunFiles(const fs::path& a, const fs::path& b) {
  std::size_t files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(a / "runs")) {
    if (!entry.is_regular_file()) continue;
    ++files;
    const fs::path relative = fs::relative(entry.path(), a);
    ASSERT_TRUE(fs::exists(b / relative)) << relative;
    EXPECT_TRUE(ReadText(entry.path()) == ReadText(b / relative)) << relative;
  }
  std::size_t others = 0;
  for (const auto& entry : fs::recursive_directory_iterator(b / "runs")) {
    if (entry.is_regular_file()) ++others;
  }
  EXPECT_GT(files, 0u);
  EXPECT_EQ(files, others);
}

TEST(CompareCommand, OneOrTwoWorkersWriteIdenticalSummaries) {
  const fs::path one = OutputFolder("workers1"), two = OutputFolder("workers2");
  const Outcome run1 =
      RunIsolab("compare " + StudyData("small_study.yaml") + " -q -j 1 -o " + one.string());
  const Outcome run2 =
      RunIsolab("compare " + StudyData("small_study.yaml") + " -q -j 2 -o " + two.string());
  ASSERT_EQ(run1.exit_code, 0) << run1.output;
  ASSERT_EQ(run2.exit_code, 0) << run2.output;
  ExpectSameSummaries(one, two);
  // The table printed, up to the folders' names.
  EXPECT_EQ(run1.output.substr(0, run1.output.find("summary: ")),
            run2.output.substr(0, run2.output.find("summary: ")));
  EXPECT_NE(run1.output.find("scale 1 (ratios to thm1)"), std::string::npos);
  // 4 variants x 3 records x 2 scales, each with its results file.
  const auto rows = CsvRows(one / "summary.csv");
  EXPECT_EQ(rows.size(), 1u + 24u + 4u * 2u * 2u);
  for (std::size_t i = 1; i <= 24; ++i) {
    EXPECT_EQ(rows[i][3], "completed") << i;
    EXPECT_TRUE(fs::exists(one / rows[i].back())) << rows[i].back();
  }
  // The per-run files too: the same bytes whichever process wrote them.
  ExpectSameRunFiles(one, two);
}

// A record entry scaled to a target: each study scale multiplies the target's factor, so the
// record's PGA is the target times the scale, for one record and for a pair's h1 (whose factor
// scales h2); a target on h2 is refused at its place.
TEST(CompareCommand, ARecordEntrysTargetIsScaledByTheStudysScales) {
  const auto folder = isolab::testing::FreshTestDirectory();
  const std::string motions = std::string(ISOLAB_SOURCE_DIR) + "/ground_motions/";
  const auto study = folder / "targets.yaml";
  std::ofstream(study) << "building: " << StudyData("small_building.yaml") << "\n"
                       << "variants: [{name: thm1}]\nrecords:\n"
                       << "  - {file: " << motions << "fwn_firm_seed1.at2, scale: {pga: 0.4 g}}\n"
                       << "scales: [0.5, 1]\n";
  const Outcome run =
      RunIsolab("compare " + study.string() + " -q --runs none -o " + (folder / "out").string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto rows = CsvRows(folder / "out" / "summary.csv");
  const auto header = rows.front();
  const std::size_t scale = std::find(header.begin(), header.end(), "scale") - header.begin();
  const std::size_t pga = std::find(header.begin(), header.end(), "pga_g") - header.begin();
  ASSERT_LT(pga, header.size());
  int checked = 0;
  for (const auto& row : rows) {
    if (row.size() <= pga || row[1] != "fwn_firm_seed1") continue;
    EXPECT_NEAR(std::stod(row[pga]), 0.4 * std::stod(row[scale]), 1e-9) << row[scale];
    ++checked;
  }
  EXPECT_EQ(checked, 2);

  std::ofstream(study) << "building: " << ISOLAB_SOURCE_DIR
                       << "/models/plan/five_story_table9_plan.yaml\n"
                       << "variants: [{name: thm1}]\nrecords:\n"
                       << "  - {h1: {file: " << motions
                       << "fwn_firm_seed1.at2}, h2: {file: " << motions
                       << "h2_fwn_firm_seed3.at2, scale: {pga: 0.3 g}}}\n"
                       << "scales: [1]\n";
  const Outcome refused = RunIsolab("compare " + study.string() + " -q", true);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.output.find("records[0].h2.scale: a pair takes its target on h1"),
            std::string::npos)
      << refused.output;
}

TEST(CompareCommand, RunsOptionKeepsTheSummaryAndChoosesThePerRunFiles) {
  const fs::path full = OutputFolder("runs_full"), summary = OutputFolder("runs_summary"),
                 none = OutputFolder("runs_none");
  const std::string study = "compare " + StudyData("small_study.yaml") + " -q -j 2 -o ";
  ASSERT_EQ(RunIsolab(study + full.string()).exit_code, 0);
  const Outcome summary_run = RunIsolab(study + summary.string() + " --runs summary");
  ASSERT_EQ(summary_run.exit_code, 0) << summary_run.output;
  const Outcome none_run = RunIsolab(study + none.string() + " --runs none");
  ASSERT_EQ(none_run.exit_code, 0) << none_run.output;
  // The summary is the same but for the files named: none without per-run files.
  EXPECT_EQ(ReadText(full / "summary.csv"), ReadText(summary / "summary.csv"));
  const auto full_rows = CsvRows(full / "summary.csv");
  const auto none_rows = CsvRows(none / "summary.csv");
  ASSERT_EQ(full_rows.size(), none_rows.size());
  const std::size_t file_column =
      std::find(full_rows[0].begin(), full_rows[0].end(), "file") - full_rows[0].begin();
  ASSERT_LT(file_column, full_rows[0].size());
  for (std::size_t i = 1; i < full_rows.size(); ++i) {
    auto expected = full_rows[i];
    if (file_column < expected.size()) expected[file_column].clear();
    EXPECT_EQ(none_rows[i], expected) << i;
  }
  EXPECT_FALSE(fs::exists(none / "runs"));
  EXPECT_EQ(none_run.output.find("runs: "), std::string::npos) << none_run.output;
  // Summary-only run files: the peaks without histories, far smaller than the full ones.
  const fs::path one = "runs/thm1/pulse_tp2_x1.h5";
  ASSERT_TRUE(fs::exists(summary / one));
  EXPECT_LT(fs::file_size(summary / one) * 4, fs::file_size(full / one));
  EXPECT_NE(summary_run.output.find("(summaries only)"), std::string::npos);

  // The study file says the same (output.runs), and the flag overrides it. (A copy of the study
  // elsewhere, its relative paths made absolute.)
  std::string text = ReadText(StudyData("small_study.yaml"));
  const auto replace_all = [&text](const std::string& from, const std::string& to) {
    for (std::size_t at = text.find(from); at != std::string::npos;
         at = text.find(from, at + to.size())) {
      text.replace(at, from.size(), to);
    }
  };
  const std::string data = fs::path(StudyData("small_study.yaml")).parent_path().string() + "/";
  replace_all("../../../", Source(""));
  replace_all("building: small_building.yaml", "building: " + data + "small_building.yaml");
  const fs::path copy = isolab::testing::OwnTestDirectory() / "runs_study.yaml";
  std::ofstream(copy) << text << "\noutput: {runs: none}\n";
  const fs::path from_study = OutputFolder("runs_from_study"),
                 overridden = OutputFolder("runs_overridden");
  const Outcome by_study = RunIsolab("compare " + copy.string() + " -q -o " + from_study.string());
  const Outcome by_flag =
      RunIsolab("compare " + copy.string() + " -q --runs full -o " + overridden.string());
  ASSERT_EQ(by_study.exit_code, 0) << by_study.output;
  ASSERT_EQ(by_flag.exit_code, 0) << by_flag.output;
  EXPECT_FALSE(fs::exists(from_study / "runs"));
  EXPECT_TRUE(fs::exists(overridden / one));

  const Outcome bad = RunIsolab(study + none.string() + " --runs some");
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
}

TEST(CompareCommand, ARunFileThatCannotBeWrittenFailsItsRunOnEveryWorkerCount) {
  for (const char* workers : {"1", "2"}) {
    const fs::path folder = OutputFolder(std::string("unwritable_") + workers);
    // A folder where the run's file should go: the file cannot be created there.
    fs::create_directories(folder / "runs/thm1/pulse_tp2_x1.h5");
    const Outcome run = RunIsolab("compare " + StudyData("small_study.yaml") + " -q -j " + workers +
                                  " -o " + folder.string());
    EXPECT_EQ(run.exit_code, 1) << workers << ": " << run.output;
    const auto rows = CsvRows(folder / "summary.csv");
    const auto* row = FindRow(rows, "thm1", "pulse_tp2", "1");
    ASSERT_NE(row, nullptr) << workers;
    EXPECT_EQ((*row)[3], "failed") << workers;
    const auto* other = FindRow(rows, "thm1", "pulse_tp2", "0.5");
    ASSERT_NE(other, nullptr);
    EXPECT_EQ((*other)[3], "completed") << workers;
  }
}

// A compare replaces only what an earlier compare wrote (its manifest lists it): a summary or a
// run file of someone else's, or a file where it needs the runs' folder, is refused before any
// run, the folder left as it was; its own folder it writes again.
TEST(CompareCommand, AnOutputFolderHoldingOtherFilesIsRefusedBeforeTheRuns) {
  const std::string compare = "compare " + StudyData("small_study.yaml") + " -q -j 1 -o ";
  for (const std::string theirs : {"summary.csv", "runs/thm1/pulse_tp2_x1.h5", "runs"}) {
    const fs::path folder = OutputFolder("theirs");
    fs::create_directories((folder / theirs).parent_path());
    std::ofstream(folder / theirs) << "my notes\n";
    const Outcome refused = RunIsolab(compare + folder.string(), true);
    EXPECT_EQ(refused.exit_code, 2) << theirs << ": " << refused.output;
    EXPECT_NE(refused.output.find(folder.string() + ": holds '" + theirs + "'"), std::string::npos)
        << refused.output;
    EXPECT_EQ(ReadText(folder / theirs), "my notes\n") << theirs;
    EXPECT_FALSE(fs::exists(folder / "compare_manifest.txt")) << theirs;
  }
  const fs::path own = OutputFolder("own");
  ASSERT_EQ(RunIsolab(compare + own.string()).exit_code, 0);
  std::ofstream(own / "notes.txt") << "beside the study's files: never the study's to write\n";
  ASSERT_EQ(RunIsolab(compare + own.string()).exit_code, 0);
  EXPECT_TRUE(fs::exists(own / "notes.txt"));
}

TEST(CompareCommand, RunsMatchIsolabRunOnTheSameModelRecordAndScale) {
  const fs::path folder = OutputFolder("match");
  ASSERT_EQ(
      RunIsolab("compare " + StudyData("small_study.yaml") + " -q -o " + folder.string()).exit_code,
      0);
  const auto rows = CsvRows(folder / "summary.csv");
  const auto* row = FindRow(rows, "thm1", "pulse_tp2", "1");
  ASSERT_NE(row, nullptr);
  const Outcome run = RunIsolab("run " + StudyData("small_building.yaml") + " --record " +
                                Source("ground_motions/pulse_tp2.at2") + " --scale 1 --json -o " +
                                (folder / "run.h5").string());
  ASSERT_EQ(run.exit_code, 0);
  const auto json = nlohmann::json::parse(run.output);
  // Same numbers to the last bit: the study runs exactly what `isolab run` runs.
  EXPECT_EQ(std::stod((*row)[4]), json["peaks"]["isolator_displacement"]["value"].get<double>());
  EXPECT_EQ(std::stod((*row)[5]), json["peaks"]["base_shear"]["value"].get<double>());
  EXPECT_GT(std::stod((*row)[4]), 200.0);  // a real response, in mm
  // Table 9 isolated vs fixed base under the same record: the isolation cuts the drift.
  const auto* fixed = FindRow(rows, "fixed", "fwn_firm_seed1", "1");
  const auto* isolated = FindRow(rows, "thm1", "fwn_firm_seed1", "1");
  ASSERT_TRUE(fixed != nullptr && isolated != nullptr);
  EXPECT_EQ((*fixed)[4], "");  // no isolator
  EXPECT_GT(std::stod((*fixed)[6]), 1.5 * std::stod((*isolated)[6]));
  // The mean row is the mean of the three records.
  const auto* mean = FindRow(rows, "thm2", "mean", "0.5");
  ASSERT_NE(mean, nullptr);
  double sum = 0.0;
  for (const char* record : {"fwn_firm_seed1", "fwn_soft_seed2", "pulse_tp2"}) {
    sum += std::stod((*FindRow(rows, "thm2", record, "0.5"))[5]);
  }
  EXPECT_NEAR(std::stod((*mean)[5]), sum / 3.0, 1e-12 * sum);
}

TEST(CompareCommand, MpiRanksWriteTheSameSummaryAsOneProcess) {
  // A machine without mpirun cannot run a study on ranks at all: a failure that says what to
  // install (scripts/setup.sh does), never a skip that counts as passed.
  ASSERT_TRUE(HaveMpirun()) << "mpirun not found: install Debian's openmpi-bin";
  const fs::path local = OutputFolder("mpi_local"), mpi = OutputFolder("mpi_2");
  ASSERT_EQ(RunIsolab("compare " + StudyData("small_study.yaml") + " -q -j 1 -o " + local.string())
                .exit_code,
            0);
  const Outcome two =
      RunShell(Mpirun(2) + " compare " + StudyData("small_study.yaml") + " -q -o " + mpi.string());
  ASSERT_EQ(two.exit_code, 0) << two.output;
  ExpectSameSummaries(local, mpi);
  ExpectSameRunFiles(local, mpi);
  EXPECT_NE(two.output.find("scale 0.5 (ratios to thm1)"), std::string::npos);
  EXPECT_EQ(two.output.find("scale 0.5", two.output.find("scale 0.5") + 1), std::string::npos)
      << "the table is printed once, by rank 0";

  // Failures too: the same rows and messages, and exit code 1 from every rank.
  const fs::path local_failing = OutputFolder("mpi_local_failing");
  const fs::path mpi_failing = OutputFolder("mpi_2_failing");
  EXPECT_EQ(
      RunIsolab("compare " + StudyData("failing_study.yaml") + " -q -o " + local_failing.string())
          .exit_code,
      1);
  EXPECT_EQ(RunShell(Mpirun(2) + " compare " + StudyData("failing_study.yaml") + " -q -o " +
                     mpi_failing.string())
                .exit_code,
            1);
  ExpectSameSummaries(local_failing, mpi_failing);
}

TEST(CompareCommand, FailedRunsAreReportedAndTheOthersFinish) {
  const fs::path folder = OutputFolder("failing");
  const Outcome run =
      RunIsolab("compare " + StudyData("failing_study.yaml") + " -q -o " + folder.string());
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.output.find("4 of 6 runs failed"), std::string::npos) << run.output;
  const auto rows = CsvRows(folder / "summary.csv");
  const auto status = [&](const char* variant, const char* record) {
    const auto* row = FindRow(rows, variant, record, "1");
    return row != nullptr ? (*row)[3] : std::string("absent");
  };
  EXPECT_EQ(status("thm1", "pulse_tp2"), "completed");
  EXPECT_EQ(status("fixed", "pulse_tp2"), "completed");
  EXPECT_EQ(status("stuck", "pulse_tp2"), "failed");
  for (const char* variant : {"thm1", "stuck", "fixed"}) {
    EXPECT_EQ(status(variant, "bad_record_nan"), "failed") << variant;
    EXPECT_EQ(status(variant, "mean"), std::string(variant) == "stuck" ? "failed" : "partial");
  }
  const std::string csv = ReadText(folder / "summary.csv");
  EXPECT_NE(csv.find("\"Newton did not converge at t = 2.01"), std::string::npos) << csv;
  EXPECT_NE(csv.find("bad_record_nan.at2:6: 'nan' is not a finite number"), std::string::npos);
  // The run that stopped early keeps its results up to there, as `isolab run` does.
  EXPECT_TRUE(fs::exists(folder / "runs/stuck/pulse_tp2_x1.h5"));
  EXPECT_FALSE(fs::exists(folder / "runs/thm1/bad_record_nan_x1.h5"));
  EXPECT_TRUE(fs::exists(folder / "summary.h5"));
}

TEST(CompareCommand, RecordEntriesGiveScaleAndUnitsAndAConflictFailsItsRuns) {
  const fs::path folder = OutputFolder("entries");
  const Outcome run =
      RunIsolab("compare " + StudyData("record_entries_study.yaml") + " -q -o " + folder.string());
  EXPECT_EQ(run.exit_code, 1);  // the run whose units disagree failed; the others finished
  const auto rows = CsvRows(folder / "summary.csv");
  const auto& header = rows[0];
  const auto column = [&](const char* name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  const auto* pulse = FindRow(rows, "thm1", "pulse_tp2", "0.5");
  const auto* gal = FindRow(rows, "thm1", "pulse_tp2_gal", "0.5");
  const auto* fwn = FindRow(rows, "thm1", "fwn_firm_seed1", "0.5");
  ASSERT_TRUE(pulse != nullptr && gal != nullptr && fwn != nullptr);
  const auto run_json = [&](const std::string& record, const char* scale) {
    const Outcome single =
        RunIsolab("run " + StudyData("small_building.yaml") + " --record " + record + " --scale " +
                  scale + " --json -o " + (folder / "run.h5").string());
    EXPECT_EQ(single.exit_code, 0);
    return nlohmann::json::parse(single.output);
  };
  // The entry's scale 2 times the study's 0.5: pulse_tp2 at 1.
  const auto full = run_json(Source("ground_motions/pulse_tp2.at2"), "1");
  EXPECT_EQ(std::stod((*pulse)[4]), full["peaks"]["isolator_displacement"]["value"].get<double>());
  EXPECT_EQ(std::stod((*pulse)[column("pga_g")]), full["pga_g"].get<double>());
  EXPECT_EQ((*pulse)[column("record_units")], "g");
  // The same motion stored in cm/s^2, read by its header: pulse_tp2 at 0.5.
  const auto half = run_json(Source("ground_motions/pulse_tp2.at2"), "0.5");
  const double expected = half["peaks"]["isolator_displacement"]["value"].get<double>();
  EXPECT_NEAR(std::stod((*gal)[4]), expected, 1e-8 * expected);
  EXPECT_EQ((*gal)[column("record_units")], "cm/s^2");
  // Units that disagree with the record's header: refused, naming both, the run failed.
  EXPECT_EQ((*fwn)[3], "failed");
  const std::string csv = ReadText(folder / "summary.csv");
  EXPECT_NE(csv.find("fwn_firm_seed1.at2: its header gives the units as g but "), std::string::npos)
      << csv;
  EXPECT_NE(csv.find("records[2].units gives gal"), std::string::npos) << csv;
}

// "[k/6] <variant> / <record> x1 ... 0.123 s" or "... failed: <why>", for the failing study.
bool IsProgressLine(const std::string& line) {
  const bool counted = line.size() > 6 && line[0] == '[' && line[1] >= '1' && line[1] <= '6' &&
                       line.compare(2, 4, "/6] ") == 0;
  if (!counted) return false;
  const std::string rest = line.substr(6);
  bool known_run = false;
  for (const char* variant : {"thm1", "stuck", "fixed"}) {
    for (const char* record : {"pulse_tp2", "bad_record_nan"}) {
      known_run =
          known_run || rest.rfind(std::string(variant) + " / " + record + " x1 ... ", 0) == 0;
    }
  }
  if (!known_run) return false;
  const std::string outcome = rest.substr(rest.find(" ... ") + 5);
  if (outcome.rfind("failed: ", 0) == 0) return outcome.size() > 8;
  // "d+.ddd s"
  const std::size_t point = outcome.find('.');
  return point != std::string::npos && point > 0 && outcome.size() == point + 6 &&
         outcome.compare(point + 4, 2, " s") == 0 &&
         std::all_of(outcome.begin(), outcome.begin() + point, ::isdigit) &&
         std::all_of(outcome.begin() + point + 1, outcome.begin() + point + 4, ::isdigit);
}

TEST(CompareCommand, ProgressGoesToStderrUnlessQuiet) {
  const fs::path folder = OutputFolder("progress");
  const Outcome loud =
      RunIsolab("compare " + StudyData("failing_study.yaml") + " -j 2 -o " + folder.string(), true);
  std::istringstream lines(loud.output);
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line, "isolab compare: 6 runs (3 variants x 2 records x 1 scale) on 2 processes");
  int progress = 0;
  while (std::getline(lines, line) && line.rfind("[", 0) == 0) {
    EXPECT_TRUE(IsProgressLine(line)) << line;
    ++progress;
  }
  EXPECT_EQ(progress, 6);
  EXPECT_EQ(line.rfind("6 runs in ", 0), 0u) << line;
  EXPECT_NE(line.find(" on 2 processes: "), std::string::npos) << line;
  EXPECT_NE(line.find("runs/s; 4 failed"), std::string::npos) << line;
  std::getline(lines, line);
  EXPECT_EQ(line.rfind("waiting on one another: ", 0), 0u) << line;
  EXPECT_NE(line.find(" % of the jobs' time"), std::string::npos) << line;
  std::getline(lines, line);
  EXPECT_EQ(line.rfind("per-run files (full): ", 0), 0u) << line;

  const Outcome quiet =
      RunIsolab("compare " + StudyData("failing_study.yaml") + " -q -o " + folder.string(), true);
  EXPECT_EQ(quiet.output, "");
}

TEST(CompareCommand, BadStudyExitsTwoWithItsLocation) {
  const fs::path folder = OutputFolder("bad");
  const std::string expected =
      StudyData("bad_study_key.yaml") + ":5:1: refrence: unknown key (did you mean 'reference'?)";
  const Outcome run =
      RunIsolab("compare " + StudyData("bad_study_key.yaml") + " -o " + folder.string(), true);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.output.find(expected), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(folder));
  ASSERT_TRUE(HaveMpirun()) << "mpirun not found: install Debian's openmpi-bin";
  // Every rank finds the error; the message appears once.
  const Outcome mpi = RunShell(
      Mpirun(2) + " compare " + StudyData("bad_study_key.yaml") + " -o " + folder.string(), true);
  EXPECT_NE(mpi.exit_code, 0);
  const std::size_t first = mpi.output.find(expected);
  EXPECT_NE(first, std::string::npos) << mpi.output;
  EXPECT_EQ(mpi.output.find(expected, first + 1), std::string::npos) << mpi.output;
}

// small_study's building fixes the run's duration: a free vibration cannot follow its records.
// Refused before any run, the output folder not made; a study whose runs fail says so per run.
TEST(CompareCommand, AFreeVibrationARunOfFixedDurationCannotTakeIsRefused) {
  const fs::path folder = OutputFolder("fixed_duration");
  const Outcome run = RunIsolab(
      "compare " + StudyData("small_study.yaml") + " --free-vibration 3 -o " + folder.string(),
      true);
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("--free-vibration: variant 'thm1' fixes the run's duration "
                            "(analysis.duration in "),
            std::string::npos)
      << run.output;
  EXPECT_FALSE(fs::exists(folder));

  // A free vibration too long for the step limit fails each run, naming the option; a study
  // has no --max-steps to raise the limit with, so none is offered.
  const fs::path study = OutputFolder("long_free_vibration.yaml");
  std::ofstream(study) << "building: " << StudyData("two_story_lrb.yaml")
                       << "\nvariants: [{name: lrb}]\nrecords: ["
                       << Source("ground_motions/pulse_tp2.at2") << "]\nscales: [1]\n";
  const fs::path long_folder = OutputFolder("long_free_vibration");
  const Outcome long_run = RunIsolab("compare " + study.string() +
                                     " -q --free-vibration 1e308 -o " + long_folder.string());
  EXPECT_EQ(long_run.exit_code, 1) << long_run.output;
  const std::string csv = ReadText(long_folder / "summary.csv");
  EXPECT_NE(csv.find("choose a larger dt or a shorter duration"), std::string::npos) << csv;
  EXPECT_EQ(csv.find("--max-steps"), std::string::npos) << csv;
}

// -j 1000000 would start a million workers; refused before the study is read.
TEST(CompareCommand, FarMoreWorkersThanTheHardwareAreRefused) {
  const fs::path folder = OutputFolder("too_many_workers");
  const Outcome run = RunIsolab(
      "compare " + StudyData("small_study.yaml") + " -q -j 1000000 -o " + folder.string(), true);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.output.rfind("isolab: --jobs: 1000000 workers on ", 0), 0u) << run.output;
  EXPECT_FALSE(fs::exists(folder));
}

// The bar charts show the summary's numbers: each panel's tallest bar is the largest "max" over
// the variants at its scale, on an axis that names the quantity and its unit.
TEST(CompareCommand, PlotWritesBarCharts) {
  ASSERT_EQ(RunShell("/usr/bin/python3 -c 'import matplotlib, h5py'").exit_code, 0)
      << "/usr/bin/python3 cannot import matplotlib and h5py: install Debian's "
         "python3-matplotlib and python3-h5py (scripts/setup.sh does)";
  const fs::path folder = OutputFolder("plot");
  const Outcome run =
      RunIsolab("compare " + StudyData("failing_study.yaml") + " -q --plot -o " + folder.string());
  EXPECT_EQ(run.exit_code, 1);  // the study's failed runs, not the plot
  for (const char* name : {"study_overview", "study_isolator_displacement", "study_base_shear",
                           "study_floor_acceleration"}) {
    EXPECT_GT(fs::file_size(folder / "plots" / (std::string(name) + ".png")), 10000u) << name;
    EXPECT_TRUE(fs::exists(folder / "plots" / (std::string(name) + ".pdf"))) << name;
  }
  // The CSV reads the same way; --metadata says what each panel shows.
  EXPECT_EQ(RunShell(Source("scripts/plot_study.py") + " " + (folder / "summary.csv").string() +
                     " --metadata -o " + (folder / "csv_plots").string())
                .exit_code,
            0);
  const auto rows = CsvRows(folder / "summary.csv");
  const std::vector<std::string>& header = rows.front();
  for (const std::string key : {"isolator_displacement", "base_shear", "floor_acceleration"}) {
    const auto column = std::find_if(header.begin(), header.end(), [&](const std::string& name) {
      return name.rfind(key + " [", 0) == 0;
    });
    ASSERT_NE(column, header.end()) << key;
    const std::size_t c = column - header.begin();
    double largest = 0.0;
    for (const auto& row : rows) {
      if (row.size() > c && row[1] == "max" && !row[c].empty()) {
        largest = std::max(largest, std::stod(row[c]));
      }
    }
    std::ifstream in(folder / "csv_plots" / ("study_" + key + ".json"));
    const nlohmann::json sidecar = nlohmann::json::parse(in);
    ASSERT_EQ(sidecar["axes"].size(), 1u) << key;  // one scale
    const nlohmann::json& axis = sidecar["axes"][0];
    const std::string unit = column->substr(key.size() + 2, column->size() - key.size() - 3);
    EXPECT_EQ(axis["y_unit"], unit) << key << ": " << axis["ylabel"];
    EXPECT_NE(axis["ylabel"].get<std::string>().find("peak"), std::string::npos) << key;
    EXPECT_NEAR(axis["y_range"][1].get<double>(), largest, 1e-12 * largest) << key;
  }
}

}  // namespace

// A run that blows up (a negative-stiffness isolation layer, 4.4 m in 4 s) is a failed run, not a
// "completed" one in its variant's means: its message says why, and the means it would have
// entered are marked failed with no numbers.
TEST(CompareCommand, ABlownUpRunFailsAndStaysOutOfTheMeans) {
  const fs::path folder = OutputFolder("blow_up");
  const Outcome run =
      RunIsolab("compare " + StudyData("blow_up_study.yaml") + " -q -o " + folder.string());
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.output.find("1 of 2 runs failed"), std::string::npos) << run.output;
  const auto rows = CsvRows(folder / "summary.csv");
  const auto* blown = FindRow(rows, "softening", "pulse_tp2", "1");
  ASSERT_NE(blown, nullptr);
  EXPECT_EQ((*blown)[3], "failed");
  EXPECT_EQ((*blown)[4], "");  // no peak isolator displacement from a divergent run
  const auto* mean = FindRow(rows, "softening", "mean", "1");
  ASSERT_NE(mean, nullptr);
  EXPECT_EQ((*mean)[3], "failed");
  EXPECT_EQ((*mean)[4], "");
  const auto* reference = FindRow(rows, "thm1", "mean", "1");
  ASSERT_NE(reference, nullptr);
  EXPECT_EQ((*reference)[3], "completed");
  EXPECT_NE(ReadText(folder / "summary.csv").find("blow-up at t = "), std::string::npos);
}
