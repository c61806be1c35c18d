// --plot end to end: `isolab run` on bundled models and `isolab spectrum` on a bundled record
// write their PNGs through scripts/plot_result.py and scripts/plot_spectrum.py; a missing Python
// stops the command before it computes or writes anything, saying what to install. Skips when
// Debian's /usr/bin/python3 cannot import matplotlib and h5py.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli/run_isolab.h"
#include "own_test_file.h"

namespace {

using isolab::testing::RunIsolab;

std::string Source(const std::string& relative) {
  return std::string(ISOLAB_SOURCE_DIR) + "/" + relative;
}

std::filesystem::path FreshDirectory(const std::string& name) {
  const auto directory = isolab::testing::OwnTestDirectory() / name;
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  return directory;
}

bool PlottingAvailable() {
  return std::system("/usr/bin/python3 -c 'import matplotlib, h5py' >/dev/null 2>&1") == 0;
}

#define REQUIRE_PLOTTING()                                                                 \
  if (!PlottingAvailable()) {                                                              \
    GTEST_SKIP() << "/usr/bin/python3 cannot import matplotlib and h5py (Debian packages " \
                 << "python3-matplotlib, python3-h5py)";                                   \
  }

// A PNG file: its signature and more than a header's worth of bytes.
void ExpectPng(const std::filesystem::path& path) {
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  EXPECT_GT(std::filesystem::file_size(path), 2000u) << path;
  std::ifstream in(path, std::ios::binary);
  char signature[8] = {};
  in.read(signature, 8);
  EXPECT_EQ(std::string(signature + 1, 3), "PNG") << path;
}

TEST(PlotScript, IsolatedBuildingRunWritesEveryPlot) {
  REQUIRE_PLOTTING();
  const auto directory = FreshDirectory("building");
  const auto result = directory / "five_story.h5";
  const auto run =
      RunIsolab("run " + Source("models/buildings/five_story_table9.yaml") + " --json -o " +
                result.string() + " --plot=" + (directory / "plots").string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_EQ(run.output.front(), '{');  // the script's messages stay off stdout
  for (const char* name : {"overview", "hysteresis", "histories", "envelopes", "energy"}) {
    ExpectPng(directory / "plots" / (std::string("five_story_") + name + ".png"));
  }
}

TEST(PlotScript, SdofRunPlotsBesideItsResult) {
  REQUIRE_PLOTTING();
  const auto directory = FreshDirectory("sdof");
  const auto result = directory / "sdof.h5";
  const auto run = RunIsolab("run " + std::string(ISOLAB_TEST_DATA_DIR) +
                             "/cli/data/run_base.yaml -o " + result.string() + " --plot");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  for (const char* name : {"hysteresis", "histories", "energy"}) {
    ExpectPng(directory / (std::string("sdof_") + name + ".png"));
  }
  EXPECT_FALSE(std::filesystem::exists(directory / "sdof_envelopes.png"));  // no stories
}

TEST(PlotScript, SpectrumPlotsFromCsvAndHdf5) {
  REQUIRE_PLOTTING();
  const auto directory = FreshDirectory("spectrum");
  for (const char* extension : {".csv", ".h5"}) {
    const auto output = directory / (std::string("fwn") + extension);
    const auto run = RunIsolab("spectrum " + Source("ground_motions/fwn_firm_seed1.at2") +
                               " --periods 0.1:2:0.1 --damping 0.02,0.05 --ductility 2,4 -q -o " +
                               output.string() + " --plot=" + (directory / extension).string());
    ASSERT_EQ(run.exit_code, 0) << run.output;
    for (const char* name : {"D", "A", "strength"}) {
      ExpectPng(directory / extension / (std::string("fwn_") + name + ".png"));
    }
  }
}

TEST(PlotScript, PairSpectrumPlotsFromCsvAndHdf5) {
  REQUIRE_PLOTTING();
  const auto directory = FreshDirectory("pair_spectrum");
  for (const char* extension : {".csv", ".h5"}) {
    const auto output = directory / (std::string("pair") + extension);
    const auto run =
        RunIsolab("spectrum " + Source("ground_motions/fwn_firm_seed1.at2") + " " +
                  Source("ground_motions/h2_fwn_firm_seed3.at2") + " --periods 0.1:2:0.1 -q -o " +
                  output.string() + " --plot=" + (directory / extension).string());
    ASSERT_EQ(run.exit_code, 0) << run.output;
    for (const char* name : {"D", "A"}) {
      ExpectPng(directory / extension / (std::string("pair_") + name + ".png"));
    }
  }
}

TEST(PlotScript, PlotDoesNotTakeTheNextArgument) {
  // `--plot MODEL` once read MODEL as the plot folder; --plot takes a folder only as --plot=DIR.
  REQUIRE_PLOTTING();
  const auto directory = FreshDirectory("next_argument");
  const auto result = directory / "sdof.h5";
  const auto run = RunIsolab("run --plot " + std::string(ISOLAB_TEST_DATA_DIR) +
                             "/cli/data/run_base.yaml -o " + result.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  ExpectPng(directory / "sdof_hysteresis.png");
}

TEST(PlotScript, IsolabPythonMayBeANameOnThePath) {
  // ISOLAB_PYTHON=<name> is looked up on PATH, as a shell would.
  REQUIRE_PLOTTING();
  const auto directory = FreshDirectory("python_by_name");
  std::filesystem::create_directories(directory / "bin");
  std::filesystem::create_symlink("/usr/bin/python3", directory / "bin" / "isolab-test-python");
  const auto result = directory / "sdof.h5";
  const auto run = isolab::testing::RunCommandLine(
      "PATH=" + (directory / "bin").string() + ":$PATH ISOLAB_PYTHON=isolab-test-python " +
      ISOLAB_BINARY + " run " + std::string(ISOLAB_TEST_DATA_DIR) + "/cli/data/run_base.yaml -o " +
      result.string() + " --plot 2>&1");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  ExpectPng(directory / "sdof_energy.png");
}

TEST(PlotScript, MissingPythonStopsBeforeTheRun) {
  const auto directory = FreshDirectory("missing");
  const auto result = directory / "never.h5";
  setenv("ISOLAB_PYTHON", "/nonexistent/python3", 1);
  const auto run = RunIsolab("run " + std::string(ISOLAB_TEST_DATA_DIR) +
                                 "/cli/data/run_base.yaml -o " + result.string() + " --plot",
                             true);
  const auto spectrum = RunIsolab("spectrum " + Source("ground_motions/fwn_firm_seed1.at2") +
                                      " -o " + (directory / "never.csv").string() + " --plot",
                                  true);
  unsetenv("ISOLAB_PYTHON");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.output.find("cannot run /nonexistent/python3"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("python3-matplotlib"), std::string::npos) << run.output;
  EXPECT_FALSE(std::filesystem::exists(result));
  EXPECT_EQ(spectrum.exit_code, 2);
  EXPECT_FALSE(std::filesystem::exists(directory / "never.csv"));
}

TEST(PlotScript, PythonWithoutMatplotlibIsNamedWithThePackages) {
  // Debian's Python without its site packages (-S) has no matplotlib: the script's import check
  // says so, and isolab passes that on before running anything.
  const auto directory = FreshDirectory("no_matplotlib");
  const auto python = directory / "python_without_site";
  {
    std::ofstream script(python);
    script << "#!/bin/sh\nexec /usr/bin/python3 -S \"$@\"\n";
  }
  std::filesystem::permissions(python, std::filesystem::perms::owner_all);
  setenv("ISOLAB_PYTHON", python.c_str(), 1);
  const auto result = directory / "never.h5";
  const auto run = RunIsolab("run " + std::string(ISOLAB_TEST_DATA_DIR) +
                                 "/cli/data/run_base.yaml -o " + result.string() + " --plot",
                             true);
  unsetenv("ISOLAB_PYTHON");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.output.find("No module named"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("python3-matplotlib"), std::string::npos) << run.output;
  EXPECT_FALSE(std::filesystem::exists(result));
}

}  // namespace
