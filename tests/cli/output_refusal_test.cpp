// Every command refuses, with exit code 2 and before any work, an output that is one of its
// inputs (by identity: the same name, another spelling, a hard link, an included file) or that
// it cannot write; the input is left byte for byte as it was, and nothing new appears.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "cli/run_isolab.h"
#include "own_test_file.h"

namespace {

namespace fs = std::filesystem;
using isolab::testing::RunCommandLine;
using isolab::testing::RunIsolab;

const std::string kSource = ISOLAB_SOURCE_DIR;

// A folder of this test alone, holding a model that runs the bundled pulse record.
fs::path FreshFolder() {
  const fs::path folder = isolab::testing::FreshTestDirectory();
  fs::copy_file(kSource + "/ground_motions/pulse_tp2.at2", folder / "rec.at2");
  std::ofstream(folder / "iso.yaml")
      << "units: {force: kN, length: mm, time: s}\n"
         "isolation:\n  components:\n"
         "    - {name: bearing, type: thm1, k0: 1.0, k1: 0.2, k2: 0.45, uy: 20, uyh: 120}\n";
  std::ofstream(folder / "m.yaml") << "units: {force: kN, length: mm, time: s}\n"
                                      "structure: {type: sdof, mass: 31.7 t, damping: {ratio: "
                                      "0.02}}\n"
                                      "isolation: {file: iso.yaml}\n"
                                      "excitation:\n  ground_motion: {file: rec.at2}\n"
                                      "analysis: {dt: 0.01}\n";
  return folder;
}

std::string Read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::set<std::string> Listing(const fs::path& folder) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) {
    names.insert(entry.path().filename().string());
  }
  return names;
}

// Runs `arguments` in `folder`; expects exit 2 with `message` on stderr, and the folder as it
// was (every file's bytes).
void ExpectRefused(const fs::path& folder, const std::string& arguments,
                   const std::string& message) {
  std::map<std::string, std::string> before;
  for (const std::string& name : Listing(folder)) before[name] = Read(folder / name);
  const auto run = RunCommandLine("cd " + folder.string() + " && " + ISOLAB_BINARY + " " +
                                  arguments + " 2>&1 >/dev/null");
  EXPECT_EQ(run.exit_code, 2) << arguments << "\n" << run.output;
  EXPECT_NE(run.output.find(message), std::string::npos) << arguments << "\n" << run.output;
  std::map<std::string, std::string> after;
  for (const std::string& name : Listing(folder)) after[name] = Read(folder / name);
  EXPECT_TRUE(before == after) << arguments << ": the folder changed";
}

TEST(OutputRefusal, RunRefusesTheModelItsRecordAndItsIncludedFile) {
  const fs::path folder = FreshFolder();
  // A run model as output cannot even be a results file (.yaml); the identity is checked too.
  fs::create_hard_link(folder / "m.yaml", folder / "m_link.h5");
  fs::create_hard_link(folder / "rec.at2", folder / "rec_link.csv");
  fs::create_hard_link(folder / "iso.yaml", folder / "iso_link.h5");
  ExpectRefused(folder, "run m.yaml -o m_link.h5", "is the input file 'm.yaml' under another name");
  ExpectRefused(folder, "run ./m.yaml -o ./m_link.h5", "under another name");
  ExpectRefused(folder, "run m.yaml -o rec_link.csv", "rec.at2' under another name");
  ExpectRefused(folder, "run m.yaml --record rec_link.csv -o rec_link.csv",
                "is an input of this command");
  ExpectRefused(folder, "run m.yaml -o iso_link.h5", "iso.yaml' under another name");
  // And a run that is not refused writes its results beside them.
  const auto run = RunCommandLine("cd " + folder.string() + " && " + ISOLAB_BINARY +
                                  " run m.yaml -o m.h5 --json > /dev/null 2>&1");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_TRUE(fs::exists(folder / "m.h5"));
}

// /dev/zero as a model or a record was read without end (memory growing ~170 MB/s).
TEST(OutputRefusal, InputsThatAreNotRegularFilesAreRefusedBeforeReading) {
  const fs::path folder = FreshFolder();
  ExpectRefused(folder, "run /dev/zero -o m.h5", "/dev/zero: is not a regular file");
  ExpectRefused(folder, "run m.yaml --record /dev/zero -o m.h5",
                "/dev/zero: is not a regular file");
  ExpectRefused(folder, "spectrum /dev/zero -o s.csv", "/dev/zero: is not a regular file");
}

// A plan model's vertical record is an input as much as its horizontal pair: `-o` naming it once
// replaced the record with the results and exited 0.
TEST(OutputRefusal, RunRefusesTheModelsVerticalRecord) {
  const fs::path folder = FreshFolder();
  fs::copy_file(kSource + "/ground_motions/v_fwn_firm_seed4.at2", folder / "v.csv");
  std::string plan = Read(kSource + "/models/plan/five_story_fp_plan.yaml");
  const std::string vertical = "../../ground_motions/v_fwn_firm_seed4.at2";
  ASSERT_NE(plan.find(vertical), std::string::npos);
  plan.replace(plan.find(vertical), vertical.size(), "v.csv");
  for (std::size_t at; (at = plan.find("../../ground_motions/")) != std::string::npos;) {
    plan.replace(at, 6, kSource + "/");
  }
  std::ofstream(folder / "plan.yaml") << plan;
  ExpectRefused(folder, "run plan.yaml -q --summary-only -o v.csv", "is an input of this command");
}

// A named pipe as a model, study, design or displacement path: opening it waited for a writer
// for ever. Each is refused before it is opened (a timeout bounds the test if one is not).
TEST(OutputRefusal, PipesAreRefusedNotWaitedOn) {
  const fs::path folder = FreshFolder();
  for (const char* name : {"pipe.yaml", "pipe.csv"}) {
    ASSERT_EQ(mkfifo((folder / name).c_str(), 0600), 0) << name;
  }
  for (const char* arguments :
       {"compare pipe.yaml -o out", "design pipe.yaml -o out", "bounds pipe.yaml -o out",
        "cyclic pipe.yaml -a 10 -T 1", "cyclic iso.yaml --path pipe.csv"}) {
    const auto run = RunCommandLine("cd " + folder.string() + " && timeout 20 " + ISOLAB_BINARY +
                                    " " + std::string(arguments) + " 2>&1 >/dev/null");
    EXPECT_EQ(run.exit_code, 2) << arguments << "\n" << run.output;
    EXPECT_NE(run.output.find("is not a regular file"), std::string::npos) << arguments << "\n"
                                                                           << run.output;
    EXPECT_FALSE(fs::exists(folder / "out")) << arguments;
  }
}

// A displacement path is read a line at a time up to the limit every text input has: a file of
// one endless line once grew to gigabytes before anything was said.
TEST(OutputRefusal, ADisplacementPathsOverlongLineIsRefusedAtItsLine) {
  const fs::path folder = FreshFolder();
  std::ofstream(folder / "long.csv") << "time,displacement\n" << std::string(100000, '1') << "\n";
  ExpectRefused(folder, "cyclic iso.yaml --path long.csv",
                "long.csv:2: a line of more than 65536 characters");
}

TEST(OutputRefusal, SpectrumRefusesItsRecordAndTwoNamesOfOneOutput) {
  const fs::path folder = FreshFolder();
  fs::create_hard_link(folder / "rec.at2", folder / "rec.csv");
  ExpectRefused(folder, "spectrum rec.at2 -o rec.csv", "is the input file 'rec.at2'");
  ExpectRefused(folder, "spectrum rec.at2 -o s.csv -o ./s.csv", "is also the output 's.csv'");
}

TEST(OutputRefusal, FitAndDiagnoseRefuseTheirDataAndSpecification) {
  const fs::path folder = FreshFolder();
  fs::copy_file(kSource + "/tests/cli/data/fit/three_laws_spec.yaml", folder / "spec.yaml");
  fs::copy_file(kSource + "/models/diagnosis/base_bhm2.yaml", folder / "base.model.yaml");
  std::ofstream(folder / "data.csv") << "test,time,displacement,force\n";
  ExpectRefused(folder, "fit data.csv --model spec.yaml -q -o data.csv",
                "is an input of this command");
  ExpectRefused(folder, "fit data.csv --model spec.yaml -q -o ./spec.yaml", "spec.yaml'");
  ExpectRefused(folder, "diagnose data.csv --base base.model.yaml -q --out base",
                "base.model.yaml: is an input of this command");
}

TEST(OutputRefusal, CyclicAndShakeTableRefuseTheirModelsAndCheckEveryOutputFirst) {
  const fs::path folder = FreshFolder();
  fs::create_hard_link(folder / "iso.yaml", folder / "iso.csv");
  ExpectRefused(folder, "cyclic iso.yaml -a 50 --test-data iso.csv", "is the input file");
  fs::copy_file(kSource + "/tests/cli/data/bncs/bncs_ica50_excerpt.csv", folder / "table.csv");
  fs::copy_file(kSource + "/models/bncs/bncs.yaml", folder / "bncs.yaml");
  fs::copy_file(kSource + "/models/bncs/bncs_bhm2.fitted.yaml", folder / "bncs_bhm2.fitted.yaml");
  ExpectRefused(folder, "shaketable table.csv --model bncs.yaml --isolator ./bncs_bhm2.fitted.yaml",
                "is the input file 'bncs_bhm2.fitted.yaml' under another name");
  ExpectRefused(folder, "shaketable table.csv --model bncs.yaml --isolator table.csv",
                "is an input of this command");
  // The results folder is missing: refused before the data are read or the prediction runs
  // (without -q, the progress lines would show either).
  const auto run = RunCommandLine("cd " + folder.string() + " && " + ISOLAB_BINARY +
                                  " shaketable table.csv --model bncs.yaml --predict --results "
                                  "missing/p.h5 2>&1 >/dev/null");
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("the folder 'missing' does not exist"), std::string::npos)
      << run.output;
  EXPECT_EQ(run.output.find("samples"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("predicting"), std::string::npos) << run.output;
}

// `-o ''` ran and wrote the default file (m.h5) as if no -o had been given; an empty value is
// refused for every option that takes one, before anything is read.
TEST(OutputRefusal, AnEmptyOutputNameIsRefused) {
  const fs::path folder = FreshFolder();
  std::ofstream(folder / "study.yaml") << "building: m.yaml\n";
  ExpectRefused(folder, "run m.yaml -o ''", "--output: an empty value");
  ExpectRefused(folder, "spectrum rec.at2 -o ''", "--output: an empty value");
  ExpectRefused(folder, "cyclic iso.yaml -a 50 --csv ''", "--csv: an empty value");
  ExpectRefused(folder, "synth noise -o ''", "--output: an empty value");
  ExpectRefused(folder, "compare study.yaml -o ''", "--output: an empty value");
}

// CLI11's range checks printed their bounds with %f: "Value 0 not in range 0.000000 to
// 1797693134862315708145274237317043567980705675354411..." (309 digits). Each range reads as the
// model reader writes one.
TEST(OutputRefusal, RangesOfOptionsAreSaidReadably) {
  const fs::path folder = FreshFolder();
  std::ofstream(folder / "study.yaml") << "building: m.yaml\n";
  std::ofstream(folder / "data.csv") << "test,time,displacement,force\n";
  std::ofstream(folder / "spec.yaml") << "units: {force: kN, length: mm, time: s}\n";
  ExpectRefused(folder, "run m.yaml --trial-displacement 0",
                "--trial-displacement: 0 (must be > 0)");
  ExpectRefused(folder, "run m.yaml --every 0", "--every: 0 (must be > 0)");
  ExpectRefused(folder, "run m.yaml --scale -1", "--scale: -1 (must be > 0)");
  ExpectRefused(folder, "run m.yaml --rtol 1", "--rtol: 1 (must be in [1e-14, 0.09])");
  ExpectRefused(folder, "run m.yaml --max-steps 0", "--max-steps: 0 (must be in [1, 2147483647])");
  ExpectRefused(folder, "cyclic iso.yaml -a 50 --noise 2 --test-data t.csv",
                "--noise: 2 (must be in [0, 1])");
  ExpectRefused(folder, "fit data.csv --model spec.yaml --budget 5",
                "--budget: 5 (must be in [100, 1000000000])");
  ExpectRefused(folder, "compare study.yaml -j 0", "--jobs: 0 (must be > 0)");
  for (const char* command : {"run m.yaml --trial-displacement 0", "run m.yaml --rtol 1"}) {
    const auto run =
        RunCommandLine("cd " + folder.string() + " && " + ISOLAB_BINARY + " " + command + " 2>&1");
    EXPECT_EQ(run.output.find("000000"), std::string::npos) << run.output;
  }
}

// `isolab run -q` was refused while compare, fit and diagnose took it: every command takes
// -q/--quiet, and run's leaves out the preamble before the peaks.
TEST(OutputRefusal, EveryCommandTakesQuiet) {
  const fs::path folder = FreshFolder();
  const auto quiet = RunCommandLine("cd " + folder.string() + " && " + ISOLAB_BINARY +
                                    " run m.yaml -q -o m.h5 2>&1");
  EXPECT_EQ(quiet.exit_code, 0) << quiet.output;
  EXPECT_EQ(quiet.output.find("record:"), std::string::npos) << quiet.output;
  EXPECT_EQ(quiet.output.find("model:"), std::string::npos) << quiet.output;
  EXPECT_NE(quiet.output.find("peak isolator displacement"), std::string::npos) << quiet.output;
  const auto loud =
      RunCommandLine("cd " + folder.string() + " && " + ISOLAB_BINARY + " run m.yaml -o m.h5 2>&1");
  EXPECT_NE(loud.output.find("record:"), std::string::npos) << loud.output;
  for (const char* command :
       {"cyclic iso.yaml -a 50 -q", "synth noise -q -o n.at2", "spectrum rec.at2 -q -o s.csv",
        "run m.yaml --quiet -o m2.h5", "cyclic iso.yaml -a 50 --quiet"}) {
    const auto run =
        RunCommandLine("cd " + folder.string() + " && " + ISOLAB_BINARY + " " + command + " 2>&1");
    EXPECT_EQ(run.exit_code, 0) << command << "\n" << run.output;
  }
  const auto cyclic = RunCommandLine("cd " + folder.string() + " && " + ISOLAB_BINARY +
                                     " cyclic iso.yaml -a 50 -q 2>&1");
  EXPECT_EQ(cyclic.output.find("mathematical"), std::string::npos) << cyclic.output;  // no table
  EXPECT_NE(cyclic.output.find("W_d"), std::string::npos) << cyclic.output;
}

}  // namespace
