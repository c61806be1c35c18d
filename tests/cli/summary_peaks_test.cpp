// One table of a run's headline peaks (analysis/summary_peaks.h) behind every output: for an
// SDOF, a fixed-base frame, an isolated shear building and a building in plan, each peak the
// table lists for the structure is in the text summary (its label), the JSON report, the HDF5
// file's /peaks and the CSV file's '# peak' lines, with the same value; and no output lists a
// peak the table does not.
#include "isolab/analysis/summary_peaks.h"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "cli/run_isolab.h"
#include "cli/text_file.h"
#include "isolab/analysis/problem.h"
#include "isolab/model/model_file.h"
#include "own_test_file.h"

namespace isolab::analysis {
namespace {

namespace fs = std::filesystem;

double Hdf5Peak(const fs::path& file, const std::string& name) {
  const hid_t h5 = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  double value = NAN;
  if (H5Lexists(h5, ("peaks/" + name).c_str(), H5P_DEFAULT) > 0) {
    const hid_t dataset = H5Dopen2(h5, ("peaks/" + name).c_str(), H5P_DEFAULT);
    H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, &value);
    H5Dclose(dataset);
  }
  H5Fclose(h5);
  return value;
}

// The names of the datasets in /peaks.
std::set<std::string> Hdf5PeakNames(const fs::path& file) {
  std::set<std::string> names;
  const hid_t h5 = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t group = H5Gopen2(h5, "peaks", H5P_DEFAULT);
  hsize_t count = 0;
  H5Gget_num_objs(group, &count);
  for (hsize_t i = 0; i < count; ++i) {
    char name[256];
    H5Gget_objname_by_idx(group, i, name, sizeof name);
    if (H5Gget_objtype_by_idx(group, i) == H5G_DATASET) names.insert(name);
  }
  H5Gclose(group);
  H5Fclose(h5);
  return names;
}

class SummaryPeaksEverywhere : public ::testing::TestWithParam<const char*> {};

TEST_P(SummaryPeaksEverywhere, EachOutputListsTheTablesPeaksWithOneValue) {
  const std::string model = std::string(ISOLAB_SOURCE_DIR) + "/" + GetParam();
  const fs::path folder = testing::FreshTestDirectory();
  const Problem problem = Prepare(model::LoadModelFile(model), {});
  const std::vector<NamedPeak> table = SummaryPeaks(problem.layout, ResponsePeaks{});
  ASSERT_GE(table.size(), 3u);

  const testing::Outcome json_run =
      testing::RunIsolab("run " + model + " -q --json -o " + (folder / "r.h5").string());
  ASSERT_EQ(json_run.exit_code, 0) << json_run.output;
  const nlohmann::json json = nlohmann::json::parse(json_run.output);
  const testing::Outcome text =
      testing::RunIsolab("run " + model + " -o " + (folder / "r.csv").string());
  ASSERT_EQ(text.exit_code, 0) << text.output;
  const std::string csv = testing::ReadText(folder / "r.csv");

  std::set<std::string> names;
  for (const NamedPeak& p : table) {
    names.insert(p.name);
    ASSERT_TRUE(json["peaks"].contains(p.name)) << p.name << "\n" << json["peaks"].dump();
    const double value = json["peaks"][p.name]["value"].get<double>();
    EXPECT_EQ(Hdf5Peak(folder / "r.h5", p.name), value) << p.name;
    std::smatch match;
    ASSERT_TRUE(std::regex_search(csv, match,
                                  std::regex(std::string("# peak ") + p.name + ": ([0-9.eE+-]+) ")))
        << p.name;
    EXPECT_NEAR(std::stod(match[1]), value, 5e-6 * std::abs(value) + 1e-300) << p.name;
    ASSERT_TRUE(std::regex_search(text.output, match,
                                  std::regex(std::string("\n") + p.label + " +([0-9.eE+-]+) ")))
        << p.label << "\n"
        << text.output;
    EXPECT_NEAR(std::stod(match[1]), value, 5e-5 * std::abs(value) + 1e-300) << p.label;
  }
  // No output lists more: the JSON's other keys are the drift ratios, numbers of no time.
  for (const auto& [key, value] : json["peaks"].items()) {
    if (key == "story_drift_ratio" || key == "largest_drift_ratio") continue;
    EXPECT_TRUE(names.contains(key)) << key;
  }
  EXPECT_EQ(Hdf5PeakNames(folder / "r.h5"), names);
  const std::regex peak_line("# peak ");
  EXPECT_EQ(std::distance(std::sregex_iterator(csv.begin(), csv.end(), peak_line),
                          std::sregex_iterator()),
            static_cast<std::ptrdiff_t>(names.size()));
}

INSTANTIATE_TEST_SUITE_P(Kinds, SummaryPeaksEverywhere,
                         ::testing::Values("models/chopra/case_c_el_centro_sdof.yaml",
                                           "models/chopra/case_e_five_story_frame.yaml",
                                           "models/buildings/five_story_table9.yaml",
                                           "models/plan/five_story_table9_plan.yaml"),
                         [](const auto& info) { return std::to_string(info.index); });

}  // namespace
}  // namespace isolab::analysis
