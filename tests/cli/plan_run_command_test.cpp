// `isolab run` on a plan model, end to end: the bundled Table 9 building in plan, reduced to a
// symmetric building on uncoupled bearings under H1 alone, gives the one-direction model's own
// `isolab run` peaks (the reader, the set-up and the results path included); the full example
// writes its HDF5 layout (docs/results.md) whose datasets agree with each other and with the
// printed summary; IDA runs it and agrees with Newmark; one-direction options are refused.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
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

const std::string kRoot = ISOLAB_SOURCE_DIR;
const std::string kPlan = kRoot + "/models/plan/five_story_table9_plan.yaml";

std::vector<double> Doubles(const std::string& path, const char* name) {
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  std::vector<double> values;
  if (file >= 0 && H5Lexists(file, name, H5P_DEFAULT) > 0) {
    const hid_t dataset = H5Dopen2(file, name, H5P_DEFAULT);
    const hid_t space = H5Dget_space(dataset);
    values.resize(H5Sget_simple_extent_npoints(space));
    H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    H5Sclose(space);
    H5Dclose(dataset);
  }
  if (file >= 0) H5Fclose(file);
  return values;
}

TEST(PlanRunCommand, SymmetricUncoupledUnderOneComponentGivesTheOneDirectionPeaks) {
  std::string text = ReadText(kPlan);
  ReplaceOnce(&text, "      components: &table9",
              "      coupling: uncoupled\n      components: &table9");
  for (int i = 0; i < 3; ++i) {
    ReplaceOnce(&text, "components: *table9}", "coupling: uncoupled, components: *table9 }");
  }
  ReplaceOnce(&text, "base: {mass: 100 t, centre_of_mass: [13200, 8000]}",
              "base: {mass: 100 t, centre_of_mass: [12000, 8000]}");
  ReplaceOnce(&text, "    centre_of_mass: [13200, 8000]\n", "    centre_of_mass: [12000, 8000]\n");
  ReplaceOnce(&text, "    h2: {file: ../../ground_motions/h2_fwn_firm_seed3.at2, scale: 0.6}\n",
              "");
  ReplaceOnce(&text, "../../ground_motions/", kRoot + "/ground_motions/");
  // The one-direction model's Rayleigh damping is on its first two fixed-base modes: the plan
  // model's on those periods, to the last digit.
  const std::string folder = OwnTestDirectory().string() + "/";
  const Outcome one = RunIsolab(
      "run " + kRoot + "/models/buildings/five_story_table9.yaml --json -o " + folder + "one.h5");
  ASSERT_EQ(one.exit_code, 0) << one.output;
  const auto o = nlohmann::json::parse(one.output);
  const auto& periods = o["model_summary"]["fixed_base_periods"];
  ReplaceOnce(&text, "periods: [0.4004, 0.1372]",
              "periods: [" + periods[0].dump() + ", " + periods[1].dump() + "]");
  const std::string model = folder + "symmetric_plan.yaml";
  std::ofstream(model) << text;
  const Outcome plan = RunIsolab("run " + model + " --json -o " + folder + "plan.h5");
  ASSERT_EQ(plan.exit_code, 0) << plan.output;
  const auto p = nlohmann::json::parse(plan.output);
  const double expected = o["peaks"]["isolator_displacement"]["value"];
  ASSERT_GT(expected, 100.0);
  ASSERT_EQ(p["isolators"].size(), 4u);
  for (const auto& [name, isolator] : p["isolators"].items()) {
    EXPECT_NEAR(isolator["displacement"]["value"].get<double>(), expected, 1e-9 * expected) << name;
  }
  EXPECT_NEAR(p["peaks"]["base_centre_displacement"]["value"].get<double>(), expected,
              1e-9 * expected);
  EXPECT_NEAR(p["torsional_amplification"].get<double>(), 1.0, 1e-12);
  // Four bearings, each the one-direction model's tributary bearing: four times its base shear.
  EXPECT_NEAR(p["peaks"]["base_shear"]["value"].get<double>(),
              4.0 * o["peaks"]["base_shear"]["value"].get<double>(), 1e-8 * 4.0 * expected);
  // The superstructure too: the same drifts, the same roof acceleration.
  for (const char* peak : {"story_drift", "roof_absolute_acceleration", "first_story_shear"}) {
    const double one_peak = o["peaks"][peak]["value"];
    const double scale = std::string(peak) == "first_story_shear" ? 4.0 : 1.0;
    EXPECT_NEAR(p["peaks"][peak]["value"].get<double>(), scale * one_peak, 1e-8 * scale * one_peak)
        << peak;
  }
  EXPECT_NEAR(p["residual_isolator_displacement"].get<double>(),
              o["residual_isolator_displacement"].get<double>(), 1e-8 * expected);
  EXPECT_NEAR(p["energy_balance_error"].get<double>(), o["energy_balance_error"].get<double>(),
              1e-9);
}

// Nothing moves under a record of zeros: every peak is 0 at t = 0 (no peak index is left unset),
// the torsional amplification of a base that does not move is 0, and the run completes, in text,
// JSON and CSV.
TEST(PlanRunCommand, AZeroRecordMovesNothingAndCompletes) {
  const std::string folder = OwnTestDirectory().string() + "/zero_";
  {
    std::ofstream record(folder + "record.txt");
    for (int k = 0; k < 3000; ++k) record << "0\n";
  }
  const std::string run = "run " + kPlan + " --record " + folder + "record.txt" +
                          " --record-dt 0.01 --units g -q -o " + folder + "out.csv";
  const Outcome text = RunIsolab(run);
  EXPECT_EQ(text.exit_code, 0) << text.output;
  EXPECT_NE(text.output.find("peak floor rotation"), std::string::npos) << text.output;
  const Outcome json = RunIsolab(run + " --json");
  ASSERT_EQ(json.exit_code, 0) << json.output;
  const nlohmann::json summary = nlohmann::json::parse(json.output);
  EXPECT_EQ(summary["termination"], "completed");
  for (const char* peak : {"isolator_displacement", "floor_rotation", "base_shear",
                           "roof_absolute_acceleration", "story_drift"}) {
    EXPECT_EQ(summary["peaks"][peak]["value"], 0.0) << peak;
    EXPECT_EQ(summary["peaks"][peak]["time"], 0.0) << peak;
  }
  EXPECT_EQ(summary["torsional_amplification"], 0.0);
}

TEST(PlanRunCommand, WritesItsLayoutAndTheSummaryAgreesWithIt) {
  const std::string output = OwnTestFile("five_story_table9_plan.h5").string();
  const Outcome run = RunIsolab("run " + kPlan + " --json -o " + output);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto summary = nlohmann::json::parse(run.output);
  EXPECT_LT(summary["energy_balance_error"].get<double>(), 1e-3);
  const std::vector<double> time = Doubles(output, "time");
  const std::vector<double> resultant = Doubles(output, "isolator/resultant");
  const std::vector<double> displacement = Doubles(output, "isolator/displacement");
  const std::vector<double> peaks = Doubles(output, "peaks/isolators/displacement");
  ASSERT_EQ(peaks.size(), 4u);
  ASSERT_EQ(resultant.size(), 4 * time.size());
  ASSERT_EQ(displacement.size(), 8 * time.size());
  for (std::size_t i = 0; i < 4; ++i) {
    double peak = 0.0;
    for (std::size_t row = 0; row < time.size(); ++row) {
      const double r = resultant[4 * row + i];
      EXPECT_NEAR(r, std::hypot(displacement[8 * row + 2 * i], displacement[8 * row + 2 * i + 1]),
                  1e-12 * (1.0 + r));
      peak = std::max(peak, r);
    }
    EXPECT_DOUBLE_EQ(peaks[i], peak);
  }
  // The eccentric building twists: the corner farthest from the centre of stiffness on the side
  // of the centre of mass moves most (ne or se), more than the base's centre of mass.
  const double amplification = summary["torsional_amplification"];
  EXPECT_GT(amplification, 1.01);
  EXPECT_DOUBLE_EQ(
      *std::max_element(peaks.begin(), peaks.end()),
      amplification * summary["peaks"]["base_centre_displacement"]["value"].get<double>());
  EXPECT_EQ(Doubles(output, "rotation").size(), 6 * time.size());
  EXPECT_EQ(Doubles(output, "displacement").size(), 12 * time.size());
  EXPECT_EQ(Doubles(output, "story/drift").size(), 10 * time.size());
  EXPECT_EQ(Doubles(output, "story/twist").size(), 5 * time.size());
  EXPECT_EQ(Doubles(output, "energy/hysteretic").size(), time.size());
}

// A building in plan takes what a one-direction building takes: its own record replaced
// (--record, and --record-h2), CSV results.
TEST(PlanRunCommand, TakesReplacedRecordsAndWritesCsv) {
  const std::string record = kRoot + "/ground_motions/pulse_tp2.at2";
  const Outcome one = RunIsolab("run " + kPlan + " --record " + record + " --json -o " +
                                OwnTestFile("x.h5").string());
  ASSERT_EQ(one.exit_code, 0) << one.output;
  const auto summary = nlohmann::json::parse(one.output);
  EXPECT_EQ(summary["record"].get<std::string>(), record);
  EXPECT_FALSE(summary.contains("h2"));
  const Outcome h2_alone = RunIsolab("run " + kPlan + " --record-h2 " + record, true);
  EXPECT_EQ(h2_alone.exit_code, 2);
  EXPECT_NE(h2_alone.output.find("--record-h2: needs --record"), std::string::npos)
      << h2_alone.output;
  const std::string csv = OwnTestFile("x.csv").string();
  const Outcome written = RunIsolab("run " + kPlan + " --summary-only -o " + csv);
  EXPECT_EQ(written.exit_code, 0) << written.output;
  EXPECT_NE(ReadText(csv).find("# peak floor_rotation: "), std::string::npos);
}

// The bundled plan model on lighter bearings (one coupled BHM2 each, so that IDA's run takes a
// few seconds), run by `isolab run --integrator ida` and by Newmark at a fifth of the model's step:
// the two integrators' peaks agree (plan_ida_test.cpp checks them in depth), IDA's statistics
// and the integrator's description reach the JSON summary.
TEST(PlanRunCommand, IdaAgreesWithNewmarkAndReportsItself) {
  std::string text = ReadText(kPlan);
  const std::size_t first = text.find("      components: &table9");
  const std::size_t last = text.find("    - {name: se,");
  ASSERT_NE(first, std::string::npos);
  ASSERT_NE(last, std::string::npos);
  text.replace(first, last - first,
               "      components: &table9\n"
               "        - {name: rubber, type: bhm2, k0: 6, k1: 0.6, uy: 10}\n");
  ReplaceOnce(&text, "../../ground_motions/", kRoot + "/ground_motions/");
  ReplaceOnce(&text, "../../ground_motions/", kRoot + "/ground_motions/");
  const std::string folder = FreshTestDirectory().string() + "/";
  const std::string model = folder + "light_bearings.yaml";
  std::ofstream(model) << text;
  const std::string common = "run " + model + " --free-vibration 5 --json";
  const Outcome ida = RunIsolab(common + " --integrator ida -o " + folder + "ida.h5");
  const Outcome newmark = RunIsolab(common + " --dt 0.001 -o " + folder + "newmark.h5");
  ASSERT_EQ(ida.exit_code, 0) << ida.output;
  ASSERT_EQ(newmark.exit_code, 0) << newmark.output;
  const auto i = nlohmann::json::parse(ida.output);
  const auto n = nlohmann::json::parse(newmark.output);
  for (const auto& [name, isolator] : i["isolators"].items()) {
    const double peak = isolator["displacement"]["value"];
    EXPECT_GT(peak, 50.0) << name;  // far past the bearings' yield
    EXPECT_NEAR(n["isolators"][name]["displacement"]["value"].get<double>() / peak, 1.0, 0.002)
        << name;
  }
  EXPECT_NEAR(n["torsional_amplification"].get<double>(),
              i["torsional_amplification"].get<double>(), 0.002);
  EXPECT_LT(i["energy_balance_error"].get<double>(), 1e-4);  // measured 3.0e-5
  EXPECT_GT(i["ida"]["events"].get<long>(), 10);
  EXPECT_EQ(i["integrator"].get<std::string>().rfind("ida rtol=1e-06", 0), 0u) << i["integrator"];
  EXPECT_TRUE(n.contains("newton"));
}

// The least axial loads and the uplift under /peaks (docs/axial_load.md): a 400 t block on four
// friction pendulums under a_v = 1.3 g sin(2 pi t), which lifts it off while sin(2 pi t) <
// -1 / 1.3. The file holds the JSON summary's values, and they are those of the file's own
// histories: the least N and its time from /isolator/axial_load, the first time N <= 0; the static
// share m g / 4, and the uplift's duration (pi - 2 asin(1 / 1.3)) / (2 pi) of each second.
TEST(PlanRunCommand, WritesTheAxialLoadPeaksTheSummaryPrints) {
  constexpr double kG = 9.80665, kDt = 0.005, kPi = 3.14159265358979323846;
  const std::string folder = FreshTestDirectory().string() + "/";
  const auto record = [&](const std::string& name, double amplitude, double frequency) {
    std::ofstream out(folder + name);
    out.precision(17);
    for (int k = 0; k <= 800; ++k) {
      out << k * kDt << " " << amplitude * std::sin(2.0 * kPi * frequency * k * kDt) << "\n";
    }
  };
  record("h1.txt", 3.0, 0.5);
  record("v.txt", 1.3 * kG, 1.0);
  std::ofstream(folder + "block.yaml")
      << "units: {force: kN, length: m, time: s}\n"
         "plan:\n"
         "  footprint: [[-5, -3], [5, 3]]\n"
         "  base: {mass: 400 t, centre_of_mass: [0, 0], radius_of_gyration: 3}\n"
         "  isolators:\n"
         "    - {name: sw, position: [-4, -2], components: &fp [{name: fp, type: "
         "friction_pendulum, w: 981, r: 2, mu: 0.05, uy: 0.0005}]}\n"
         "    - {name: se, position: [4, -2], components: *fp}\n"
         "    - {name: nw, position: [-4, 2], components: *fp}\n"
         "    - {name: ne, position: [4, 2], components: *fp}\n"
         "excitation:\n"
         "  ground_motion:\n"
         "    h1: {file: h1.txt, units: m/s^2}\n"
         "    v: {file: v.txt, units: m/s^2}\n"
         "analysis: {dt: 0.005, free_vibration: 0}\n"
         "axial_load: {vertical: true}\n";
  const std::string output = folder + "block.h5";
  const Outcome run = RunIsolab("run " + folder + "block.yaml --json -o " + output);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto summary = nlohmann::json::parse(run.output);
  const std::vector<double> time = Doubles(output, "time");
  const std::vector<double> axial = Doubles(output, "isolator/axial_load");
  ASSERT_EQ(axial.size(), 4 * time.size());
  const std::vector<double> statics = Doubles(output, "peaks/axial_loads/static");
  const std::vector<double> minima = Doubles(output, "peaks/axial_loads/minimum");
  const std::vector<double> minimum_times = Doubles(output, "peaks/axial_loads/minimum_time");
  const std::vector<double> durations = Doubles(output, "peaks/axial_loads/uplift_duration");
  const std::vector<double> firsts = Doubles(output, "peaks/axial_loads/first_uplift");
  ASSERT_EQ(statics.size(), 4u);
  ASSERT_EQ(minima.size(), 4u);
  ASSERT_EQ(minimum_times.size(), 4u);
  ASSERT_EQ(durations.size(), 4u);
  ASSERT_EQ(firsts.size(), 4u);
  const char* names[] = {"sw", "se", "nw", "ne"};
  for (std::size_t j = 0; j < 4; ++j) {
    SCOPED_TRACE(names[j]);
    const nlohmann::json& printed = summary["axial_loads"][names[j]];
    EXPECT_EQ(statics[j], printed["static"].get<double>());
    EXPECT_EQ(minima[j], printed["minimum"]["value"].get<double>());
    EXPECT_EQ(minimum_times[j], printed["minimum"]["time"].get<double>());
    EXPECT_EQ(durations[j], printed["uplift_duration"].get<double>());
    EXPECT_EQ(firsts[j], printed["first_uplift"].get<double>());
    std::size_t least = 0, first = time.size();
    for (std::size_t row = 0; row < time.size(); ++row) {
      if (axial[4 * row + j] < axial[4 * least + j]) least = row;
      if (axial[4 * row + j] <= 0.0 && first == time.size()) first = row;
    }
    EXPECT_EQ(minima[j], axial[4 * least + j]);
    EXPECT_EQ(minimum_times[j], time[least]);
    ASSERT_LT(first, time.size());
    EXPECT_EQ(firsts[j], time[first]);
    EXPECT_NEAR(statics[j], 400.0 * kG / 4.0, 1e-9);
    EXPECT_NEAR(durations[j], 4.0 * (kPi - 2.0 * std::asin(1.0 / 1.3)) / (2.0 * kPi), 4 * 2 * kDt);
  }
}

}  // namespace
}  // namespace isolab::testing
