// --plot end to end: `isolab run` on bundled models and `isolab spectrum` on a bundled record
// write their figures (300 dpi PNG, vector PDF) through scripts/plot_result.py and
// scripts/plot_spectrum.py; what the figures show is checked through the scripts' --metadata
// sidecars against the run's and the spectrum's own numbers: each axis's quantity and unit
// (accelerations in g) and the range of the data drawn. A missing Python stops the command
// before it computes or writes anything, saying what to install. Debian's /usr/bin/python3
// without matplotlib and h5py is a failure naming the packages (scripts/setup.sh installs them):
// a skipped test would pass on a machine that cannot plot at all.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
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

#define REQUIRE_PLOTTING()                                                                  \
  if (!PlottingAvailable()) {                                                               \
    GTEST_FAIL() << "/usr/bin/python3 cannot import matplotlib and h5py: install Debian's " \
                 << "python3-matplotlib and python3-h5py (scripts/setup.sh does)";          \
  }

// A PNG's width and height in pixels (its IHDR chunk, big-endian), {0, 0} if it is none.
std::pair<unsigned, unsigned> PngSize(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char header[24] = {};
  in.read(reinterpret_cast<char*>(header), sizeof header);
  if (!in || std::string(reinterpret_cast<char*>(header) + 1, 3) != "PNG") return {0, 0};
  const auto word = [&](int at) {
    return (unsigned(header[at]) << 24) | (unsigned(header[at + 1]) << 16) |
           (unsigned(header[at + 2]) << 8) | unsigned(header[at + 3]);
  };
  return {word(16), word(20)};
}

// A figure for a report: a PNG of print resolution (a 300 dpi figure a few inches wide: more than
// 1000 pixels each way; the drafts were 396 x 330) and a PDF beside it.
void ExpectFigure(const std::filesystem::path& png) {
  ASSERT_TRUE(std::filesystem::exists(png)) << png;
  const auto [width, height] = PngSize(png);
  EXPECT_GT(width, 1000u) << png;
  EXPECT_GT(height, 800u) << png;
  auto pdf = png;
  pdf.replace_extension(".pdf");
  ASSERT_TRUE(std::filesystem::exists(pdf)) << pdf;
  std::ifstream in(pdf, std::ios::binary);
  char signature[5] = {};
  in.read(signature, 5);
  EXPECT_EQ(std::string(signature, 5), "%PDF-") << pdf;
}

// A figure's sidecar (plot_common.py's --metadata), checked against its PNG's own size.
nlohmann::json Sidecar(const std::filesystem::path& png) {
  auto path = png;
  path.replace_extension(".json");
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << path;
  const nlohmann::json sidecar = nlohmann::json::parse(in, nullptr, false);
  EXPECT_FALSE(sidecar.is_discarded()) << path;
  const auto [width, height] = PngSize(png);
  EXPECT_EQ(sidecar["dpi"], 300) << path;
  EXPECT_EQ(sidecar["size_px"], nlohmann::json::array({width, height})) << path;
  return sidecar;
}

// The largest absolute value of an axis's data range.
double Extent(const nlohmann::json& range) {
  return std::max(std::abs(range[0].get<double>()), std::abs(range[1].get<double>()));
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
    ExpectFigure(directory / "plots" / (std::string("five_story_") + name + ".png"));
  }
}

// What the figures show, against the run's own peaks (every step is written, so the histories
// drawn reach them): the loop spans the peak isolator displacement and force, the histories give
// the accelerations in g (peak / 9806.65 mm/s^2), every axis names its quantity and unit, and
// the title names the model and the record in full.
TEST(PlotScript, FiguresShowTheRunsNumbersWithTheirUnits) {
  REQUIRE_PLOTTING();
  const auto directory = FreshDirectory("content");
  const auto result = directory / "five_story.h5";
  const auto run = RunIsolab("run " + Source("models/buildings/five_story_table9.yaml") +
                             " --json -o " + result.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json peaks = nlohmann::json::parse(run.output)["peaks"];
  const auto plot = isolab::testing::RunCommandLine(
      "/usr/bin/python3 " + Source("scripts/plot_result.py") + " " + result.string() +
      " --metadata -q -o " + (directory / "plots").string() + " 2>&1");
  ASSERT_EQ(plot.exit_code, 0) << plot.output;
  const auto figure = [&](const char* name) {
    const auto png = directory / "plots" / (std::string("five_story_") + name + ".png");
    ExpectFigure(png);
    return Sidecar(png);
  };
  const double peak_u = peaks["isolator_displacement"]["value"].get<double>();
  const double peak_f = peaks["isolator_force"]["value"].get<double>();
  const double peak_roof_g = peaks["roof_absolute_acceleration"]["value"].get<double>() / 9806.65;

  const nlohmann::json hysteresis = figure("hysteresis");
  EXPECT_NE(hysteresis["title"].get<std::string>().find(
                "five_story_table9.yaml under fwn_firm_seed1.at2"),
            std::string::npos)
      << hysteresis["title"];
  ASSERT_EQ(hysteresis["axes"].size(), 10u);  // the total and nine components
  const nlohmann::json& total = hysteresis["axes"][0];
  EXPECT_EQ(total["xlabel"], "isolator displacement [mm]");
  EXPECT_EQ(total["ylabel"], "force [kN]");
  EXPECT_NEAR(Extent(total["x_range"]), peak_u, 1e-9 * peak_u);
  EXPECT_NEAR(Extent(total["y_range"]), peak_f, 1e-9 * peak_f);

  const nlohmann::json histories = figure("histories");
  ASSERT_EQ(histories["axes"].size(), 4u);  // base and roof: displacement, acceleration
  const nlohmann::json& roof_acceleration = histories["axes"][3];
  EXPECT_EQ(roof_acceleration["y_unit"], "g");
  EXPECT_EQ(roof_acceleration["x_unit"], "s");
  EXPECT_NEAR(Extent(roof_acceleration["y_range"]), peak_roof_g, 1e-9 * peak_roof_g);
  EXPECT_NEAR(Extent(histories["axes"][0]["y_range"]), peak_u, 1e-9 * peak_u);

  const nlohmann::json envelopes = figure("envelopes");
  ASSERT_EQ(envelopes["axes"].size(), 4u);
  // The peak absolute acceleration over height: the roof's among the levels', in g.
  EXPECT_EQ(envelopes["axes"][2]["x_unit"], "g");
  EXPECT_GE(envelopes["axes"][2]["x_range"][1].get<double>(), peak_roof_g * (1 - 1e-9));
  EXPECT_LT(envelopes["axes"][2]["x_range"][1].get<double>(), 2 * peak_roof_g);

  for (const char* name : {"overview", "hysteresis", "histories", "envelopes", "energy"}) {
    for (const nlohmann::json& axis : figure(name)["axes"]) {
      EXPECT_FALSE(axis["x_unit"].get<std::string>().empty()) << name << ": " << axis["xlabel"];
      if (axis["ylabel"] != "level") {
        EXPECT_FALSE(axis["y_unit"].get<std::string>().empty()) << name << ": " << axis["ylabel"];
      }
    }
  }
}

// A plan model's figures: the isolators' orbits and resultant displacement span the run's peak
// resultant isolator displacement, the rotations axis (in mrad) its peak floor rotation, and the
// hysteresis is drawn along x and along y.
TEST(PlotScript, PlanRunShowsOrbitsResultantsAndRotations) {
  REQUIRE_PLOTTING();
  const auto directory = FreshDirectory("plan");
  const auto result = directory / "plan.h5";
  const auto run = RunIsolab("run " + Source("models/plan/five_story_table9_plan.yaml") +
                             " --json -q -o " + result.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json peaks = nlohmann::json::parse(run.output)["peaks"];
  const auto plot = isolab::testing::RunCommandLine(
      "/usr/bin/python3 " + Source("scripts/plot_result.py") + " " + result.string() +
      " --metadata -q -o " + (directory / "plots").string() + " 2>&1");
  ASSERT_EQ(plot.exit_code, 0) << plot.output;
  const auto figure = [&](const char* name) {
    const auto png = directory / "plots" / (std::string("plan_") + name + ".png");
    ExpectFigure(png);
    return Sidecar(png);
  };
  const double peak_u = peaks["isolator_displacement"]["value"].get<double>();
  const double peak_rotation = peaks["floor_rotation"]["value"].get<double>();

  const nlohmann::json overview = figure("overview");
  ASSERT_EQ(overview["axes"].size(), 3u);  // orbits, resultant displacement, rotations
  EXPECT_EQ(overview["axes"][0]["xlabel"], "isolator displacement x [mm]");
  EXPECT_EQ(overview["axes"][0]["ylabel"], "isolator displacement y [mm]");
  EXPECT_LE(Extent(overview["axes"][0]["x_range"]), peak_u * (1 + 1e-9));
  EXPECT_NEAR(overview["axes"][1]["y_range"][1].get<double>(), peak_u, 1e-9 * peak_u);
  EXPECT_EQ(overview["axes"][2]["y_unit"], "mrad");
  EXPECT_NEAR(Extent(overview["axes"][2]["y_range"]), 1e3 * peak_rotation, 1e-6 * peak_rotation);

  const nlohmann::json hysteresis = figure("hysteresis");
  ASSERT_EQ(hysteresis["axes"].size(), 2u);
  EXPECT_EQ(hysteresis["axes"][0]["xlabel"], "isolator displacement x [mm]");
  EXPECT_EQ(hysteresis["axes"][1]["xlabel"], "isolator displacement y [mm]");
  for (const char* name : {"histories", "envelopes", "energy"}) figure(name);
}

TEST(PlotScript, SdofRunPlotsBesideItsResult) {
  REQUIRE_PLOTTING();
  const auto directory = FreshDirectory("sdof");
  const auto result = directory / "sdof.h5";
  const auto run = RunIsolab("run " + std::string(ISOLAB_TEST_DATA_DIR) +
                             "/cli/data/run_base.yaml -o " + result.string() + " --plot");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  for (const char* name : {"hysteresis", "histories", "energy"}) {
    ExpectFigure(directory / (std::string("sdof_") + name + ".png"));
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
      ExpectFigure(directory / extension / (std::string("fwn_") + name + ".png"));
    }
  }
  // The spectra drawn are the command line's: A in g up to its largest A_g or A_y_g, D in m.
  const auto json = RunIsolab("spectrum " + Source("ground_motions/fwn_firm_seed1.at2") +
                              " --periods 0.1:2:0.1 --damping 0.02,0.05 --ductility 2,4 -q --json");
  ASSERT_EQ(json.exit_code, 0) << json.output;
  const nlohmann::json spectrum = nlohmann::json::parse(json.output);
  double largest_a = 0.0, largest_d = 0.0;
  for (const nlohmann::json& curve : spectrum["elastic"]) {
    for (const double a : curve["A_g"]) largest_a = std::max(largest_a, a);
    for (const double d : curve["D"]) largest_d = std::max(largest_d, d);
  }
  for (const nlohmann::json& curve : spectrum["constant_ductility"]) {
    for (const double a : curve["A_y_g"]) largest_a = std::max(largest_a, a);
    for (const double d : curve["D_y"]) largest_d = std::max(largest_d, d);
  }
  const auto plot =
      isolab::testing::RunCommandLine("/usr/bin/python3 " + Source("scripts/plot_spectrum.py") +
                                      " " + (directory / "fwn.h5").string() + " --metadata -q -o " +
                                      (directory / "meta").string() + " 2>&1");
  ASSERT_EQ(plot.exit_code, 0) << plot.output;
  const nlohmann::json a = Sidecar(directory / "meta" / "fwn_A.png")["axes"][0];
  EXPECT_EQ(a["ylabel"], "pseudo-acceleration A [g]");
  EXPECT_EQ(a["xlabel"], "natural period T [s]");
  EXPECT_NEAR(a["y_range"][1].get<double>(), largest_a, 1e-9 * largest_a);
  EXPECT_NEAR(a["x_range"][0].get<double>(), 0.1, 1e-12);
  EXPECT_NEAR(a["x_range"][1].get<double>(), 2.0, 1e-12);
  const nlohmann::json d = Sidecar(directory / "meta" / "fwn_D.png")["axes"][0];
  EXPECT_EQ(d["y_unit"], "m");
  EXPECT_NEAR(d["y_range"][1].get<double>(), largest_d, 1e-9 * largest_d);
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
      ExpectFigure(directory / extension / (std::string("pair_") + name + ".png"));
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
  ExpectFigure(directory / "sdof_hysteresis.png");
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
  ExpectFigure(directory / "sdof_energy.png");
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
