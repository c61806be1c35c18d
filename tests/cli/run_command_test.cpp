// `isolab run` end to end: the summary, the HDF5 and CSV files, the energy balance of the
// isolated five-story building under El Centro, the record's units and scale as applied, the
// model summary's warnings, the residual displacement after free vibration against a closed
// form, output paths that are refused, and bad input (exit code 2, no output file).
#include <gtest/gtest.h>
#include <hdf5.h>
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>

#include "cli/run_isolab.h"
#include "leftover_temporaries.h"
#include "own_test_file.h"
#include "reference_data.h"

namespace {

using isolab::testing::RunIsolab;

std::string Source(const std::string& relative) {
  return std::string(ISOLAB_SOURCE_DIR) + "/" + relative;
}
std::string Data(const std::string& name) {
  return std::string(ISOLAB_TEST_DATA_DIR) + "/cli/data/" + name;
}

// In a folder of this process's own: ctest runs each test in its own process, several at a time
// (two tests once raced on one /tmp/isolab_run_test/slip.h5).
std::filesystem::path TemporaryFile(const std::string& name) {
  static const std::filesystem::path directory = isolab::testing::FreshTestDirectory();
  const auto path = directory / name;
  std::filesystem::remove(path);
  return path;
}

// Dimensions of a dataset, empty when it is absent.
std::vector<hsize_t> Dimensions(hid_t file, const char* name) {
  if (H5Lexists(file, name, H5P_DEFAULT) <= 0) return {};
  const hid_t dataset = H5Dopen2(file, name, H5P_DEFAULT);
  const hid_t space = H5Dget_space(dataset);
  std::vector<hsize_t> dims(H5Sget_simple_extent_ndims(space));
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  H5Sclose(space);
  H5Dclose(dataset);
  return dims;
}

// A string attribute, read only when HDF5 stores it as a variable-length UTF-8 string (what h5py
// returns as str); empty otherwise.
std::string Utf8Attribute(hid_t file, const char* object, const char* name) {
  std::string text;
  const hid_t attribute = H5Aopen_by_name(file, object, name, H5P_DEFAULT, H5P_DEFAULT);
  if (attribute < 0) return text;
  const hid_t type = H5Aget_type(attribute), space = H5Aget_space(attribute);
  if (H5Tis_variable_str(type) > 0 && H5Tget_cset(type) == H5T_CSET_UTF8 &&
      H5Sget_simple_extent_ndims(space) == 0) {
    char* value = nullptr;
    if (H5Aread(attribute, type, &value) >= 0 && value != nullptr) {
      text = value;
      H5free_memory(value);
    }
  }
  H5Sclose(space);
  H5Tclose(type);
  H5Aclose(attribute);
  return text;
}

// The class of an attribute's type (H5T_INTEGER, H5T_FLOAT, ...) and its value as a double.
std::pair<H5T_class_t, double> NumberAttribute(hid_t file, const char* name) {
  const hid_t attribute = H5Aopen(file, name, H5P_DEFAULT);
  if (attribute < 0) return {H5T_NO_CLASS, NAN};
  const hid_t type = H5Aget_type(attribute);
  const H5T_class_t type_class = H5Tget_class(type);
  double value = NAN;
  H5Aread(attribute, H5T_NATIVE_DOUBLE, &value);
  H5Tclose(type);
  H5Aclose(attribute);
  return {type_class, value};
}

// The "columns" attribute of a dataset: variable-length UTF-8 strings.
std::vector<std::string> Columns(hid_t file, const char* dataset) {
  std::vector<std::string> columns;
  const hid_t attribute = H5Aopen_by_name(file, dataset, "columns", H5P_DEFAULT, H5P_DEFAULT);
  if (attribute < 0) return columns;
  const hid_t type = H5Aget_type(attribute), space = H5Aget_space(attribute);
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  if (H5Tis_variable_str(type) > 0 && H5Tget_cset(type) == H5T_CSET_UTF8) {
    std::vector<char*> values(n);
    H5Aread(attribute, type, values.data());
    for (char* value : values) columns.emplace_back(value);
    H5Dvlen_reclaim(type, space, H5P_DEFAULT, values.data());
  }
  H5Sclose(space);
  H5Tclose(type);
  H5Aclose(attribute);
  return columns;
}

std::vector<double> Doubles(hid_t file, const char* name) {
  const auto dims = Dimensions(file, name);
  std::size_t n = 1;
  for (const hsize_t d : dims) n *= d;
  std::vector<double> values(n);
  const hid_t dataset = H5Dopen2(file, name, H5P_DEFAULT);
  H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
  H5Dclose(dataset);
  return values;
}

TEST(RunCommand, IsolatedBuildingWritesTheFullResponse) {
  const auto output = TemporaryFile("five_story.h5");
  const auto run = RunIsolab("run " + Source("models/buildings/five_story_table9.yaml") +
                             " --json -o " + output.string());
  ASSERT_EQ(run.exit_code, 0);
  const auto json = nlohmann::json::parse(run.output);
  EXPECT_EQ(json["termination"], "completed");
  EXPECT_LT(json["energy_balance_error"].get<double>(), 1e-3);
  EXPECT_GT(json["peaks"]["isolator_displacement"]["value"].get<double>(), 10.0);
  const int rows = json["steps"].get<int>() + 1;
  EXPECT_TRUE(isolab::testing::LeftoverTemporaries(output).empty());

  const hid_t file = H5Fopen(output.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_EQ(Dimensions(file, "time"), (std::vector<hsize_t>{hsize_t(rows)}));
  EXPECT_EQ(Dimensions(file, "displacement"), (std::vector<hsize_t>{hsize_t(rows), 6}));
  EXPECT_EQ(Dimensions(file, "absolute_acceleration"), (std::vector<hsize_t>{hsize_t(rows), 6}));
  EXPECT_EQ(Dimensions(file, "isolator/component_force"), (std::vector<hsize_t>{hsize_t(rows), 9}));
  EXPECT_EQ(Dimensions(file, "story/drift"), (std::vector<hsize_t>{hsize_t(rows), 5}));
  EXPECT_EQ(Dimensions(file, "story/shear"), (std::vector<hsize_t>{hsize_t(rows), 5}));
  for (const char* term : {"energy/input", "energy/kinetic", "energy/damping", "energy/elastic",
                           "energy/hysteretic"}) {
    EXPECT_EQ(Dimensions(file, term), (std::vector<hsize_t>{hsize_t(rows)})) << term;
  }
  EXPECT_EQ(Dimensions(file, "model_yaml"), std::vector<hsize_t>{});  // a scalar string
  EXPECT_GT(H5Lexists(file, "model_yaml", H5P_DEFAULT), 0);
  for (const char* attribute : {"record", "integrator", "isolab_version", "units"}) {
    EXPECT_NE(Utf8Attribute(file, "/", attribute), "") << attribute;
  }
  // Columns named, so a reader knows which is the base and which the floors.
  const std::vector<std::string> dofs = {"base",    "floor 1", "floor 2",
                                         "floor 3", "floor 4", "floor 5"};
  EXPECT_EQ(Columns(file, "displacement"), dofs);
  EXPECT_EQ(Columns(file, "absolute_acceleration"), dofs);
  EXPECT_EQ(
      Columns(file, "connection_force"),
      (std::vector<std::string>{"isolation", "story1", "story2", "story3", "story4", "story5"}));
  EXPECT_EQ(Columns(file, "isolator/component_force").size(), 9u);
  EXPECT_EQ(Utf8Attribute(file, "displacement", "units"), "mm");
  // Story heights (3.2 m) and drift ratios, in percent of them.
  EXPECT_EQ(Doubles(file, "story/height"), std::vector<double>(5, 3200.0));
  const auto drift = Doubles(file, "story/drift"), ratio = Doubles(file, "story/drift_ratio");
  ASSERT_EQ(ratio.size(), drift.size());
  for (std::size_t k = 0; k < drift.size(); k += 997) {
    EXPECT_NEAR(ratio[k], 100.0 * drift[k] / 3200.0, 1e-12 * std::abs(ratio[k]) + 1e-300);
  }
  // Counts as integers; the record as applied: ground_motions/README.md made it with PGA 0.35 g,
  // and the model scales it by 0.6.
  EXPECT_EQ(NumberAttribute(file, "newton_iterations").first, H5T_INTEGER);
  EXPECT_EQ(NumberAttribute(file, "steps").second, rows - 1);
  EXPECT_EQ(NumberAttribute(file, "record_scale").second, 0.6);
  EXPECT_NEAR(NumberAttribute(file, "record_pga_g").second, 0.6 * 0.35, 1e-9);
  EXPECT_EQ(Utf8Attribute(file, "/", "record_units"), "g");
  EXPECT_EQ(Utf8Attribute(file, "/", "record_units_source"), "header");
  // Solves per step: Newton iterations over completed steps, the same in JSON and the file.
  const double solves = json["newton"]["solves_per_step"].get<double>();
  EXPECT_DOUBLE_EQ(
      solves, json["newton"]["iterations"].get<double>() / json["steps_completed"].get<double>());
  double attribute_solves = 0.0;
  const hid_t attribute = H5Aopen(file, "solves_per_step", H5P_DEFAULT);
  ASSERT_GE(attribute, 0);
  H5Aread(attribute, H5T_NATIVE_DOUBLE, &attribute_solves);
  H5Aclose(attribute);
  EXPECT_EQ(attribute_solves, solves);
  H5Fclose(file);
}

TEST(RunCommand, EnergyBalancesForTheIsolatedBuildingUnderElCentro) {
  const auto record = isolab::testing::ElCentroPath();
  const auto output = TemporaryFile("el_centro.h5");
  const auto run =
      RunIsolab("run " + Source("models/buildings/five_story_table9.yaml") + " --record " +
                record.string() + " --scale 1 --json -o " + output.string());
  ASSERT_EQ(run.exit_code, 0);
  const auto json = nlohmann::json::parse(run.output);
  EXPECT_LT(json["energy_balance_error"].get<double>(), 1e-3);
  std::printf("five-story Table 9 under El Centro: isolator %.2f mm, energy balance error %.2e\n",
              json["peaks"]["isolator_displacement"]["value"].get<double>(),
              json["energy_balance_error"].get<double>());
}

TEST(RunCommand, ChopraCaseBThroughTheModelFile) {
  const auto output = TemporaryFile("case_b.h5");
  const auto run = RunIsolab("run " + Source("models/chopra/case_b_elastoplastic_sdof.yaml") +
                             " --json -o " + output.string());
  ASSERT_EQ(run.exit_code, 0);
  const auto json = nlohmann::json::parse(run.output);
  // Chopra Ex. 5.5: the peak of the 0.1 s samples is u(0.7 s) = 2.0952 in.
  EXPECT_NEAR(json["peaks"]["isolator_displacement"]["value"].get<double>(), 2.0952, 2e-4);
  EXPECT_NEAR(json["peaks"]["isolator_displacement"]["time"].get<double>(), 0.7, 1e-9);
}

TEST(RunCommand, IdaAndNewmarkThroughTheCommandLineAgreeOnCaseB) {
  // The model file samples the load at 0.1 s (linear between samples), so both integrators run
  // at a 0.001 s output step and must agree on the peak of that load's response.
  const auto output = TemporaryFile("case_b_ida.h5");
  const std::string common = "run " + Source("models/chopra/case_b_elastoplastic_sdof.yaml") +
                             " --dt 0.001 --json -o " + output.string();
  const auto ida = RunIsolab(common + " --integrator ida --rtol 1e-8");
  const auto newmark = RunIsolab(common + " --integrator newmark");
  ASSERT_EQ(ida.exit_code, 0) << ida.output;
  ASSERT_EQ(newmark.exit_code, 0) << newmark.output;
  const auto ida_json = nlohmann::json::parse(ida.output);
  const auto newmark_json = nlohmann::json::parse(newmark.output);
  const auto peak = [](const nlohmann::json& json) {
    return json["peaks"]["isolator_displacement"]["value"].get<double>();
  };
  EXPECT_NEAR(peak(ida_json), peak(newmark_json), 1e-4);
  EXPECT_EQ(ida_json["ida"]["events"].get<int>(), 2);  // yield, then unloading at the peak
  EXPECT_EQ(ida_json["integrator"].get<std::string>().rfind("ida rtol=1e-08", 0), 0u);
  EXPECT_TRUE(newmark_json.contains("newton"));
  EXPECT_LT(ida_json["energy_balance_error"].get<double>(), 1e-5);
}

struct BadInput {
  std::string file, message;
};

TEST(RunCommand, BadInputExitsWithCodeTwoAndWritesNothing) {
  const BadInput cases[] = {
      {"bad_malformed.yaml", "bad_malformed.yaml:2:10: YAML syntax error"},
      {"bad_unknown_analysis_key.yaml",
       "analysis.durration: unknown key (did you mean 'duration'?)"},
      {"bad_missing_mass.yaml", "structure: missing key 'mass'"},
      {"bad_wrong_unit.yaml", "structure.mass: 'kN' is a force unit, expected mass"},
      {"bad_negative_mass.yaml", "structure.mass: -0.0317 (must be > 0)"},
      {"bad_zero_dt.yaml", "analysis.dt: 0 (must be > 0)"},
      // A record that is not there is named at the model's key, with its path.
      {"bad_unreadable_record.yaml",
       "bad_unreadable_record.yaml:7:18: excitation.ground_motion.file: '"},
      {"bad_unreadable_record.yaml", "missing_record.at2' is not a file"},
      {"bad_nan_record.yaml", "bad_record_nan.at2:6: 'nan' is not a finite number"},
      {"bad_empty_record.yaml", "bad_record_empty.txt: the record is empty"},
      {"bad_unknown_integrator.yaml",
       "bad_unknown_integrator.yaml:8:34: analysis.integrator: 'rk4' is not an integrator "
       "(expected newmark or ida)"},
      {"bad_ida_rtol.yaml", "bad_ida_rtol.yaml:11:15: analysis.ida.rtol = 0 (must be in (0, 0.1))"},
      // Halving is bounded, not recursive (an unbounded one is a stack overflow waiting).
      {"bad_max_step_cuts.yaml",
       "bad_max_step_cuts.yaml:11:28: analysis.newmark.max_step_cuts = 1e+08 (must be in [0, 20])"},
  };
  for (const BadInput& c : cases) {
    const auto output = TemporaryFile("bad.h5");
    const auto run = RunIsolab("run " + Data(c.file) + " -o " + output.string(), true);
    EXPECT_EQ(run.exit_code, 2) << c.file << ": " << run.output;
    EXPECT_NE(run.output.find(c.message), std::string::npos) << c.file << ": " << run.output;
    EXPECT_FALSE(std::filesystem::exists(output)) << c.file;
    EXPECT_TRUE(isolab::testing::LeftoverTemporaries(output).empty()) << c.file;
  }
  EXPECT_EQ(RunIsolab("run " + Data("run_base.yaml") + " --dt 0.02", true).exit_code,
            2);  // coarser than the record
}

nlohmann::json RunJson(const std::string& arguments) {
  const auto run = RunIsolab(arguments + " --json");
  EXPECT_EQ(run.exit_code, 0) << arguments;
  return run.exit_code == 0 ? nlohmann::json::parse(run.output) : nlohmann::json{};
}

double PeakIsolatorDisplacement(const nlohmann::json& json) {
  return json["peaks"]["isolator_displacement"]["value"].get<double>();
}

TEST(RunCommand, RecordUnitsThatDisagreeWithTheHeaderAreRefusedNamingBoth) {
  const auto output = TemporaryFile("conflict.h5");
  const auto model =
      RunIsolab("run " + Data("bad_record_units_conflict.yaml") + " -o " + output.string(), true);
  EXPECT_EQ(model.exit_code, 2);
  EXPECT_NE(model.output.find("pulse_tp2_gal.at2: its header gives the units as cm/s^2 but "
                              "excitation.ground_motion.units in"),
            std::string::npos)
      << model.output;
  EXPECT_NE(model.output.find("gives m/s^2"), std::string::npos) << model.output;
  const auto option =
      RunIsolab("run " + Data("run_base.yaml") + " --units m/s^2 -o " + output.string(), true);
  EXPECT_EQ(option.exit_code, 2);
  EXPECT_NE(option.output.find("its header gives the units as g but --units gives m/s^2"),
            std::string::npos)
      << option.output;
  const auto step =
      RunIsolab("run " + Data("run_base.yaml") + " --record-dt 0.02 -o " + output.string(), true);
  EXPECT_EQ(step.exit_code, 2);
  EXPECT_NE(step.output.find("its header gives a step of 0.01 s but --record-dt gives 0.02 s"),
            std::string::npos)
      << step.output;
  EXPECT_FALSE(std::filesystem::exists(output));
}

TEST(RunCommand, AReplacedRecordKeepsItsOwnUnitsAndNotTheModelsScale) {
  // The model reads its own record (pulse_tp2 in g) with `units: g, scale: 0.5`. Replaced by the
  // same motion stored in cm/s^2, the record's header decides the units and the scale is 1: the
  // response is that of pulse_tp2 at scale 1, not 981 x 0.5 times it.
  const auto output = TemporaryFile("units.h5");
  const auto own = RunJson("run " + Data("run_units_g.yaml") + " --scale 1 -o " + output.string());
  const auto replaced = RunJson("run " + Data("run_units_g.yaml") + " --record " +
                                Source("tests/data/pulse_tp2_gal.at2") + " -o " + output.string());
  ASSERT_FALSE(own.is_null());
  ASSERT_FALSE(replaced.is_null());
  EXPECT_EQ(own["record_units"], "g");
  EXPECT_EQ(replaced["record_units"], "cm/s^2");
  EXPECT_EQ(replaced["record_units_source"], "header");
  EXPECT_EQ(replaced["scale"].get<double>(), 1.0);
  EXPECT_NEAR(replaced["pga_g"].get<double>(), own["pga_g"].get<double>(), 1e-9);
  EXPECT_NEAR(PeakIsolatorDisplacement(replaced), PeakIsolatorDisplacement(own),
              1e-8 * PeakIsolatorDisplacement(own));
  EXPECT_GT(PeakIsolatorDisplacement(own), 10.0);
}

TEST(RunCommand, ARecordScaledToATargetReportsItsFactorEverywhere) {
  const auto model = TemporaryFile("scaled.yaml");
  std::ofstream(model) << "units: {force: kN, length: mm, time: s}\n"
                          "structure: {type: sdof, mass: 31.7 t, damping: {ratio: 0.0}}\n"
                          "isolation: {components: [{name: k, type: linear_spring, k: 0.2}]}\n"
                          "excitation:\n"
                          "  ground_motion: {file: "
                       << Source("ground_motions/elcentro_1940_ns.at2")
                       << ", scale: {pga: 0.4 g}}\n"
                          "analysis: {dt: 0.02, free_vibration: 0}\n";
  const auto output = TemporaryFile("scaled.h5");
  const auto json = RunJson("run " + model.string() + " -o " + output.string());
  ASSERT_FALSE(json.is_null());
  const double scale = json["scale"].get<double>();
  EXPECT_EQ(json["scaled_to"], "PGA 0.4 g");
  EXPECT_NEAR(json["pga_g"].get<double>(), 0.4, 1e-12);
  const hid_t file = H5Fopen(output.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_EQ(NumberAttribute(file, "record_scale").second, scale);
  EXPECT_EQ(Utf8Attribute(file, "/", "record_scaled_to"), "PGA 0.4 g");
  H5Fclose(file);
  const auto text = RunIsolab("run " + model.string() + " -o " + output.string());
  ASSERT_EQ(text.exit_code, 0);
  EXPECT_NE(text.output.find("to PGA 0.4 g: PGA 0.4 g"), std::string::npos) << text.output;
}

TEST(RunCommand, ModelSummaryIsPrintedAndImplausibleValuesWarned) {
  // Masses typed without a unit in a kN-mm model: 25,000 t a floor.
  const auto output = TemporaryFile("slip.h5");
  const auto text = isolab::testing::RunCommandLine(
      std::string(ISOLAB_BINARY) + " run " + Source("tests/io/data/summary_mass_slip.yaml") +
      " --free-vibration 0 -o " + output.string() + " 2>&1");
  ASSERT_EQ(text.exit_code, 0) << text.output;
  EXPECT_NE(text.output.find("model: total weight 1.471e+06 kN (1.5e+05 t)"), std::string::npos)
      << text.output;
  EXPECT_NE(text.output.find("isolab: warning: the superstructure's fixed-base first period, "
                             "12.66 s, exceeds 10 s"),
            std::string::npos)
      << text.output;
  // The warnings are stored with the results.
  const hid_t file = H5Fopen(output.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_NE(Utf8Attribute(file, "/", "warnings").find("fixed-base first period"),
            std::string::npos);
  EXPECT_NEAR(Doubles(file, "model_summary/total_weight")[0], 150 * 1000 * 9.80665, 1e-6);
  H5Fclose(file);
  // A record scaled far beyond any earthquake drives the isolator beyond any bearing.
  const auto strong = RunJson("run " + Source("models/buildings/five_story_table9.yaml") +
                              " --scale 15 --free-vibration 0 -o " + output.string());
  ASSERT_FALSE(strong.is_null());
  std::string warnings;
  for (const auto& warning : strong["warnings"]) warnings += warning.get<std::string>() + "\n";
  EXPECT_NE(warnings.find("peak ground acceleration, 5.25 g, exceeds 3 g"), std::string::npos)
      << warnings;
  EXPECT_NE(warnings.find("exceeds 1.5 m, beyond any bearing built"), std::string::npos)
      << warnings;
}

// Dimensions typed without their units, each warned about by name with what it was read as: a
// story height of 3.5 in a mm model (3.5 mm), a floor mass of 500 (500 kN s^2/mm, 500,000 t), and
// friction pendulums of W = 1e300 kN and R = 1e-300 mm. The runs go on: the engineer decides.
TEST(RunCommand, DimensionsNoBuildingHasAreWarnedAbout) {
  const auto model = TemporaryFile("slips.yaml");
  const auto write = [&](const std::string& stories, const std::string& bearing) {
    std::ofstream(model) << "units: {force: kN, length: mm, time: s}\n"
                         << "structure:\n  type: shear_building\n  base_mass: 25 t\n"
                         << "  stories: {count: 2, " << stories << ", stiffness: 76 kN/mm}\n"
                         << "  damping: {type: rayleigh, modes: [1, 2], ratios: [0.02, 0.02]}\n"
                         << "isolation:\n  components:\n    - {name: fps, type: friction_pendulum, "
                         << bearing << ", uy: 0.5, mu: 0.05}\n"
                         << "excitation:\n  ground_motion: {file: "
                         << Source("ground_motions/pulse_tp2.at2") << "}\nanalysis: {dt: 0.01}\n";
  };
  const auto warnings = [&] {
    const auto json = RunJson("run " + model.string() + " --free-vibration 0 -o " +
                              TemporaryFile("slips.h5").string());
    std::string all;
    if (!json.is_null()) {
      for (const auto& warning : json["warnings"]) all += warning.get<std::string>() + "\n";
    }
    return all;
  };
  write("mass: 25 t, height: 3.2 m", "w: 735, r: 2000");
  EXPECT_EQ(warnings(), "");  // a real building on real bearings
  write("mass: 25 t, height: 3.5", "w: 735, r: 2000");
  EXPECT_NE(warnings().find("story 1's height, 3.5 mm (0.0035 m), is outside the 1 to 20 m of real "
                            "stories: a height without a unit is in mm"),
            std::string::npos);
  write("mass: 500, height: 3.2 m", "w: 735, r: 2000");
  EXPECT_NE(warnings().find("the mass of floor 1, 5e+05 t, is outside the 1 to 100000 t"),
            std::string::npos);
  write("mass: 25 t, height: 3.2 m", "w: 1e300, r: 2000");
  EXPECT_NE(warnings().find("friction pendulum 'fps' carries W = 1e+300 kN, more than the whole "
                            "structure weighs (735.5 kN)"),
            std::string::npos);
  write("mass: 25 t, height: 3.2 m", "w: 735, r: 1e-300");
  EXPECT_NE(warnings().find("friction pendulum 'fps' has a radius of 1e-303 m, outside the 0.1 to "
                            "50 m"),
            std::string::npos);
}

TEST(RunCommand, ResidualDisplacementAfterFreeVibrationMatchesTheClosedForm) {
  // residual_step_force.yaml derives both numbers: the offset the yielded SDOF swings about after
  // release (its residual), and where it stands at release (what was read before free vibration).
  const double k = 4 * M_PI * M_PI, fy = 1.0, p = 0.7;
  const double offset = fy / k * (2 * p - fy) / (2 * (fy - p));
  const double at_release = offset + (2 * p - fy) / k;
  const auto json = RunJson("run " + Data("residual_step_force.yaml") + " -o " +
                            TemporaryFile("residual.h5").string());
  ASSERT_FALSE(json.is_null());
  EXPECT_NEAR(json["residual_isolator_displacement"].get<double>(), offset, 1e-5 * offset);
  EXPECT_NEAR(json["isolator_displacement_at_excitation_end"].get<double>(), at_release,
              1e-5 * at_release);
  // It never stops swinging (nothing damps it): half its range is (2P - fy)/k... left as it is.
  EXPECT_NEAR(json["residual_oscillation"].get<double>(), at_release - offset, 1e-5 * offset);
  // The default free vibration: five times the period at the trial displacement (0.1 m: the
  // secant stiffness fy / 0.1 m of the yielded spring).
  EXPECT_NEAR(json["free_vibration"].get<double>(), 5 * 2 * M_PI * std::sqrt(1.0 / (fy / 0.1)),
              1e-9);
  // Without free vibration the residual is read at release.
  const auto none = RunJson("run " + Data("residual_step_force.yaml") + " --free-vibration 0 -o " +
                            TemporaryFile("residual.h5").string());
  EXPECT_NEAR(none["residual_isolator_displacement"].get<double>(), at_release, 1e-5 * at_release);
}

// A write that fails (a full disk; here a real "File too large" from the shell's ulimit -f):
// exit code 3 with the system's reason, the previous results untouched, no temporary file, and
// no crash at exit (HDF5 1.10 once segfaulted after its failed close).
TEST(RunCommand, AFailedWriteIsAResourceErrorAndKeepsThePreviousResults) {
  for (const char* name : {"full.h5", "full.csv"}) {
    const auto output = TemporaryFile(name);
    { std::ofstream(output) << "previous"; }
    const auto run = isolab::testing::RunCommandLine(
        "sh -c \"ulimit -f 100; trap '' XFSZ; exec " + std::string(ISOLAB_BINARY) + " run " +
        Source("models/buildings/five_story_table9.yaml") + " -o " + output.string() +
        "\" 2>&1 >/dev/null");
    EXPECT_EQ(run.exit_code, 3) << name << ": " << run.output;
    EXPECT_NE(run.output.find("File too large"), std::string::npos) << run.output;
    std::ifstream in(output);
    std::string text;
    std::getline(in, text);
    EXPECT_EQ(text, "previous") << name;
    EXPECT_TRUE(isolab::testing::LeftoverTemporaries(output).empty()) << name;
  }
}

// A dt or a duration wrong by orders of magnitude is refused before anything is allocated: the
// step count (once an int that overflowed: duration 1e9 "completed" at once) against the limit.
TEST(RunCommand, RunsOfTooManyStepsAreRefusedBeforeTheyStart) {
  const auto output = TemporaryFile("too_many_steps.h5");
  const std::string run = "run " + Data("run_base.yaml") + " -o " + output.string();
  const auto tiny_dt = RunIsolab(run + " --dt 1e-7", true);
  EXPECT_EQ(tiny_dt.exit_code, 2);
  EXPECT_EQ(tiny_dt.output.rfind("isolab: --dt: the run would take 2.13e+08 steps", 0), 0u)
      << tiny_dt.output;
  EXPECT_NE(tiny_dt.output.find("--max-steps"), std::string::npos) << tiny_dt.output;
  // 12 s of record (1201 samples of 0.01 s, its header) and 9.3 s of free vibration (5 isolated
  // periods): 2133 steps. A limit below that refuses, one above runs.
  const auto limited = RunIsolab(run + " --max-steps 2000", true);
  EXPECT_EQ(limited.exit_code, 2);
  EXPECT_NE(limited.output.find("2.13e+03 steps"), std::string::npos) << limited.output;
  EXPECT_FALSE(std::filesystem::exists(output));
  EXPECT_EQ(RunIsolab(run + " --max-steps 2200").exit_code, 0);

  const auto model = TemporaryFile("long.yaml");
  {
    std::ifstream in(Data("run_base.yaml"));
    std::stringstream text;
    text << in.rdbuf();
    std::string yaml = text.str();
    yaml.replace(yaml.find("{file: ../../../ground_motions/"),
                 std::string("{file: ../../../ground_motions/").size(),
                 "{file: " + Source("ground_motions/"));
    yaml.replace(yaml.find("analysis: {dt: 0.01}"), std::string("analysis: {dt: 0.01}").size(),
                 "analysis: {dt: 0.01, duration: 1e9}");
    std::ofstream(model) << yaml;
  }
  const auto long_run = RunIsolab("run " + model.string() + " -o " + output.string(), true);
  EXPECT_EQ(long_run.exit_code, 2);
  EXPECT_NE(long_run.output.find("1e+11 steps"), std::string::npos) << long_run.output;
}

TEST(RunCommand, OutputPathsThatAreNotRegularFilesAreRefused) {
  const auto folder = TemporaryFile("paths");
  std::filesystem::create_directories(folder);
  const std::string run = "run " + Data("run_base.yaml") + " -o ";
  const auto fifo = folder / "pipe.h5";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  const auto pipe = RunIsolab(run + fifo.string(), true);
  EXPECT_EQ(pipe.exit_code, 2);
  EXPECT_NE(pipe.output.find("pipe.h5: is a named pipe"), std::string::npos) << pipe.output;
  EXPECT_TRUE(std::filesystem::is_fifo(fifo));
  const auto target = folder / "target.h5", link = folder / "link.h5";
  { std::ofstream(target) << "kept"; }
  std::filesystem::create_symlink(target, link);
  EXPECT_EQ(RunIsolab(run + link.string(), true).exit_code, 2);
  EXPECT_TRUE(std::filesystem::is_symlink(link));
  EXPECT_EQ(std::filesystem::file_size(target), 4u);
  const auto missing = RunIsolab(run + (folder / "no" / "out.h5").string(), true);
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.output.find("/no' does not exist"), std::string::npos) << missing.output;
  const auto text = RunIsolab(run + (folder / "out.txt").string(), true);
  EXPECT_EQ(text.exit_code, 2);
  EXPECT_NE(text.output.find("unknown results file type '.txt'"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(folder / "out.txt"));
  EXPECT_TRUE(isolab::testing::LeftoverTemporaries(folder / "out.txt").empty());
}

TEST(RunCommand, CsvExportHasNamedUnitTaggedColumns) {
  const auto csv = TemporaryFile("five_story.csv");
  const auto json =
      RunJson("run " + Source("models/buildings/five_story_table9.yaml") + " -o " + csv.string());
  ASSERT_FALSE(json.is_null());
  std::ifstream in(csv);
  std::string line, header;
  std::getline(in, line);
  EXPECT_EQ(line.rfind("# isolab", 0), 0u) << line;  // text, not HDF5 under a .csv name
  while (std::getline(in, line) && line[0] == '#') {
  }
  header = line;
  for (const char* column : {"time [s]", "displacement/base [mm]", "displacement/floor 5 [mm]",
                             "isolator/component_force/c9 [kN]", "story/drift_ratio/story1 [%]",
                             "energy/hysteretic [kN*mm]", "ground_acceleration [mm/s^2]"}) {
    EXPECT_NE(header.find(column), std::string::npos) << column;
  }
  // The isolator's column holds the peak the summary reports.
  std::vector<std::string> names;
  std::stringstream fields(header);
  for (std::string name; std::getline(fields, name, ',');) names.push_back(name);
  const auto column = std::find(names.begin(), names.end(), "isolator/displacement [mm]");
  ASSERT_NE(column, names.end());
  const std::size_t index = column - names.begin();
  double peak = 0.0;
  int rows = 0;
  while (std::getline(in, line)) {
    std::stringstream values(line);
    std::string value;
    for (std::size_t c = 0; c <= index; ++c) std::getline(values, value, ',');
    peak = std::max(peak, std::abs(std::stod(value)));
    ++rows;
  }
  EXPECT_EQ(rows, json["steps"].get<int>() + 1);
  EXPECT_EQ(peak, PeakIsolatorDisplacement(json));
}

// isolab run --samples of a model carrying a fit's uncertainty: the spread of the peaks over
// drawn parameter sets. With a covariance of zero every draw is the model itself (its values
// through exp(ln p), to round-off), so the band collapses onto the run's own peaks; with a spread,
// the percentiles are ordered and apart. A model without uncertainty is refused before the run
// writes anything.
TEST(RunCommand, SamplesDrawTheSpreadOfThePeaksFromTheFittedUncertainty) {
  const auto model = [](const std::string& covariance) {
    const auto path =
        isolab::testing::OwnTestFile("fitted_" + std::to_string(covariance.size()) + ".yaml");
    std::ofstream(path) << "units: {force: kN, length: mm, time: s}\n"
                           "structure:\n  type: shear_building\n  base_mass: 30 t\n"
                           "  stories: {count: 3, mass: 30 t, stiffness: 60 kN/mm}\n"
                           "  damping: {type: rayleigh, modes: [1, 2], ratios: [0.02, 0.02]}\n"
                           "isolation:\n  components:\n"
                           "    - {name: iso, type: bhm2, k0: 3, k1: 0.4, uy: 5}\n"
                           "excitation:\n  ground_motion: {file: "
                        << Source("ground_motions/fwn_firm_seed1.at2")
                        << "}\nanalysis: {dt: 0.01}\n"
                           "uncertainty:\n  parameters: [{name: isolation.iso.k1, value: 0.4, "
                           "log: true}, {name: stories.stiffness, value: 60, log: true}]\n"
                           "  covariance: "
                        << covariance << "\n";
    return path.string();
  };
  const auto results = isolab::testing::OwnTestFile("band.h5").string();
  const auto run = [&](const std::string& path) {
    const auto outcome =
        RunIsolab("run " + path + " --samples 12 --seed 3 --json -q -o " + results);
    EXPECT_EQ(outcome.exit_code, 0) << outcome.output;
    return nlohmann::json::parse(outcome.output);
  };
  const auto fixed = run(model("[[0, 0], [0, 0]]"));
  ASSERT_EQ(fixed["band"]["samples"].get<int>(), 12);
  // Every peak of the run's summary has its band, and nothing else does.
  std::size_t banded = 0;
  for (const auto& [peak, value] : fixed["peaks"].items()) {
    if (!value.is_object()) continue;  // the drift ratios: derived from story_drift, not peaks
    SCOPED_TRACE(peak);
    ASSERT_TRUE(fixed["band"].contains(peak));
    ++banded;
    const double own = value["value"].get<double>();
    for (const char* p : {"p5", "p50", "p95"}) {
      EXPECT_NEAR(fixed["band"][peak][p].get<double>(), own, 1e-9 * own) << p;
    }
  }
  EXPECT_EQ(banded, 7u);  // a shear building's: isolator, story and floor peaks
  EXPECT_EQ(fixed["band"].size(), banded + 5);  // and samples, refused, contents, widening, seed
  const auto spread = run(model("[[0.01, 0], [0, 0.0025]]"));
  for (const char* peak : {"isolator_displacement", "base_shear", "roof_absolute_acceleration"}) {
    const auto& band = spread["band"][peak];
    EXPECT_LT(band["p5"].get<double>(), band["p50"].get<double>()) << peak;
    EXPECT_LT(band["p50"].get<double>(), band["p95"].get<double>()) << peak;
  }

  // Identified up to a third of the run's own peak: the band's draws are widened by the factor
  // the run goes past it, and the band says so; the range warning names the parameter given by
  // a prior, which the response beyond the range rests on too.
  const auto own = spread["peaks"]["isolator_displacement"]["value"].get<double>();
  const auto beyond = isolab::testing::OwnTestFile("beyond.yaml");
  const auto beyond_prior = isolab::testing::OwnTestFile("beyond_prior.yaml");
  {
    std::ifstream in(model("[[0.01, 0], [0, 0.0025]]"));
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string components = "isolation:\n  components:\n";
    text.replace(text.find(components), components.size(),
                 components.substr(0, components.size() - 12) +
                     "identified_range: {displacement: " + std::to_string(own / 3) +
                     ", velocity: 1.0e9, cycles: 3, data: [m]}\n  components:\n");
    std::ofstream(beyond) << text;
    std::ofstream(beyond_prior)
        << text
        << "  priors: [{name: isolation.iso.uy, value: 5, sigma: 0.1, source: design data}]\n";
  }
  const auto widened = run(beyond.string());
  const auto with_prior = run(beyond_prior.string());
  // 3 to the six decimals std::to_string wrote the identified displacement with.
  EXPECT_NEAR(widened["band"]["widening"].get<double>(), 3.0, 1e-6);
  EXPECT_NE(widened["band"]["contents"].get<std::string>().find("widened 3.00 times beyond"),
            std::string::npos);
  EXPECT_EQ(spread["band"]["widening"].get<double>(), 1.0);  // no identified range
  EXPECT_NE(with_prior["band"]["contents"].get<std::string>().find(
                "with 1 parameter from a prior (isolation.iso.uy: design data)"),
            std::string::npos);
  bool named = false;
  for (const auto& warning : with_prior["warnings"]) {
    named |= warning.get<std::string>().find(
                 "far beyond the range the fit saw (more than 2 times it): the response there "
                 "rests on the law's form alone, not on the data; beyond it the response also "
                 "rests on parameters given, not fitted: isolation.iso.uy = 5 (design data)") !=
             std::string::npos;
  }
  EXPECT_TRUE(named) << with_prior["warnings"].dump();
  const auto width = [](const nlohmann::json& band) {
    return band["isolator_displacement"]["p95"].get<double>() -
           band["isolator_displacement"]["p5"].get<double>();
  };
  EXPECT_GT(width(widened["band"]), 2.0 * width(spread["band"]));

  std::filesystem::remove(results);
  const auto none = RunIsolab(
      "run " + Source("models/buildings/five_story_table9.yaml") + " --samples 12 -q -o " + results,
      true);
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_NE(none.output.find("no uncertainty"), std::string::npos) << none.output;
  EXPECT_FALSE(std::filesystem::exists(results));
  const auto one = RunIsolab("run " + model("[[0]]") + " --samples 1 -q -o " + results, true);
  EXPECT_NE(one.exit_code, 0);
  EXPECT_NE(one.output.find("--samples"), std::string::npos) << one.output;

  // A covariance with a negative variance along an eigenvector, and one of a factor 1e434 per
  // sigma, are refused by their key before the run writes anything.
  for (const auto& [covariance, message] :
       {std::pair{"[[1, 2], [2, 1]]", "positive semi-definite"},
        std::pair{"[[1.0e6, 0], [0, 0]]", "implausibly wide"}}) {
    const auto bad = RunIsolab("run " + model(covariance) + " --samples 4 -q -o " + results, true);
    EXPECT_EQ(bad.exit_code, 2) << bad.output;
    EXPECT_NE(bad.output.find("uncertainty.covariance"), std::string::npos) << bad.output;
    EXPECT_NE(bad.output.find(message), std::string::npos) << bad.output;
    EXPECT_FALSE(std::filesystem::exists(results));
  }
}

// The band is drawn about the model as it stands: a model whose story stiffness was edited from
// the fitted 60 to 80 kN/mm (the uncertainty section still says 60) gets, with a zero covariance,
// a band that is its own run's peaks, not the fitted model's.
TEST(RunCommand, ABandIsCentredOnTheModelItRunsNotOnTheFittedValues) {
  const auto model = [](const std::string& name, int stiffness) {
    const auto path = isolab::testing::OwnTestFile(name);
    std::ofstream(path) << "units: {force: kN, length: mm, time: s}\n"
                           "structure:\n  type: shear_building\n  base_mass: 30 t\n"
                           "  stories: {count: 3, mass: 30 t, stiffness: "
                        << stiffness
                        << " kN/mm}\n"
                           "  damping: {type: rayleigh, modes: [1, 2], ratios: [0.02, 0.02]}\n"
                           "isolation:\n  components:\n"
                           "    - {name: iso, type: bhm2, k0: 3, k1: 0.4, uy: 5}\n"
                           "excitation:\n  ground_motion: {file: "
                        << Source("ground_motions/fwn_firm_seed1.at2")
                        << "}\nanalysis: {dt: 0.01}\n"
                           "uncertainty:\n  parameters: [{name: stories.stiffness, value: 60, "
                           "log: true}]\n  covariance: [[0]]\n";
    return path.string();
  };
  const auto peaks = [&](const std::string& path) {
    const auto run = RunIsolab("run " + path + " --samples 3 --json -q -o " + path + ".h5");
    EXPECT_EQ(run.exit_code, 0) << run.output;
    return nlohmann::json::parse(run.output);
  };
  const auto fitted = peaks(model("fitted.yaml", 60));
  const auto edited = peaks(model("edited.yaml", 80));
  const double own = edited["peaks"]["story_drift"]["value"].get<double>();
  const double fitted_drift = fitted["peaks"]["story_drift"]["value"].get<double>();
  ASSERT_GT(std::abs(own - fitted_drift), 0.05 * own);  // the edit moves the drift
  for (const char* p : {"p5", "p50", "p95"}) {
    EXPECT_NEAR(edited["band"]["story_drift"][p].get<double>(), own, 1e-9 * own) << p;
  }
}

}  // namespace

// The command line's output options replace the model's output section: every 10th step of the
// roof's displacement and the isolator, the peaks of every step (those of the full run), and the
// selection recorded in the file's attributes; a bad selection is refused before the run.
TEST(RunCommand, OutputOptionsChooseWhatIsWrittenNotWhatIsComputed) {
  const std::string model = Source("models/buildings/five_story_table9.yaml");
  const auto full_output = TemporaryFile("full.h5");
  const auto full = RunJson("run " + model + " -o " + full_output.string());
  const auto output = TemporaryFile("thinned.h5");
  const auto thinned = RunJson("run " + model + " -o " + output.string() +
                               " --every 10 --quantities displacement,isolator --levels roof");
  ASSERT_FALSE(full.empty());
  ASSERT_FALSE(thinned.empty());
  EXPECT_EQ(thinned["peaks"], full["peaks"]);
  EXPECT_EQ(thinned["residual_isolator_displacement"], full["residual_isolator_displacement"]);
  EXPECT_EQ(thinned["energy"], full["energy"]);

  const int steps = full["steps"].get<int>();
  const hid_t file = H5Fopen(output.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  const hsize_t rows = steps / 10 + 1;
  EXPECT_EQ(Dimensions(file, "displacement"), (std::vector<hsize_t>{rows, 1}));
  EXPECT_EQ(Columns(file, "displacement"), std::vector<std::string>{"floor 5"});
  EXPECT_EQ(Dimensions(file, "isolator/displacement"), std::vector<hsize_t>{rows});
  EXPECT_TRUE(Dimensions(file, "velocity").empty());
  EXPECT_TRUE(Dimensions(file, "story/drift").empty());
  EXPECT_EQ(NumberAttribute(file, "output_every"), std::make_pair(H5T_INTEGER, 10.0));
  EXPECT_EQ(NumberAttribute(file, "summary_only"), std::make_pair(H5T_INTEGER, 0.0));
  // Row k of the thinned file is row 10 k of the full one.
  const hid_t full_file = H5Fopen(full_output.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(full_file, 0);
  const std::vector<double> u = Doubles(file, "displacement");
  const std::vector<double> u_full = Doubles(full_file, "displacement");
  ASSERT_EQ(u.size(), rows);
  for (hsize_t k = 0; k < rows; ++k) ASSERT_EQ(u[k], u_full[10 * k * 6 + 5]) << k;
  H5Fclose(full_file);
  H5Fclose(file);

  const auto summary = TemporaryFile("summary.h5");
  EXPECT_EQ(RunJson("run " + model + " --summary-only -o " + summary.string())["peaks"],
            full["peaks"]);
  const hid_t summary_file = H5Fopen(summary.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(summary_file, 0);
  EXPECT_TRUE(Dimensions(summary_file, "time").empty());
  EXPECT_EQ(Doubles(summary_file, "peaks/isolator_displacement"),
            std::vector<double>{PeakIsolatorDisplacement(full)});
  H5Fclose(summary_file);

  const BadInput bad[] = {
      {"--levels 6", "--levels: level 6 is not in the structure (its levels are 0 to 5, or roof)"},
      {"--levels top", "--levels: 'top' is not a level"},
      {"--quantities displacment", "unknown quantity 'displacment'; did you mean 'displacement'?"},
      {"--every 0", "--every"},
  };
  for (const BadInput& c : bad) {
    const auto refused = TemporaryFile("refused.h5");
    const auto run = RunIsolab("run " + model + " " + c.file + " -o " + refused.string(), true);
    EXPECT_EQ(run.exit_code, 2) << c.file << ": " << run.output;
    EXPECT_NE(run.output.find(c.message), std::string::npos) << c.file << ": " << run.output;
    EXPECT_FALSE(std::filesystem::exists(refused)) << c.file;
  }
}

// isolab's start-up loads neither MPI nor pagmo (nor their dependencies): only fit, diagnose,
// compare and design need them, and the front hands those on (src/cli/main.cpp).
TEST(RunCommand, TheFrontLinksNeitherMpiNorPagmo) {
  const auto libraries = isolab::testing::RunShell(std::string("ldd ") + ISOLAB_BINARY);
  ASSERT_EQ(libraries.exit_code, 0);
  for (const char* heavy : {"libmpi", "libpagmo", "libtbb", "libboost"}) {
    EXPECT_EQ(libraries.output.find(heavy), std::string::npos) << heavy << "\n" << libraries.output;
  }
  // And the commands that need them still run through it.
  const auto fit = RunIsolab("fit --help");
  EXPECT_EQ(fit.exit_code, 0);
  EXPECT_NE(fit.output.find("Identify an isolator model's parameters"), std::string::npos);
}

// A study's start-up is time its workers wait, and pagmo's libraries take about 20 ms to load:
// compare, design and synth run in an executable without them. fit and diagnose run in one with
// pagmo and MPI (a fit spreads over mpirun's ranks), whose start-up is nothing beside a search,
// and so do cyclic and shaketable, on the same libraries.
TEST(RunCommand, StudiesLoadNoPagmoAndSearchesBoth) {
  const auto studies = isolab::testing::RunShell(std::string("ldd ") + ISOLAB_STUDIES_BINARY);
  ASSERT_EQ(studies.exit_code, 0);
  EXPECT_NE(studies.output.find("libmpi"), std::string::npos) << studies.output;
  EXPECT_EQ(studies.output.find("libpagmo"), std::string::npos) << studies.output;
  const auto search = isolab::testing::RunShell(std::string("ldd ") + ISOLAB_SEARCH_BINARY);
  ASSERT_EQ(search.exit_code, 0);
  EXPECT_NE(search.output.find("libpagmo"), std::string::npos) << search.output;
  EXPECT_NE(search.output.find("libmpi"), std::string::npos) << search.output;
  for (const char* command :
       {"compare", "design", "synth", "fit", "diagnose", "cyclic", "shaketable", "bounds"}) {
    const auto help = RunIsolab(std::string(command) + " --help");
    EXPECT_EQ(help.exit_code, 0) << command << ": " << help.output;
    EXPECT_NE(help.output.find(std::string("isolab ") + command + " [OPTIONS]"), std::string::npos)
        << help.output;
  }
}

// scripts/setup.sh alone builds the front: a command it hands over whose executable is not built
// says how to build it, in a build tree; elsewhere (an install missing a file) it says to
// reinstall.
TEST(RunCommand, AHandedOverCommandWhoseExecutableIsMissingSaysHowToBuildIt) {
  const std::filesystem::path made = TemporaryFile("front_alone");
  std::filesystem::create_directories(made);
  // As the front reads its own path (/proc/self/exe): without symbolic links.
  const std::filesystem::path folder = std::filesystem::canonical(made);
  const std::filesystem::path front = folder / "isolab";
  std::filesystem::copy_file(ISOLAB_BINARY, front);
  const std::string fit = front.string() + " fit --help";
  const auto installed = isolab::testing::RunShell(fit, true);
  EXPECT_EQ(installed.exit_code, 1) << installed.output;
  // An install looks in ../libexec beside bin/.
  EXPECT_NE(installed.output.find("cannot start " +
                                  (folder.parent_path() / "libexec/isolab/isolab-search").string() +
                                  " for 'fit'"),
            std::string::npos)
      << installed.output;
  EXPECT_NE(installed.output.find("reinstall isolab"), std::string::npos) << installed.output;

  std::ofstream(folder / "CMakeCache.txt") << "# a build tree\n";
  for (const auto& [command, target] :
       {std::pair{"fit", "isolab_search"}, std::pair{"cyclic", "isolab_search"},
        std::pair{"compare", "isolab_studies"}, std::pair{"synth", "isolab_studies"}}) {
    const auto built = isolab::testing::RunShell(front.string() + " " + command + " --help", true);
    EXPECT_EQ(built.exit_code, 1) << built.output;
    EXPECT_NE(built.output.find(std::string("isolab: '") + command + "' is not built yet (" +
                                (folder / "libexec/isolab/").string()),
              std::string::npos)
        << built.output;
    EXPECT_NE(built.output.find("`cmake --build " + folder.string() + " --target " + target +
                                "`, or every command with `scripts/setup.sh --all`"),
              std::string::npos)
        << built.output;
  }
  // The front's own commands need nothing beside it.
  EXPECT_EQ(isolab::testing::RunShell(front.string() + " run --help").exit_code, 0);
}

namespace {

// Largest kinetic energy over the largest |input energy| so far, over a results file's rows. A
// passive structure cannot exceed 1 (kinetic = input - elastic - damping - hysteretic, each of
// the last three >= 0), up to the balance error.
double KineticToInputRatio(const std::filesystem::path& results) {
  const hid_t file = H5Fopen(results.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const std::vector<double> kinetic = Doubles(file, "energy/kinetic");
  const std::vector<double> input = Doubles(file, "energy/input");
  H5Fclose(file);
  double ratio = 0.0, max_input = 0.0;
  for (std::size_t k = 0; k < std::min(kinetic.size(), input.size()); ++k) {
    max_input = std::max(max_input, std::abs(input[k]));
    if (max_input > 0.0) ratio = std::max(ratio, kinetic[k] / max_input);
  }
  return ratio;
}

}  // namespace

// A divergent run must not exit 0 "completed" (peaks of 1e92 mm, NaN energies printed as a
// balance error of 0). Both integrators stop it with exit 1 and say why; the results written up
// to there show the energy the model created, which a valid run never does.
TEST(RunCommand, BlowUpsExitOneUnderBothIntegratorsAndValidRunsStayPassive) {
  const auto output = TemporaryFile("blow_up.h5");
  for (const char* integrator : {"newmark", "ida"}) {
    const auto run = RunIsolab("run " + Data("blow_up_negative_stiffness.yaml") + " --integrator " +
                                   integrator + " -o " + output.string(),
                               true);
    EXPECT_EQ(run.exit_code, 1) << integrator << ": " << run.output;
    EXPECT_NE(run.output.find("the run stopped early: blow-up at t = "), std::string::npos)
        << integrator << ": " << run.output;
    EXPECT_GT(KineticToInputRatio(output), 10.0) << integrator;
  }
  const auto huge =
      RunIsolab("run " + Data("run_base.yaml") + " --scale 1e300 -o " + output.string(), true);
  EXPECT_EQ(huge.exit_code, 1) << huge.output;
  EXPECT_NE(huge.output.find("blow-up at t = "), std::string::npos) << huge.output;
  EXPECT_NE(huge.output.find("the response is not finite"), std::string::npos) << huge.output;
  const auto json =
      RunIsolab("run " + Data("blow_up_negative_stiffness.yaml") + " --json -o " + output.string());
  EXPECT_EQ(json.exit_code, 1);
  EXPECT_EQ(nlohmann::json::parse(json.output)["termination"], "failed");

  ASSERT_EQ(RunIsolab("run " + Data("run_base.yaml") + " -o " + output.string()).exit_code, 0);
  EXPECT_LE(KineticToInputRatio(output), 1.0 + 1e-3);
}

// `--scale nan`, `--scale inf` and `--rtol nan` are not numbers (a range check lets NaN
// through): every floating-point option refuses them, exit 2, naming the option.
TEST(RunCommand, NonFiniteNumbersOnTheCommandLineExitTwo) {
  const auto output = TemporaryFile("non_finite.h5");
  const std::pair<std::string, std::string> cases[] = {
      {"--scale nan", "--scale: 'nan' is not a finite number"},
      {"--scale inf", "--scale: 'inf' is not a finite number"},
      {"--scale 1e999", "--scale: '1e999' is out of range"},
      {"--rtol nan", "--rtol: 'nan' is not a finite number"},
      {"--trial-displacement NaN", "--trial-displacement: 'NaN' is not a finite number"},
      // An angle is a direction: at 1e308 degrees its cosine was NaN and the run reported a
      // failed Newton iteration (exit 1).
      {"--record " + Source("ground_motions/fwn_firm_seed1.at2") + " --angle 1e308",
       "--angle: 1e+308 degrees (must be in [-360, 360])"},
      // The record overflowed to inf: a blow-up reported as a failed run (exit 1).
      {"--scale 1e308", "--scale: 1e+308: the record "},
  };
  for (const auto& [option, message] : cases) {
    const auto run =
        RunIsolab("run " + Data("run_base.yaml") + " " + option + " -o " + output.string(), true);
    EXPECT_EQ(run.exit_code, 2) << option << ": " << run.output;
    EXPECT_NE(run.output.find(message), std::string::npos) << option << ": " << run.output;
    EXPECT_FALSE(std::filesystem::exists(output)) << option;
  }
}

// IDA integrates rate forms: a law without one (degrading_bhm2) is refused before the run, on a
// one-direction member and on an isolator in plan alike, naming where it is and what runs it.
TEST(RunCommand, IdaRefusesALawWithoutARateFormOnEitherModelKind) {
  const std::string record = Source("ground_motions/fwn_firm_seed1.at2");
  const std::string worn =
      "{name: worn, type: degrading_bhm2, k0: 2, k1: 0.25, uy: 20, loss: 0.1, slip_scale: 500}";
  const std::string sdof =
      "units: {force: kN, length: mm, time: s}\n"
      "structure: {type: sdof, mass: 31.7 t, damping: {ratio: 0.0}}\n"
      "isolation: {components: [" +
      worn +
      "]}\n"
      "excitation: {ground_motion: {file: " +
      record + ", scale: 0.5}}\n";
  const std::string plan =
      "units: {force: kN, length: mm, time: s}\n"
      "plan:\n"
      "  footprint: [[0, 0], [20000, 10000]]\n"
      "  base: {mass: 100 t, centre_of_mass: [10000, 5000], radius_of_gyration: 6000}\n"
      "  stories: [{name: s1, mass: 100 t, stiffness: {x: 300, y: 200, torsion: 3.0e10}}]\n"
      "  isolators:\n"
      "    - {name: a, position: [0, 0], components: [{type: bhm2, k0: 2, k1: 0.25, uy: 20}]}\n"
      "    - {name: b, position: [20000, 10000], coupling: uncoupled, components: [" +
      worn +
      "]}\n"
      "excitation: {ground_motion: {h1: {file: " +
      record + ", scale: 0.5}}}\n";
  for (const auto& [name, text, where] : {std::tuple{"sdof", sdof, std::string("member '")},
                                          std::tuple{"plan", plan, std::string("isolator 'b'")}}) {
    SCOPED_TRACE(name);
    const auto model = TemporaryFile(std::string(name) + "_worn.yaml");
    std::ofstream(model) << text;
    const auto output = TemporaryFile(std::string(name) + "_worn.h5");
    const auto ida =
        RunIsolab("run " + model.string() + " --integrator ida -o " + output.string(), true);
    EXPECT_EQ(ida.exit_code, 2) << ida.output;
    EXPECT_NE(ida.output.find("cannot run " + where), std::string::npos) << ida.output;
    EXPECT_NE(ida.output.find("degrading_bhm2"), std::string::npos) << ida.output;
    EXPECT_NE(ida.output.find("--integrator newmark"), std::string::npos) << ida.output;
    EXPECT_FALSE(std::filesystem::exists(output));
    const auto newmark =
        RunIsolab("run " + model.string() + " --integrator newmark -q -o " + output.string());
    EXPECT_EQ(newmark.exit_code, 0) << newmark.output;
  }
}
