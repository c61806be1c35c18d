// `isolab fit` end to end: data written by `isolab cyclic --test-data` from a known model are
// fitted back, the fitted model file is accepted by `isolab cyclic`, a fixed seed reproduces the
// fit, bad data gives a located message with exit code 2, and a fit on MPI ranks gives what one
// process gives.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "cli/run_isolab.h"
#include "isolab/model/model_file.h"
#include "own_test_file.h"

namespace {

using isolab::testing::RunIsolab;

std::string Data(const std::string& name) {
  return std::string(ISOLAB_TEST_DATA_DIR) + "/cli/data/fit/" + name;
}

std::filesystem::path TemporaryFile(const std::string& name) {
  const auto directory = isolab::testing::OwnTestDirectory();
  std::filesystem::create_directories(directory);
  const auto path = directory / name;
  std::filesystem::remove(path);
  return path;
}

std::string GenerateTests(double noise) {
  const auto csv = TemporaryFile("three_laws_" + std::to_string(noise) + ".csv");
  const auto run = RunIsolab("cyclic " + Data("three_laws.yaml") +
                             " -a 5,50,100,150 -T 2 -n 3 --steps-per-cycle 200 --test-data " +
                             csv.string() + " --noise " + std::to_string(noise) + " --seed 3");
  EXPECT_EQ(run.exit_code, 0) << run.output;
  return csv.string();
}

nlohmann::json Fit(const std::string& data, const std::string& output, const std::string& extra) {
  const auto run = RunIsolab("fit " + data + " --model " + Data("three_laws_spec.yaml") +
                             " --budget 6000 --json -q -o " + output + " " + extra);
  EXPECT_EQ(run.exit_code, 0) << run.output;
  return nlohmann::json::parse(run.output);
}

// The first 1,500 samples of the Bouc-Wen benchmark's sine sweep (bundled) as a force-driven
// cyclic-test file, and the benchmark's model beside it (boucwen.yaml) for a building fit's
// specification to name.
std::filesystem::path WriteSweepTest() {
  std::ifstream sweep(std::string(ISOLAB_TEST_DATA_DIR) +
                      "/data/boucwen/sinesweep_first_30000.csv");
  const auto data = TemporaryFile("sweep.csv");
  std::ofstream out(data);
  out << "# units: force N, length m\ntest,time,displacement,force\n";
  std::string line;
  for (int k = 0; k < 1500 && std::getline(sweep, line);) {
    if (line.empty() || line[0] == '#' || line.find("u_N") != std::string::npos) continue;
    const auto comma = line.find(',');
    out << "sweep," << k / 750.0 << "," << line.substr(comma + 1) << "," << line.substr(0, comma)
        << "\n";
    ++k;
  }
  std::ofstream(TemporaryFile("boucwen.yaml"))
      << "units: {force: N, length: m, time: s}\nstructure: {type: sdof, mass: 2}\n"
         "isolation:\n  components:\n    - {name: k, type: linear_spring, k: 5.0e4}\n"
         "    - {name: z, type: bouc_wen, alpha: 5.0e4, beta: 1.0e3, gamma: 0.8, delta: -1.1, "
         "nu: 1}\n    - {name: c, type: dashpot, c: 10}\n";
  return data;
}

TEST(FitCommand, FitsBackAKnownModelAndWritesAModelFileIsolabAccepts) {
  const std::string data = GenerateTests(0.0);
  const auto fitted = TemporaryFile("fitted.yaml");
  const auto json = Fit(data, fitted.string(), "--cycles 3 --seed 5");
  EXPECT_LT(json["e2"].get<double>(), 1e-8);
  ASSERT_EQ(json["e2_per_test"].size(), 4u);
  for (const auto& row : json["energy_per_cycle"]) {
    EXPECT_NEAR(row["fitted"].get<double>() / row["measured"].get<double>(), 1.0, 1e-4);
    EXPECT_EQ(row["cycle"].get<int>(), 3);
  }
  // The trilinear spring comes back exactly; the elastoplastic pair in either order.
  const auto& c = json["components"][2]["parameters"];
  EXPECT_NEAR(c["k1"].get<double>(), 0.2, 1e-4);
  EXPECT_NEAR(c["k2"].get<double>(), 0.6, 1e-4);
  EXPECT_NEAR(c["uyh"].get<double>(), 120, 1e-2);
  const auto cyclic = RunIsolab("cyclic " + fitted.string() + " -a 100 --json");
  EXPECT_EQ(cyclic.exit_code, 0) << cyclic.output;
  // e^2 is the paper's sum over tests; per test, and their mean, is what reads right.
  EXPECT_NEAR(json["e2_mean"].get<double>(), json["e2"].get<double>() / 4, 1e-15);
  // A building model takes the fitted isolator with isolation: {file: fitted.yaml}.
  const auto building = fitted.parent_path() / "building_on_fitted.yaml";
  std::filesystem::copy_file(Data("building_on_fitted.yaml"), building,
                             std::filesystem::copy_options::overwrite_existing);
  const auto run = RunIsolab("run " + building.string() + " --json -o " +
                             (fitted.parent_path() / "building.h5").string());
  EXPECT_EQ(run.exit_code, 0) << run.output;
}

// The testing factors of the tests' own cycles (identification/testing_factors.h), from a
// lead-rubber bearing whose core heats (adiabatic): its Qd falls from the second cycle to the
// third, so lambda_test brackets 1; the fitted model carries the modification entry to copy.
TEST(FitCommand, ReportsTheTestingFactorsOfTheTestsCycles) {
  const auto model = TemporaryFile("heating_lrb.yaml");
  std::ofstream(model) << "units: {force: kN, length: mm, time: s}\n"
                          "isolation:\n  components:\n"
                          "    - {name: lrb, type: lead_rubber, qd: 88.26, kd: 0.3391, ku: 3.391, "
                          "lead_diameter: 106, lead_height: 127, lead_heat_capacity: 1.456e-3}\n";
  const auto csv = TemporaryFile("heating_lrb.csv");
  const auto cyclic =
      RunIsolab("cyclic " + model.string() +
                " -a 100,200 -T 2 -n 4 --steps-per-cycle 400 --test-data " + csv.string());
  ASSERT_EQ(cyclic.exit_code, 0) << cyclic.output;
  const auto fitted = TemporaryFile("heating_fitted.yaml");
  const auto json = Fit(csv.string(), fitted.string(), "");
  const auto& factors = json["testing_factors"];
  ASSERT_EQ(factors["cycles"].size(), 6u);  // two tests, their first three cycles
  for (int test = 0; test < 2; ++test) {
    const auto& cycles = factors["cycles"];
    EXPECT_LT(cycles[3 * test + 2]["qd"].get<double>(), cycles[3 * test + 1]["qd"].get<double>())
        << "the core heats: the third cycle is weaker than the second";
  }
  EXPECT_GT(factors["qd"]["max"].get<double>(), 1.0);
  EXPECT_LT(factors["qd"]["min"].get<double>(), 1.0);
  std::ifstream in(fitted);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("#   modification: {<component>: {qd: {testing: ["), std::string::npos)
      << text;
}

// The fitted model carries the range of the samples the fit saw. A sinusoidal test u = A sin(2 pi
// t / T) of N cycles, S samples a cycle, has, in closed form: peak |u| = A (S a multiple of 4
// samples the crests), peak |v| = 2 pi A / T, which the backward differences the fit drives the
// laws with reach as A sin(2 pi / S) / dt (the difference across a zero crossing), and 2 N
// reversals: N cycles. Fitting cycles 2 and 3 only sees two.
TEST(FitCommand, TheFittedModelCarriesTheRangeOfTheDataTheFitSaw) {
  const double amplitude = 80.0, period = 1.6;  // mm, s
  const int cycles = 3, steps = 400;
  const auto csv = TemporaryFile("sine.csv");
  const auto generate = RunIsolab("cyclic " + Data("three_laws.yaml") + " -a 80 -T 1.6 -n 3 " +
                                  "--steps-per-cycle 400 --test-data " + csv.string());
  ASSERT_EQ(generate.exit_code, 0) << generate.output;
  const double dt = period / steps;
  const double closed_form = 2 * std::numbers::pi * amplitude / period;
  const double sampled = amplitude * std::sin(2 * std::numbers::pi / steps) / dt;
  // The differences fall short of the derivative by (2 pi / S)^2 / 6, 4e-5 here.
  EXPECT_NEAR(sampled / closed_form, 1.0, 5e-5);
  struct Case {
    std::string cycles;
    double expected_cycles;
  };
  for (const Case& c : {Case{"", double(cycles)}, Case{"--cycles 2 --cycles 3", 2.0}}) {
    const auto fitted = TemporaryFile("sine_fitted.yaml");
    const auto run = RunIsolab("fit " + csv.string() + " --model " + Data("three_laws_spec.yaml") +
                               " --budget 600 --json -q -o " + fitted.string() + " " + c.cycles);
    ASSERT_EQ(run.exit_code, 0) << run.output;
    const auto json = nlohmann::json::parse(run.output);
    const auto& range = json["identified_range"];
    EXPECT_NEAR(range["displacement"].get<double>(), amplitude, 1e-9 * amplitude) << c.cycles;
    // The data file holds 9 significant digits: a difference of two samples keeps about 8.
    EXPECT_NEAR(range["velocity"].get<double>(), sampled, 1e-7 * sampled) << c.cycles;
    EXPECT_NEAR(range["velocity"].get<double>(), closed_form, 5e-5 * closed_form) << c.cycles;
    EXPECT_EQ(range["cycles"].get<double>(), c.expected_cycles) << c.cycles;
    ASSERT_EQ(json["e2_per_test"].size(), 1u);
    const std::string test = json["e2_per_test"].begin().key();
    EXPECT_EQ(range["data"], nlohmann::json::array({test}));
    // The file says the same, to the digits it is written with, and reads back.
    const isolab::model::ModelFile model = isolab::model::LoadModelFile(fitted.string());
    ASSERT_TRUE(model.identified_range) << c.cycles;
    EXPECT_NEAR(model.identified_range->displacement, amplitude, 1e-8 * amplitude);
    EXPECT_NEAR(model.identified_range->velocity, sampled, 1e-7 * sampled);
    EXPECT_EQ(model.identified_range->cycles, c.expected_cycles);
    EXPECT_EQ(model.identified_range->data, std::vector<std::string>{test});
  }
}

TEST(FitCommand, AFixedSeedReproducesTheFitAndNoiseSetsTheFloor) {
  const std::string noisy = GenerateTests(0.01);
  const auto first = Fit(noisy, TemporaryFile("a.yaml").string(), "--seed 11");
  const auto second = Fit(noisy, TemporaryFile("b.yaml").string(), "--seed 11");
  EXPECT_EQ(first["e2"].get<double>(), second["e2"].get<double>());
  EXPECT_EQ(first["components"], second["components"]);
  // 1 % noise on every sample: each test's term is near 1e-4, and the fit cannot go below it.
  const double per_test = first["e2"].get<double>() / 4;
  EXPECT_GT(per_test, 0.5e-4);
  EXPECT_LT(per_test, 2e-4);
}

// `isolab cyclic --sequential` writes a campaign on one specimen with its header; fit reads it as
// one specimen unless --specimen independent says otherwise, and the carried state is what lets
// the truth's own form fit it: as fresh specimens the same fit misses by far more.
TEST(FitCommand, ACampaignOnOneSpecimenIsFittedAsOne) {
  const auto csv = TemporaryFile("campaign.csv");
  const auto run = RunIsolab("cyclic " + std::string(ISOLAB_SOURCE_DIR) +
                             "/models/diagnosis/cyclic_degradation.yaml -a 25,100,50 -n 2 "
                             "--steps-per-cycle 200 --sequential --test-data " +
                             csv.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  std::ifstream in(csv);
  std::string first, second;
  std::getline(in, first);
  std::getline(in, second);
  EXPECT_EQ(second, "# specimen: one, in order");
  const auto spec = TemporaryFile("degrading_spec.yaml");
  std::ofstream(spec) << "units: {force: kN, length: mm}\ncomponents:\n"
                         "  - {type: bhm2, name: base, fixed: {uy: 8}}\n"
                         "  - {type: degrading_bhm2, name: degrading, fixed: {uy: 10}}\n";
  const auto fit = [&](const std::string& extra) {
    const auto result = RunIsolab("fit " + csv.string() + " --model " + spec.string() +
                                  " --budget 1500 --cycles 1 --cycles 2 --json -q -o " +
                                  TemporaryFile("campaign_fit.yaml").string() + " " + extra);
    EXPECT_EQ(result.exit_code, 0) << result.output;
    return nlohmann::json::parse(result.output);
  };
  const auto one = fit("");
  const auto fresh = fit("--specimen independent");
  EXPECT_TRUE(one["one_specimen"].get<bool>());
  EXPECT_FALSE(fresh["one_specimen"].get<bool>());
  EXPECT_LT(one["e2"].get<double>(), 1e-6);
  EXPECT_GT(fresh["e2"].get<double>(), 100 * one["e2"].get<double>());
  const auto& degrading = one["components"][1]["parameters"];
  EXPECT_NEAR(degrading["loss"].get<double>(), 0.6, 0.01);
  EXPECT_NEAR(degrading["slip_scale"].get<double>(), 150, 2);
}

TEST(FitCommand, BadDataExitsWithCodeTwoNamingFileLineAndTest) {
  struct Case {
    std::string file, message;
  };
  const Case cases[] = {
      {"bad_missing_column.csv", "bad_missing_column.csv:1: missing column 'force'"},
      {"bad_not_a_number.csv", "bad_not_a_number.csv:3: column 'force': 'abc' is not a number"},
      {"bad_never_reverses.csv", "test 'ramp': too short to identify anything"},
      {"bad_one_reversal.csv", "test 'once': too short to identify anything: 5 samples"},
      {"bad_time_repeats.csv", "bad_time_repeats.csv:5: column 'time': 2 does not increase"},
      // Nothing to fit: not "e^2 = 0 % over 0 tests" or "e^2 = 100 %" with exit 0.
      {"bad_header_only.csv", "bad_header_only.csv:1: a header and no samples"},
      {"bad_constant_force.csv", "test 'u=50': the force is 3 throughout"},
      {"bad_constant_displacement.csv", "test 'u=0': the displacement is 7 throughout"},
      // Two elastoplastic components and a trilinear spring: 3 shape coordinates (uy, uy, uyh)
      // and 4 stiffnesses (k0, k0, k1, k2) cannot be determined by 6 samples.
      {"bad_six_samples.csv",
       "7 parameters to identify (3 shape coordinates and 4 stiffnesses) from 6 samples"},
  };
  for (const Case& c : cases) {
    const auto output = TemporaryFile("bad.yaml");
    const auto run = RunIsolab("fit " + Data(c.file) + " --model " + Data("three_laws_spec.yaml") +
                                   " -q -o " + output.string(),
                               true);
    EXPECT_EQ(run.exit_code, 2) << c.file << ": " << run.output;
    EXPECT_NE(run.output.find(c.message), std::string::npos) << c.file << ": " << run.output;
    EXPECT_FALSE(std::filesystem::exists(output)) << c.file;
  }
  // One file given twice, spelled two ways: its tests were fitted twice and the fitted model's
  // range said twice as many cycles.
  const std::string once = Data("bad_header_only.csv");
  const std::string again =
      (std::filesystem::path(once).parent_path() / "." / "bad_header_only.csv").string();
  const auto twice = RunIsolab(
      "fit " + once + " " + again + " --model " + Data("three_laws_spec.yaml") + " -q", true);
  EXPECT_EQ(twice.exit_code, 2) << twice.output;
  EXPECT_NE(twice.output.find(again + ": is '" + once + "' given again"), std::string::npos)
      << twice.output;
}

TEST(FitCommand, AComponentFittedToZeroIsDroppedWithANoteAndTheModelWritten) {
  // A linear spring's data (F = 0.5 u) need only the trilinear spring (k1 = k2 = 0.5): an
  // elastoplastic component gets no stiffness. The fit drops it with a note and writes the rest,
  // a model isolab cyclic reads, rather than refusing the whole fit.
  const auto output = isolab::testing::OwnTestFile("linear_spring.fitted.yaml");
  std::filesystem::remove(output);
  const auto run = RunIsolab("fit " + Data("linear_spring.csv") + " --model " +
                             Data("three_laws_spec.yaml") + " --budget 300 -o " + output.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("(elastoplastic) was dropped: the fit gave it no stiffness"),
            std::string::npos)
      << run.output;
  ASSERT_TRUE(std::filesystem::exists(output));
  const auto cyclic = RunIsolab("cyclic " + output.string() + " -a 50 --json");
  EXPECT_EQ(cyclic.exit_code, 0) << cyclic.output;
}

TEST(FitCommand, DataWithoutUnitsAreRefusedUnlessTheCommandLineGivesThem) {
  // Read silently as kN and mm, data in kip and in would give k0 5.7 times too large with the
  // same e^2: a file without a units line needs both units on the command line.
  const auto bare = TemporaryFile("no_units.csv");
  {
    std::ifstream in(Data("linear_spring.csv"));
    std::ofstream out(bare);
    for (std::string line; std::getline(in, line);) {
      if (line.rfind("#", 0) != 0) out << line << "\n";
    }
  }
  const auto output = TemporaryFile("no_units.yaml");
  const std::string command = "fit " + bare.string() + " --model " + Data("three_laws_spec.yaml") +
                              " --budget 300 -q -o " + output.string();
  auto run = RunIsolab(command, true);
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("no_units.csv: no '# units: force ..., length ...' line: give the "
                            "data's units in the file or with --force-unit and --length-unit"),
            std::string::npos)
      << run.output;
  EXPECT_FALSE(std::filesystem::exists(output));
  run = RunIsolab(command + " --force-unit kN", true);  // one unit is not enough
  EXPECT_EQ(run.exit_code, 2) << run.output;
  run = RunIsolab(command + " --force-unit kN --length-unit mm --json");
  EXPECT_EQ(run.exit_code, 0) << run.output;

  // A file whose line gives its units takes a unit given beside it only if it is the same one:
  // kN against N would read the forces a thousandfold off, so it is refused at the line.
  const std::string with_line = "fit " + Data("linear_spring.csv") + " --model " +
                                Data("three_laws_spec.yaml") + " --budget 300 -q -o " +
                                output.string();
  run = RunIsolab(with_line + " --force-unit N --length-unit mm", true);
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("linear_spring.csv:1: units: the file's line says force kN, the force "
                            "unit given beside it says N"),
            std::string::npos)
      << run.output;
  std::filesystem::remove(output);
  EXPECT_EQ(RunIsolab(with_line + " --force-unit kN --length-unit mm").exit_code, 0);
}

// The units line names force and length only, the times being seconds: a time unit other than
// seconds (its velocities would be off), a part it does not know and a unit isolab does not know
// are refused at the line itself, and nothing is written.
TEST(FitCommand, AUnitsLineNamingAnotherTimeUnitOrAnUnknownPartIsRefusedAtItsLine) {
  std::ifstream in(Data("linear_spring.csv"));
  std::string first, rest;
  std::getline(in, first);
  rest.assign(std::istreambuf_iterator<char>(in), {});
  const auto output = TemporaryFile("units_line.yaml");
  for (const auto& [line, message] :
       {std::pair{"# units: force kN, length mm, time fortnight",
                  "units: time fortnight: the file's times are read in seconds"},
        std::pair{"# units: force kN, length mm, time ms",
                  "units: time ms: the file's times are read in seconds"},
        std::pair{"# units: force kN, length mm, mass t",
                  "units: 'mass t' is not a part the line names"},
        std::pair{"# units: force kN, length furlong", "units: unknown unit 'furlong'"}}) {
    const auto data = TemporaryFile("units_line.csv");
    std::ofstream(data) << line << "\n" << rest;
    const auto run = RunIsolab("fit " + data.string() + " --model " + Data("three_laws_spec.yaml") +
                                   " --budget 300 -q -o " + output.string(),
                               true);
    EXPECT_EQ(run.exit_code, 2) << line << ": " << run.output;
    EXPECT_NE(run.output.find("units_line.csv:1: " + std::string(message)), std::string::npos)
        << line << ": " << run.output;
    EXPECT_FALSE(std::filesystem::exists(output)) << line;
  }
  const auto seconds = TemporaryFile("units_line_seconds.csv");
  std::ofstream(seconds) << "# units: force kN, length mm, time s\n" << rest;
  EXPECT_EQ(RunIsolab("fit " + seconds.string() + " --model " + Data("three_laws_spec.yaml") +
                      " --budget 300 -q -o " + output.string())
                .exit_code,
            0);
}

TEST(FitCommand, BuildingOptionsAreRefusedToCyclicTests) {
  // --offsets reads shake-table accelerometers and --global-budget splits a building fit's
  // search: a cyclic fit has neither, and would ignore them.
  const auto output = TemporaryFile("offsets.yaml");
  for (const std::string option :
       {"--offsets none", "--global-budget 500", "--cross-validate", "--model-form"}) {
    const auto run =
        RunIsolab("fit " + Data("linear_spring.csv") + " --model " + Data("three_laws_spec.yaml") +
                      " " + option + " -q -o " + output.string(),
                  true);
    EXPECT_EQ(run.exit_code, 2) << run.output;
    EXPECT_NE(run.output.find(option.substr(0, option.find(' ')) +
                              " applies to --building, not to cyclic tests"),
              std::string::npos)
        << run.output;
    EXPECT_FALSE(std::filesystem::exists(output));
  }
}

TEST(FitCommand, DataBeyondWhatSquaresHoldAreLocated) {
  const auto huge = TemporaryFile("huge.csv");
  {
    std::ifstream in(Data("linear_spring.csv"));
    std::ofstream out(huge);
    int row = 0;
    for (std::string line; std::getline(in, line);) {
      if (line.rfind("u=50,", 0) == 0 && ++row == 3)
        line = line.substr(0, line.rfind(',')) + ",1e300";
      out << line << "\n";
    }
  }
  const auto run = RunIsolab("fit " + huge.string() + " --model " + Data("three_laws_spec.yaml") +
                                 " -q -o " + TemporaryFile("huge.yaml").string(),
                             true);
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("huge.csv: test 'u=50': column 'force' reaches 1e+300"),
            std::string::npos)
      << run.output;
}

TEST(FitCommand, WorkBeyondTheLimitIsRefusedBeforeTheFitAndSaidOtherwise) {
  const std::string spec = " --model " + Data("three_laws_spec.yaml");
  const auto output = TemporaryFile("work.yaml");
  // 60,001 samples, two laws run per evaluation (the elastoplastic elements; the trilinear
  // spring is a clamp of u): 10^7 evaluations are 1.2e12 sample-law runs, beyond 1e11.
  const auto dense = TemporaryFile("dense.csv");
  ASSERT_EQ(RunIsolab("cyclic " + Data("three_laws.yaml") +
                      " -a 50 -T 2 -n 3 --steps-per-cycle 20000 --test-data " + dense.string())
                .exit_code,
            0);
  auto run = RunIsolab(
      "fit " + dense.string() + spec + " --budget 10000000 -q -o " + output.string(), true);
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("work: up to 10000000 evaluations x 60001 samples x 2 laws = 1.2e+12"),
            std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("beyond the limit"), std::string::npos) << run.output;
  EXPECT_FALSE(std::filesystem::exists(output));
  // Within it, the estimate goes to stderr before the fit starts.
  run = RunIsolab("fit " + Data("linear_spring.csv") + spec + " --budget 300 -o " + output.string(),
                  true);
  EXPECT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("work: up to 300 evaluations x 41 samples x 2 laws"), std::string::npos)
      << run.output;
}

TEST(FitCommand, BadSpecificationsAreLocatedBeforeTheFit) {
  // They used to fail inside the fit ("internal error: uy = -3.6 (must be > 0)", exit 1), or be
  // clamped silently (a start outside its bounds), or allocate without end (count: 999999999).
  struct Case {
    std::string component, message;
  };
  const Case cases[] = {
      {"{type: elastoplastic, bounds: {uy: [-5, 10]}}",
       "spec.yaml:3:41: components[0].bounds.uy[0]: uy = -5 (must be > 0)"},
      {"{type: elastoplastic, fixed: {uy: -3}}",
       "spec.yaml:3:39: components[0].fixed.uy: uy = -3 (must be > 0)"},
      {"{type: elastoplastic, start: {uy: 500}, bounds: {uy: [1, 10]}}",
       "spec.yaml:3:39: components[0].start.uy: 500 is outside its bounds [1, 10]"},
      {"{type: thm1, bounds: {k1_ratio: [0.1, 3]}}",
       "spec.yaml:3:43: components[0].bounds.k1_ratio[1]: k1_ratio = 3 (must be < 1)"},
      {"{type: degrading_bhm2, fixed: {loss: 1}}",
       "spec.yaml:3:42: components[0].fixed.loss: loss = 1 (must be in [0, 1))"},
      {"{type: elastoplastic, count: 999999999}",
       "spec.yaml:3:34: components[0].count: 999999999 (must be 1 to 100"},
      // A fixed coordinate's bounds or start would be dropped; a name used twice was refused
      // only after the whole fit, as if the data had asked for it.
      {"{type: elastoplastic, fixed: {uy: 8}, bounds: {uy: [1, 3]}}",
       "spec.yaml:3:39: components[0].fixed.uy: 8 fixes it, and bounds.uy is given too"},
      {"{type: elastoplastic, fixed: {uy: 8}, start: {uy: 3}}",
       "spec.yaml:3:39: components[0].fixed.uy: 8 fixes it, and start.uy is given too"},
      {"{type: bhm2, name: a}\n  - {type: elastoplastic, name: a}",
       "spec.yaml:4:33: components[1].name: 'a' names component 1 already"},
      {"{type: bhm2, count: 2, name: a}\n  - {type: elastoplastic, name: a1}",
       "spec.yaml:4:33: components[1].name: 'a1' names component 1 already"},
  };
  const auto output = isolab::testing::OwnTestFile("bad_spec.fitted.yaml");
  for (const Case& c : cases) {
    const auto spec = isolab::testing::OwnTestFile("spec.yaml");
    std::ofstream(spec) << "units: {force: kN, length: mm}\ncomponents:\n  - " << c.component
                        << "\n";
    const auto run = RunIsolab("fit " + Data("linear_spring.csv") + " --model " + spec.string() +
                                   " --budget 300 -q -o " + output.string(),
                               true);
    EXPECT_EQ(run.exit_code, 2) << c.component << ": " << run.output;
    EXPECT_NE(run.output.find(c.message), std::string::npos) << c.component << ": " << run.output;
    EXPECT_FALSE(std::filesystem::exists(output)) << c.component;
  }
}

// A force-driven test fitted through the command (spec `input: force`): the Bouc-Wen benchmark's
// sine sweep (bundled) as a cyclic-test file, its spring and dashpot started off, come back at
// the benchmark's published values (k = 5e4 N/m, c = 10 N s/m); what does not apply is refused.
TEST(FitCommand, AForceDrivenTestIsFittedAsTheBenchmarkStatesIt) {
  const auto data = WriteSweepTest();
  const auto spec = [](const std::string& extra, const std::string& substeps = "4") {
    const auto path = TemporaryFile("force_spec.yaml");
    std::ofstream(path) << "model: boucwen.yaml\ninput: force\nsubsteps: " << substeps
                        << "\nparameters:\n"
                           "  - {name: isolation.k.k, start: 3.5e4}\n"
                           "  - {name: isolation.c.c, start: 15}\n"
                        << extra;
    return path.string();
  };
  const auto fitted = TemporaryFile("force.fitted.yaml");
  const auto run = RunIsolab("fit " + data.string() + " --building " + spec("") +
                             " --budget 300 --json -q -o " + fitted.string());
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto json = nlohmann::json::parse(run.output);
  EXPECT_NEAR(json["parameters"][0]["value"].get<double>() / 5e4, 1.0, 0.01);
  EXPECT_NEAR(json["parameters"][1]["value"].get<double>() / 10.0, 1.0, 0.1);
  EXPECT_EQ(json["channels"][0]["channel"], "d1");
  EXPECT_EQ(json["stop"], "converged") << json["stop_reason"];
  // A global stage below CMA-ES's least or leaving the refinement less than its first Jacobian
  // and step (2 x 2 + 2 of the budget) is refused by its option's name, nothing written.
  const auto refused = TemporaryFile("refused.fitted.yaml");
  for (const std::string option : {"--global-budget 50", "--global-budget 295"}) {
    const auto bad = RunIsolab("fit " + data.string() + " --building " + spec("") +
                                   " --budget 300 " + option + " -q -o " + refused.string(),
                               true);
    EXPECT_EQ(bad.exit_code, 2) << bad.output;
    EXPECT_NE(bad.output.find("--global-budget"), std::string::npos) << bad.output;
    EXPECT_FALSE(std::filesystem::exists(refused));
  }
  EXPECT_LT(json["channels"][0]["nrmse"].get<double>(), 0.005);
  EXPECT_EQ(isolab::model::LoadModelFile(fitted.string()).identified_range->data,
            std::vector<std::string>{"sweep"});

  struct Case {
    std::string extra, options, message, substeps = "4";
  };
  const Case cases[] = {
      {"channels: [a1]\n", "", "channel a1 is not measured"},
      {"", "--offsets pre-event", "--offsets applies to shake-table motions"},
      {"", "--cycles 2", "--cycles applies to cyclic tests"},
      {"", "", "force_spec.yaml:3:11: substeps: must be >= 1", "0"},
      {"  - isolation.k.k\n", "", "'isolation.k.k' is fitted twice (also parameters[0])"},
      // Priors: given, so never fitted; a sigma of a factor 10 or more, a value not > 0 and a
      // prior without its source are refused where they are.
      {"priors:\n  - {name: isolation.k.k, sigma: 0.1, source: x}\n", "",
       "priors[0].name: 'isolation.k.k' is fitted: a prior gives what the fit does not"},
      {"priors:\n  - {name: isolation.z.gamma, sigma: 3, source: x}\n", "",
       "priors[0].sigma: must be in (0, ln 10 = 2.303]"},
      {"priors:\n  - {name: isolation.z.gamma, value: -1, sigma: 0.1, source: x}\n", "",
       "priors[0].value: must be > 0"},
      {"priors:\n  - {name: isolation.z.gamma, sigma: 0.1}\n", "",
       "priors[0]: missing key 'source'"},
      {"priors:\n  - {name: isolation.z.no_such, sigma: 0.1, source: x}\n", "",
       "force_spec.yaml:8:12: priors[0].name: parameter 'isolation.z.no_such'"},
      // What only the model can check is said at the specification's line, not the model's.
      {"  - isolation.no_such.k\n", "",
       "force_spec.yaml:7:5: parameters[2].name: parameter 'isolation.no_such.k'"},
      {"channels: [d9]\n", "", "force_spec.yaml:7:12: channels[0]: d9: the model"},
      {"channels: [x9]\n", "", "force_spec.yaml:7:12: channel 'x9': expected d<level>"},
      // One motion twice: its data counted twice, or held out and fitted at once.
      {"", data.string(), "given twice (also as " + data.string() + ")"},
  };
  for (const Case& c : cases) {
    const auto refused = TemporaryFile("refused.yaml");
    const auto bad = RunIsolab("fit " + data.string() + " --building " + spec(c.extra, c.substeps) +
                                   " --budget 300 -q -o " + refused.string() + " " + c.options,
                               true);
    EXPECT_EQ(bad.exit_code, 2) << c.message << ": " << bad.output;
    EXPECT_NE(bad.output.find(c.message), std::string::npos) << bad.output;
    EXPECT_FALSE(std::filesystem::exists(refused)) << c.message;
  }
  // A prior holds the Bouc-Wen's gamma at a value from outside the data (0.7, the model's 0.8)
  // through the fit; the fitted model carries it with its sigma and source, and the JSON says so.
  const auto held = TemporaryFile("held.fitted.yaml");
  const auto with_prior = RunIsolab(
      "fit " + data.string() + " --building " +
      spec("priors:\n  - {name: isolation.z.gamma, value: 0.7, sigma: 0.1, source: the vendor's "
           "test}\n") +
      " --budget 300 --json -q -o " + held.string());
  ASSERT_EQ(with_prior.exit_code, 0) << with_prior.output;
  const auto prior_json = nlohmann::json::parse(with_prior.output);
  ASSERT_EQ(prior_json["priors"].size(), 1u);
  EXPECT_EQ(prior_json["priors"][0]["name"], "isolation.z.gamma");
  EXPECT_EQ(prior_json["priors"][0]["value"].get<double>(), 0.7);
  EXPECT_EQ(prior_json["priors"][0]["source"], "the vendor's test");
  const auto held_model = isolab::model::LoadModelFile(held.string());
  ASSERT_EQ(held_model.uncertainty->priors.size(), 1u);
  EXPECT_EQ(held_model.uncertainty->priors[0].sigma, 0.1);
  EXPECT_EQ(held_model.isolation.components()[1].parameters.Values(
                isolab::hysteresis::ParameterForm::kMathematical)[2],
            0.7);

  const auto shaker = TemporaryFile("shaker_spec.yaml");
  std::ofstream(shaker) << "model: boucwen.yaml\ninput: shaker\nparameters: [isolation.k.k]\n";
  const auto word =
      RunIsolab("fit " + data.string() + " --building " + shaker.string() + " -q", true);
  EXPECT_EQ(word.exit_code, 2);
  EXPECT_NE(word.output.find("shaker_spec.yaml:2:8: input: 'shaker': expected table"),
            std::string::npos)
      << word.output;
}

// A fit's output with what may differ between two runs of one fit taken out: where it was written
// and how long it took.
nlohmann::json WithoutPlaceAndTime(const std::string& output) {
  nlohmann::json json = nlohmann::json::parse(output);  // one document: rank 0 alone prints
  json.erase("output");
  json.erase("seconds");
  return json;
}

std::string ReadFile(const std::filesystem::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Under mpirun a fit's islands and Jacobian columns spread over the ranks
// (identification/task_spread.h): each rank ends with the result one process finds, and rank 0
// alone prints and writes it. Cyclic tests (CMA-ES islands and the polish) and a building fit
// (islands, then the least-squares refinement's Jacobians) on 2 ranks and on 3 (more ranks than
// islands: one owns none) give the same model file and the same numbers as one process on one
// thread and on every thread; so does a diagnosis, whose fits run one after another.
TEST(FitCommand, OnMpiRanksAFitGivesWhatOneProcessGives) {
  ASSERT_EQ(isolab::testing::RunShell("command -v mpirun").exit_code, 0)
      << "no mpirun: install openmpi-bin (scripts/setup.sh does)";
  const std::string cyclic = GenerateTests(0.01) + " --model " + Data("three_laws_spec.yaml") +
                             " --budget 3000 --seed 11 --json -q";
  const auto sweep = WriteSweepTest();
  const auto spec = TemporaryFile("ranks_spec.yaml");
  std::ofstream(spec) << "model: boucwen.yaml\ninput: force\nsubsteps: 4\nparameters:\n"
                         "  - {name: isolation.k.k, start: 3.5e4}\n"
                         "  - {name: isolation.c.c, start: 15}\n"
                         "  - {name: isolation.z.gamma, start: 0.5}\n";
  // A budget with room for a global stage (two islands) before the refinement.
  const std::string building =
      sweep.string() + " --building " + spec.string() + " --budget 1500 --json -q";
  for (const std::string& fit : {cyclic, building}) {
    const auto one = TemporaryFile("one.fitted.yaml");
    const auto alone = RunIsolab("fit " + fit + " --threads 1 -o " + one.string());
    ASSERT_EQ(alone.exit_code, 0) << alone.output;
    const nlohmann::json expected = WithoutPlaceAndTime(alone.output);
    const std::string expected_model = ReadFile(one);
    if (fit == building) {
      EXPECT_NE(expected["stop_reason"].get<std::string>().find("global search: "),
                std::string::npos)
          << "the building fit is to run its islands too: " << expected["stop_reason"];
    }
    const auto threads = TemporaryFile("threads.fitted.yaml");
    const auto threaded = RunIsolab("fit " + fit + " -o " + threads.string());
    ASSERT_EQ(threaded.exit_code, 0) << threaded.output;
    EXPECT_EQ(WithoutPlaceAndTime(threaded.output), expected);
    for (const int ranks : {2, 3}) {
      const auto spread = TemporaryFile("ranks" + std::to_string(ranks) + ".fitted.yaml");
      const auto run = isolab::testing::RunShell("mpirun --allow-run-as-root --oversubscribe -np " +
                                                 std::to_string(ranks) + " " + ISOLAB_BINARY +
                                                 " fit " + fit + " -o " + spread.string());
      ASSERT_EQ(run.exit_code, 0) << ranks << " ranks: " << run.output;
      EXPECT_EQ(WithoutPlaceAndTime(run.output), expected) << ranks << " ranks";
      EXPECT_EQ(ReadFile(spread), expected_model) << ranks << " ranks";
    }
  }
  // Without -q, rank 0 alone says the fit's progress (its first line, once).
  const auto said = isolab::testing::RunCommandLine(
      "mpirun --allow-run-as-root --oversubscribe -np 2 " + std::string(ISOLAB_BINARY) + " fit " +
      GenerateTests(0.01) + " --model " + Data("three_laws_spec.yaml") + " --budget 1000 -o " +
      TemporaryFile("said.fitted.yaml").string() + " 2>&1 >/dev/null");
  ASSERT_EQ(said.exit_code, 0) << said.output;
  const auto head = said.output.find("isolab fit: ");
  ASSERT_NE(head, std::string::npos) << said.output;
  EXPECT_EQ(said.output.find("isolab fit: ", head + 1), std::string::npos) << said.output;
  // diagnose runs its fits one after another, each spread alike: the report, its files and the
  // final model are those of one process (the paths and the time aside).
  const auto diagnose = [](const std::string& launcher, const std::string& folder) {
    const auto out = TemporaryFile(folder + "/diagnosis");
    std::filesystem::create_directories(out.parent_path());
    const auto run = isolab::testing::RunShell(
        launcher + std::string(ISOLAB_BINARY) + " diagnose " + GenerateTests(0.01) + " --base " +
        Data("three_laws_spec.yaml") + " --budget 2000 --json -q --no-plot --out " + out.string());
    EXPECT_EQ(run.exit_code, 0) << launcher << run.output;
    nlohmann::json json = WithoutPlaceAndTime(run.output);
    for (const char* path : {"final_model_file", "residual_file"}) json.erase(path);
    return std::pair{json, ReadFile(out.string() + ".model.yaml")};
  };
  const auto [alone_json, alone_model] = diagnose("", "alone");
  const auto [ranks_json, ranks_model] =
      diagnose("mpirun --allow-run-as-root --oversubscribe -np 2 ", "ranks");
  EXPECT_EQ(ranks_json, alone_json);
  EXPECT_EQ(ranks_model, alone_model);
  EXPECT_FALSE(alone_model.empty());
}

}  // namespace
