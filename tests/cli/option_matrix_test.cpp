// Every option of `run`, `compare`, `cyclic` and `spectrum`, on a one-direction model and on a
// building in plan (for `spectrum`: one record and a pair): either applied, and then seen in what
// the command wrote (its JSON, its files, its stderr), or refused with exit code 2 and a message
// that names the option. An option that is accepted and does nothing fails here.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/run_isolab.h"
#include "cli/text_file.h"
#include "own_test_file.h"

namespace isolab::testing {
namespace {

namespace fs = std::filesystem;

const std::string kRoot = ISOLAB_SOURCE_DIR;
const std::string kH1 = kRoot + "/ground_motions/fwn_firm_seed1.at2";
const std::string kH2 = kRoot + "/ground_motions/h2_fwn_firm_seed3.at2";

struct Kind {
  const char* name;
  std::string model;
  bool plan;
};
void PrintTo(const Kind& kind, std::ostream* out) { *out << kind.name; }

const Kind kKinds[] = {
    {"one_direction", kRoot + "/models/buildings/five_story_table9.yaml", false},
    {"plan", kRoot + "/models/plan/five_story_table9_plan.yaml", true},
};

fs::path Folder(const std::string& name) {
  const fs::path folder = OwnTestDirectory() / name;
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

// `isolab <arguments>`: its exit code 0 and its JSON on stdout.
nlohmann::json Applied(const std::string& arguments) {
  const Outcome outcome = RunIsolab(arguments);
  EXPECT_EQ(outcome.exit_code, 0) << arguments << "\n" << RunIsolab(arguments, true).output;
  const nlohmann::json json = nlohmann::json::parse(outcome.output, nullptr, false);
  EXPECT_FALSE(json.is_discarded()) << arguments << "\n" << outcome.output;
  return json;
}

// `isolab <arguments>` exits 2 and its message names `option`.
void ExpectRefused(const std::string& arguments, const std::string& option) {
  const Outcome outcome = RunIsolab(arguments, true);
  EXPECT_EQ(outcome.exit_code, 2) << arguments << "\n" << outcome.output;
  EXPECT_NE(outcome.output.find(option), std::string::npos)
      << arguments << ": the message does not name " << option << "\n"
      << outcome.output;
}

bool EndsWith(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

// The CSV's header row (the first line that is not a '#' comment) and its number of data rows.
std::pair<std::string, int> CsvShape(const fs::path& path) {
  std::ifstream in(path);
  std::string line, header;
  int rows = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (header.empty()) {
      header = line;
    } else {
      ++rows;
    }
  }
  return {header, rows};
}

class RunOptions : public ::testing::TestWithParam<Kind> {};

TEST_P(RunOptions, EachRecordOptionIsAppliedOrRefused) {
  const Kind& kind = GetParam();
  const fs::path folder = Folder(std::string("run_records_") + kind.name);
  const std::string run = "run " + kind.model + " --json -q -o " + (folder / "r.h5").string() + " ";
  const nlohmann::json base = Applied(run);

  EXPECT_TRUE(EndsWith(Applied(run + "--record " + kH2)["record"], "h2_fwn_firm_seed3.at2"));
  const std::string pair = "--record " + kH1 + " --record-h2 " + kH2;
  const std::string turned = "--record " + kH1 + " --angle 30";
  if (kind.plan) {
    EXPECT_TRUE(EndsWith(Applied(run + pair)["h2"]["record"], "h2_fwn_firm_seed3.at2"));
    EXPECT_EQ(Applied(run + turned)["angle"], 30.0);
  } else {
    ExpectRefused(run + pair, "--record-h2");
    ExpectRefused(run + turned, "--angle");
  }
  ExpectRefused(run + "--record-h2 " + kH2, "--record-h2");  // without --record
  ExpectRefused(run + "--angle 30", "--angle");              // the model's pair has its own
  // A vertical component: refused where no friction pendulum takes it (axial_load), and without
  // --record; applied on the plan building on friction pendulums (docs/axial_load.md).
  const std::string kV = kRoot + "/ground_motions/v_fwn_firm_seed4.at2";
  ExpectRefused(run + "--record " + kH1 + " --record-v " + kV, "--record-v");
  EXPECT_EQ(RunIsolab(run + "--record " + kH1 + " --record-v " + kV, true)
                .output.find("--record-v: --record-v"),
            std::string::npos);  // the option said once
  ExpectRefused(run + "--record-v " + kV, "--record-v");
  if (kind.plan) {
    const std::string fp = kRoot + "/models/plan/five_story_fp_plan.yaml --json -q -o " +
                           (folder / "fp.h5").string() + " ";
    EXPECT_TRUE(EndsWith(Applied("run " + fp + pair + " --record-v " + kV)["v"]["record"],
                         "v_fwn_firm_seed4.at2"));
    ExpectRefused("run " + fp + pair, "--record-v");            // the model asks for the vertical
    ExpectRefused("run " + fp + "--fixed-base", "axial_load");  // no bearing carries the weight
  }

  // The AT2 header says g and 0.01 s: the options must agree with it, and are checked.
  EXPECT_EQ(Applied(run + "--record " + kH1 + " --units g")["record_units"], "g");
  ExpectRefused(run + "--record " + kH1 + " --units m/s^2", "--units");
  EXPECT_EQ(Applied(run + "--record " + kH1 + " --record-dt 0.01")["record_dt"], 0.01);
  ExpectRefused(run + "--record " + kH1 + " --record-dt 0.02", "--record-dt");
  ExpectRefused(run + "--record " + kH1 + " --record-dt 0", "--record-dt");  // not "no step"

  const nlohmann::json half = Applied(run + "--scale 0.5");
  EXPECT_NEAR(half["pga"].get<double>(),
              0.5 / base["scale"].get<double>() * base["pga"].get<double>(),
              1e-9 * base["pga"].get<double>());
}

TEST_P(RunOptions, EachAnalysisOptionIsAppliedOrRefused) {
  const Kind& kind = GetParam();
  const fs::path folder = Folder(std::string("run_analysis_") + kind.name);
  const std::string run = "run " + kind.model + " --json -q -o " + (folder / "r.h5").string() + " ";
  const nlohmann::json base = Applied(run);

  const nlohmann::json fine = Applied(run + "--dt 0.0025");
  EXPECT_EQ(fine["dt"], 0.0025);
  EXPECT_NEAR(fine["steps"].get<double>(), 2 * base["steps"].get<double>(), 2);
  ExpectRefused(run + "--max-steps 10", "--max-steps");
  EXPECT_EQ(Applied(run + "--free-vibration 0")["free_vibration"], 0.0);
  EXPECT_EQ(Applied(run + "--free-vibration 3")["free_vibration"], 3.0);
  EXPECT_EQ(Applied(run + "--trial-displacement 50")["model_summary"]["trial_displacement"], 50.0);

  const nlohmann::json fixed = Applied(run + "--fixed-base");
  EXPECT_FALSE(fixed.contains("isolators"));
  EXPECT_FALSE(fixed["peaks"].contains("isolator_displacement"));
  EXPECT_FALSE(fixed["model_summary"].contains("isolated_period"));
  EXPECT_LT(fixed["peaks"]["base_shear"]["value"].get<double>(),
            10 * base["peaks"]["base_shear"]["value"].get<double>());
  ASSERT_TRUE(base.contains("isolators"));
  // A fixed base has no isolated period to read at a trial displacement.
  ExpectRefused(run + "--fixed-base --trial-displacement 50", "--trial-displacement");
  // The seed of the parameter sets --samples draws, without them.
  ExpectRefused(run + "--seed 3", "--seed");

  EXPECT_EQ(base["integrator"].get<std::string>().rfind("newmark", 0), 0u);
  const nlohmann::json ida = Applied(run + "--integrator ida --rtol 1e-5 --atol 1e-4");
  EXPECT_EQ(ida["integrator"].get<std::string>().rfind("ida rtol=1e-05 atol=0.0001", 0), 0u)
      << ida["integrator"];
  ExpectRefused(run + "--rtol 1e-5", "--rtol");  // a Newmark run has no IDA tolerance
  ExpectRefused(run + "--atol 1e-4", "--atol");
}

TEST_P(RunOptions, EachOutputOptionIsAppliedOrRefused) {
  const Kind& kind = GetParam();
  const fs::path folder = Folder(std::string("run_output_") + kind.name);
  const std::string run = "run " + kind.model + " --json -q ";
  const fs::path csv = folder / "r.csv";
  const int steps = Applied(run + "-o " + csv.string())["steps"];
  const auto [header, rows] = CsvShape(csv);
  EXPECT_EQ(rows, steps + 1);  // t = 0 and every step
  EXPECT_EQ(header.rfind("time", 0), 0u) << header;
  EXPECT_NE(header.find("floor 1"), std::string::npos) << header;
  EXPECT_NE(header.find("velocity"), std::string::npos) << header;

  Applied(run + "-o " + csv.string() + " --every 10");
  EXPECT_EQ(CsvShape(csv).second, steps / 10 + 1);  // t = 0 and every tenth step
  Applied(run + "-o " + csv.string() + " --quantities displacement --levels roof");
  const std::string chosen = CsvShape(csv).first;
  EXPECT_EQ(chosen.find("velocity"), std::string::npos) << chosen;
  EXPECT_EQ(chosen.find("floor 1"), std::string::npos) << chosen;
  EXPECT_NE(chosen.find("displacement"), std::string::npos) << chosen;
  ExpectRefused(run + "-o " + csv.string() + " --quantities bogus", "--quantities");
  ExpectRefused(run + "-o " + csv.string() + " --levels 7", "--levels");
  // Histories the run has not: an isolator's on a fixed base, stories' on an SDOF.
  ExpectRefused(run + "-o " + csv.string() + " --fixed-base --quantities isolator", "--quantities");
  ExpectRefused("run " + kRoot + "/models/sdof/table7_thm1_hard.yaml -q -o " + csv.string() +
                    " --quantities story",
                "--quantities");
  // Options that choose histories, beside --summary-only, which writes none.
  for (const std::string option : {"--every 7", "--quantities energy", "--levels roof"}) {
    ExpectRefused(run + "-o " + csv.string() + " --summary-only " + option,
                  option.substr(0, option.find(' ')));
  }

  const fs::path full = folder / "full.h5", summary = folder / "summary.h5";
  Applied(run + "-o " + full.string());
  Applied(run + "-o " + summary.string() + " --summary-only");
  EXPECT_LT(fs::file_size(summary) * 20, fs::file_size(full));

  // -q drops the preamble (the record and the model's periods) before the peaks.
  const std::string text = "run " + kind.model + " -o " + full.string();
  EXPECT_NE(RunIsolab(text).output.find("fixed-base periods"), std::string::npos);
  EXPECT_EQ(RunIsolab(text + " -q").output.find("fixed-base periods"), std::string::npos);
}

// --plot draws, byte for byte, the figures scripts/plot_result.py draws from the same results
// (what those show against the run's peaks is tests/cli/plot_script_test.cpp's), titled with the
// kind's model and every panel with a unit (the script's --metadata sidecars); and it is
// refused with a selection that leaves out histories the plots read.
TEST_P(RunOptions, PlotIsApplied) {
  const Kind& kind = GetParam();
  const fs::path folder = Folder(std::string("run_plot_") + kind.name);
  const Outcome outcome = RunIsolab("run " + kind.model + " -q -o " + (folder / "r.h5").string() +
                                    " --plot=" + (folder / "plots").string());
  ASSERT_EQ(outcome.exit_code, 0) << outcome.output;
  const Outcome script = isolab::testing::RunCommandLine(
      "/usr/bin/python3 " + kRoot + "/scripts/plot_result.py " + (folder / "r.h5").string() +
      " --metadata -q -o " + (folder / "script").string() + " 2>&1");
  ASSERT_EQ(script.exit_code, 0) << script.output;
  for (const char* name : {"overview", "hysteresis", "histories", "envelopes", "energy"}) {
    const std::string png = std::string("r_") + name + ".png";
    const std::string drawn = ReadText(folder / "plots" / png);
    ASSERT_EQ(drawn.rfind("\x89PNG", 0), 0u) << png << " is not a PNG";
    EXPECT_TRUE(drawn == ReadText(folder / "script" / png)) << png << " differs from the script's";
    const nlohmann::json sidecar =
        nlohmann::json::parse(ReadText(folder / "script" / (std::string("r_") + name + ".json")));
    std::string titles = sidecar["title"];  // the figure's, or its one panel's
    for (const nlohmann::json& axes : sidecar["axes"])
      titles += "|" + axes["title"].get<std::string>();
    EXPECT_NE(titles.find(fs::path(kind.model).filename().string()), std::string::npos)
        << png << ": " << titles;
    ASSERT_FALSE(sidecar["axes"].empty()) << png;
    for (const nlohmann::json& axes : sidecar["axes"]) {  // a level or a shared time axis aside
      EXPECT_FALSE(axes["x_unit"].get<std::string>().empty() &&
                   axes["y_unit"].get<std::string>().empty())
          << png << ": " << axes["xlabel"] << ", " << axes["ylabel"];
    }
  }
  // Without the histories the plots read, refused before the run writes anything.
  for (const std::string option : {"--summary-only", "--quantities energy", "--levels roof"}) {
    const fs::path results = folder / "left_out.h5";
    ExpectRefused("run " + kind.model + " -q -o " + results.string() + " --plot " + option,
                  "--plot");
    EXPECT_FALSE(fs::exists(results)) << option;
  }
}

INSTANTIATE_TEST_SUITE_P(Kinds, RunOptions, ::testing::ValuesIn(kKinds),
                         [](const auto& info) { return std::string(info.param.name); });

// A study of the kind's model under one record (a pair in plan) at one scale.
fs::path WriteStudy(const fs::path& folder, const Kind& kind) {
  const fs::path path = folder / "study.yaml";
  std::ofstream out(path);
  out << "building: " << kind.model << "\nvariants:\n  - {name: base}\nrecords:\n";
  if (kind.plan) {
    out << "  - {name: firm, h1: {file: " << kH1 << "}, h2: {file: " << kH2 << "}}\n";
  } else {
    out << "  - {file: " << kH1 << "}\n";
  }
  out << "scales: [0.6]\n";
  return path;
}

class CompareOptions : public ::testing::TestWithParam<Kind> {};

TEST_P(CompareOptions, EachOptionIsApplied) {
  const Kind& kind = GetParam();
  const fs::path folder = Folder(std::string("compare_") + kind.name);
  const fs::path study = WriteStudy(folder, kind);
  const std::string compare = "compare " + study.string() + " -o ";

  // -o, -j: the summary in the folder named, the same from one thread and two.
  ASSERT_EQ(RunIsolab(compare + (folder / "one").string() + " -j 1 -q").exit_code, 0);
  ASSERT_EQ(RunIsolab(compare + (folder / "two").string() + " -j 2 -q").exit_code, 0);
  EXPECT_EQ(ReadText(folder / "one" / "summary.csv"), ReadText(folder / "two" / "summary.csv"));
  ExpectRefused(compare + (folder / "bad").string() + " -j 0", "--jobs");

  // -q: no progress on stderr.
  EXPECT_FALSE(RunIsolab(compare + (folder / "loud").string(), true).output.empty());
  EXPECT_TRUE(RunIsolab(compare + (folder / "quiet").string() + " -q", true).output.empty());

  // --free-vibration 0: the residual is read where the record ends, as `isolab run` reads it.
  ASSERT_EQ(RunIsolab(compare + (folder / "end").string() + " -q --free-vibration 0").exit_code, 0);
  const nlohmann::json run =
      Applied("run " + kind.model + " --json -q --scale 0.6 -o " + (folder / "r.h5").string() +
              " --free-vibration 0 --record " + kH1 + (kind.plan ? " --record-h2 " + kH2 : ""));
  const std::vector<std::vector<std::string>> rows = CsvRows(folder / "end" / "summary.csv");
  ASSERT_GE(rows.size(), 2u);
  std::size_t residual = 0;
  while (residual < rows[0].size() && rows[0][residual].rfind("residual_isolator", 0) != 0) {
    ++residual;
  }
  ASSERT_LT(residual, rows[0].size());
  const double expected = run["residual_isolator_displacement"].get<double>();
  EXPECT_NEAR(std::stod(rows[1][residual]), expected, 1e-9 * (1 + expected));
  ExpectRefused(compare + (folder / "bad").string() + " --free-vibration -1", "--free-vibration");

  // --plot: the bar charts beside the summary.
  ASSERT_EQ(RunIsolab(compare + (folder / "plot").string() + " -q --plot").exit_code, 0);
  EXPECT_TRUE(fs::exists(folder / "plot" / "plots"));
  EXPECT_FALSE(fs::is_empty(folder / "plot" / "plots"));
}

INSTANTIATE_TEST_SUITE_P(Kinds, CompareOptions, ::testing::ValuesIn(kKinds),
                         [](const auto& info) { return std::string(info.param.name); });

// `cyclic` on a one-direction isolation (a Table 7 SDOF) and a plan model's isolators: the
// sinusoidal test is a one-direction model's; a path or an orbit drives either.
TEST(CyclicOptions, TheSinusoidalTestsOptionsOnAOneDirectionModelAreApplied) {
  const fs::path folder = Folder("cyclic_sinusoidal");
  const std::string cyclic = "cyclic " + kRoot + "/models/sdof/table7_thm1_hard.yaml --json ";
  const nlohmann::json json = Applied(cyclic + "-a 40 -T 2 -n 2 --steps-per-cycle 40");
  const nlohmann::json& protocol = json["runs"][0]["protocol"];
  EXPECT_EQ(protocol["amplitude"], 40.0);
  EXPECT_EQ(protocol["period"], 2.0);
  EXPECT_EQ(protocol["cycles"], 2);
  EXPECT_EQ(protocol["steps_per_cycle"], 40);

  const fs::path loop = folder / "loop.csv", data = folder / "data.csv";
  Applied(cyclic + "-a 40 --csv " + loop.string() + " --test-data " + data.string() +
          " --noise 0.05 --seed 7 --sequential");
  EXPECT_TRUE(fs::exists(loop));
  EXPECT_NE(ReadText(data).find("# specimen: one"), std::string::npos);
  const std::string noisy = ReadText(data);
  Applied(cyclic + "-a 40 --test-data " + data.string() + " --noise 0.05 --seed 8 --sequential");
  EXPECT_NE(ReadText(data), noisy);  // another seed, other noise

  ExpectRefused(cyclic + "-a 40 --isolator x", "--isolator");
  ExpectRefused(cyclic + "-a 40 --uncoupled", "--uncoupled");
  ExpectRefused(cyclic + "-a 40 --force-unit kN", "--force-unit");
  ExpectRefused(cyclic + "-a 40 --noise 0.1", "--noise");  // no --test-data to put it on
}

TEST(CyclicOptions, TheSinusoidalTestOnABuildingInPlanIsRefusedNamingTheOrbit) {
  const std::string cyclic = "cyclic " + kKinds[1].model + " --json ";
  ExpectRefused(cyclic + "-a 40", "--orbit");
}

// A model whose bearings take axial loads (docs/axial_load.md): its tests, paths and orbits would
// drive the laws at their own w, so they are refused naming the key.
TEST(CyclicOptions, AModelWithAxialLoadsIsRefusedNamingTheKey) {
  const std::string fp = "cyclic " + kRoot + "/models/plan/five_story_fp_plan.yaml --json ";
  ExpectRefused(fp + "-a 40", "five_story_fp_plan.yaml:39:13: axial_load");
  ExpectRefused(fp + "--orbit circle -a 40", "five_story_fp_plan.yaml:39:13: axial_load");
}

class CyclicPathOptions : public ::testing::TestWithParam<Kind> {};

TEST_P(CyclicPathOptions, EachOptionIsAppliedOrRefused) {
  const Kind& kind = GetParam();
  const fs::path folder = Folder(std::string("cyclic_path_") + kind.name);
  const std::string model = kind.plan ? kind.model : kRoot + "/models/sdof/table7_thm1_hard.yaml";
  const std::string orbit = "cyclic " + model + " --json --orbit circle -a 40 -T 2 ";

  const nlohmann::json one = Applied(orbit + "-n 1 --steps-per-cycle 40");
  const nlohmann::json& run = one["runs"][0];
  EXPECT_EQ(run["cycles"].size(), 1u);
  EXPECT_EQ(run["samples"], 40 + 10 + 1);  // a quarter period from rest, then the cycle
  EXPECT_NEAR(run["peak_displacement"].get<double>(), 40.0, 1e-9);
  EXPECT_EQ(Applied(orbit + "-n 3")["runs"][0]["cycles"].size(), 3u);

  if (kind.plan) {
    EXPECT_EQ(Applied(orbit + "-n 1")["runs"].size(), 4u);  // the four corner isolators
    const nlohmann::json ne = Applied(orbit + "-n 1 --isolator ne");
    ASSERT_EQ(ne["runs"].size(), 1u);
    EXPECT_TRUE(EndsWith(ne["runs"][0]["model"], "isolator ne"));
    ExpectRefused(orbit + "--uncoupled", "--uncoupled");
  } else {
    ExpectRefused(orbit + "--isolator ne", "--isolator");
    // Uncoupled, each law along x and y on its own: a circle's force is not the coupled one.
    const double coupled = Applied(orbit)["runs"][0]["peak_force"];
    const double uncoupled = Applied(orbit + "--uncoupled")["runs"][0]["peak_force"];
    EXPECT_GT(std::abs(uncoupled - coupled), 1e-3 * coupled);
  }

  const fs::path csv = folder / "loop.csv";
  Applied(orbit + "-n 1 --csv " + csv.string() + (kind.plan ? " --isolator ne" : ""));
  EXPECT_GT(CsvShape(csv).second, 40);
  for (const char* option : {"--test-data x.csv", "--noise 0.1", "--seed 3", "--sequential"}) {
    ExpectRefused(orbit + option, std::string(option).substr(0, std::string(option).find(' ')));
  }
  ExpectRefused(orbit + "--force-unit kN", "--force-unit");

  // A path file without a units line takes --force-unit and --length-unit (m here: 0.02 m is
  // 20 mm); the shape options are the path's own.
  const fs::path path = folder / "path.csv";
  std::ofstream(path) << "time,displacement_x,displacement_y\n0,0,0\n0.1,0.01,0.005\n"
                         "0.2,0.02,0\n0.3,0,-0.01\n";
  const std::string along = "cyclic " + model + " --json --path " + path.string() + " ";
  ExpectRefused(along, "--force-unit");
  const nlohmann::json followed = Applied(along + "--force-unit kN --length-unit m");
  EXPECT_NEAR(followed["runs"][0]["peak_displacement"].get<double>(), 20.0, 1e-9);
  EXPECT_EQ(followed["runs"][0]["samples"], 4);
  ExpectRefused(along + "--force-unit kN --length-unit m -a 40", "--amplitude");
  ExpectRefused(along + "--force-unit kN --length-unit m -n 2", "--cycles");
}

INSTANTIATE_TEST_SUITE_P(Kinds, CyclicPathOptions, ::testing::ValuesIn(kKinds),
                         [](const auto& info) { return std::string(info.param.name); });

// `spectrum` of one record and of a pair (a plan model's excitation).
class SpectrumOptions : public ::testing::TestWithParam<bool> {};

TEST_P(SpectrumOptions, EachOptionIsAppliedOrRefused) {
  const bool pair = GetParam();
  const fs::path folder = Folder(pair ? "spectrum_pair" : "spectrum_one");
  const std::string spectrum =
      "spectrum " + kH1 + (pair ? " " + kH2 : "") + " --periods 0.5,1 --json -q ";
  // One record's curves are "elastic"; a pair's, per damping ratio, its RotD100 among others.
  const auto curve = [&](const nlohmann::json& json) {
    return pair ? json["pair"][0]["rotd100"] : json["elastic"][0];
  };
  const nlohmann::json base = Applied(spectrum);
  EXPECT_EQ(Applied(spectrum + "--damping 0.02")[pair ? "pair" : "elastic"][0]["damping"], 0.02);
  const nlohmann::json twice = Applied(spectrum + "--scale 2");
  EXPECT_NEAR(curve(twice)["D"][0].get<double>(), 2 * curve(base)["D"][0].get<double>(),
              1e-9 * curve(base)["D"][0].get<double>());
  const nlohmann::json mm = Applied(spectrum + "--length-unit mm");
  EXPECT_NEAR(curve(mm)["D"][0].get<double>(), 1000 * curve(base)["D"][0].get<double>(),
              1e-9 * curve(mm)["D"][0].get<double>());
  const nlohmann::json coarse = Applied(spectrum + "--points-per-period 1");
  EXPECT_NE(curve(coarse)["D"][0].get<double>(), curve(base)["D"][0].get<double>());
  ExpectRefused(spectrum + "--max-steps 100", "--max-steps");
  EXPECT_EQ(Applied(spectrum + "--units g")["record_units"], "g");
  ExpectRefused(spectrum + "--units m/s^2", "--units");
  ExpectRefused(spectrum + "--dt 0.02", "--dt");       // the AT2 file says 0.01 s
  ExpectRefused(spectrum + "--alpha 0.1", "--alpha");  // without --ductility

  if (pair) {
    ExpectRefused(spectrum + "--ductility 2", "--ductility");
  } else {
    const nlohmann::json ductile = Applied(spectrum + "--ductility 2 --alpha 0.1");
    EXPECT_EQ(ductile["constant_ductility"][0]["ductility"], 2.0);
    EXPECT_EQ(ductile["constant_ductility"][0]["alpha"], 0.1);
  }
  const fs::path csv = folder / "s.csv", h5 = folder / "s.h5";
  Applied(spectrum + "-o " + csv.string() + " -o " + h5.string());
  EXPECT_TRUE(fs::exists(csv));
  EXPECT_TRUE(fs::exists(h5));
}

INSTANTIATE_TEST_SUITE_P(Records, SpectrumOptions, ::testing::Bool(),
                         [](const auto& info) { return std::string(info.param ? "pair" : "one"); });

}  // namespace
}  // namespace isolab::testing
