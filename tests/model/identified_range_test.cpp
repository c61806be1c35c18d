// isolation.identified_range: read in the model's units, taken from a file the isolation names,
// replaced with the laws of a study's variant, and refused where it is malformed at file:line:col
// with its key path.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "isolab/core/errors.h"
#include "isolab/model/model_file.h"
#include "isolab/model/study_file.h"
#include "own_test_file.h"

namespace isolab::model {
namespace {

const std::string kLaws = "  components: [{name: b, type: bhm2, k0: 13, k1: 3.7, uy: 4.6}]\n";

std::string Bearing(const std::string& range) {
  return "units: {force: kN, length: mm, time: s}\nisolation:\n" + range + kLaws;
}

// The message of the InputError that loading `text` as "lrb.yaml" throws.
std::string ErrorOf(const std::string& text) {
  try {
    LoadModelText(text, "lrb.yaml");
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << text << "\nloaded without error";
  return {};
}

void Write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

TEST(ModelFileIdentifiedRange, IsReadInTheModelsUnitsAndAbsentWithoutOne) {
  const ModelFile model = LoadModelText(
      Bearing("  identified_range: {displacement: 0.1085 m, velocity: 520, cycles: 68.5, data: "
              "[bncs_ica50, \"b 2\"]}\n"),
      "lrb.yaml");
  ASSERT_TRUE(model.identified_range);
  EXPECT_DOUBLE_EQ(model.identified_range->displacement, 108.5);
  EXPECT_DOUBLE_EQ(model.identified_range->velocity, 520.0);
  EXPECT_DOUBLE_EQ(model.identified_range->cycles, 68.5);
  EXPECT_EQ(model.identified_range->data, (std::vector<std::string>{"bncs_ica50", "b 2"}));
  EXPECT_FALSE(LoadModelText(Bearing(""), "lrb.yaml").identified_range);
}

TEST(ModelFileIdentifiedRange, ComesWithTheFileTheIsolationNamesAndGoesWithReplacedLaws) {
  const auto directory = testing::FreshTestDirectory();
  Write(directory / "fitted.yaml",
        Bearing("  identified_range: {displacement: 80, velocity: \"0.3 m/s\", cycles: 3, data: "
                "[a80]}\n"));
  Write(directory / "building.yaml",
        "units: {force: kN, length: mm, time: s}\nisolation: {file: fitted.yaml}\n"
        "structure: {type: sdof, mass: 100 t}\n");
  ModelFile building = LoadModelFile((directory / "building.yaml").string());
  ASSERT_TRUE(building.identified_range);
  EXPECT_DOUBLE_EQ(building.identified_range->displacement, 80.0);
  EXPECT_DOUBLE_EQ(building.identified_range->velocity, 300.0);
  EXPECT_EQ(building.identified_range->data, std::vector<std::string>{"a80"});
  // Laws from elsewhere were not identified on that range.
  ReplaceIsolation(&building, building.isolation);
  EXPECT_FALSE(building.identified_range);
}

TEST(ModelFileIdentifiedRange, AStudysIsolationVariantCarriesItsOwnRange) {
  const auto directory = testing::FreshTestDirectory();
  Write(directory / "fitted.yaml",
        Bearing("  identified_range: {displacement: 80, velocity: 300, cycles: 3, data: [a80]}\n"));
  Write(directory / "building.yaml",
        "units: {force: kN, length: mm, time: s}\nisolation: {file: fitted.yaml}\n"
        "structure: {type: sdof, mass: 100 t}\n");
  Write(directory / "study.yaml",
        "building: building.yaml\nvariants:\n  - {name: as_built}\n"
        "  - {name: inline, isolation: {identified_range: {displacement: 40, velocity: 150, "
        "cycles: 2, data: [a40]}, components: [{type: bhm2, k0: 13, k1: 3.7, uy: 4.6}]}}\n"
        "  - {name: plain, isolation: {components: [{type: bhm2, k0: 13, k1: 3.7, uy: 4.6}]}}\n"
        "records: [" +
            std::string(ISOLAB_SOURCE_DIR) +
            "/ground_motions/elcentro_1940_ns.at2]\nscales: [1]\n");
  const StudyFile study = LoadStudyFile((directory / "study.yaml").string());
  ASSERT_EQ(study.variants.size(), 3u);
  ASSERT_TRUE(study.variants[0].model.identified_range);
  EXPECT_DOUBLE_EQ(study.variants[0].model.identified_range->displacement, 80.0);
  ASSERT_TRUE(study.variants[1].model.identified_range);
  EXPECT_DOUBLE_EQ(study.variants[1].model.identified_range->displacement, 40.0);
  EXPECT_EQ(study.variants[1].model.identified_range->data, std::vector<std::string>{"a40"});
  EXPECT_FALSE(study.variants[2].model.identified_range);
}

TEST(ModelFileIdentifiedRange, MalformedRangesAreLocated) {
  const auto expect = [](const std::string& range, const std::string& where) {
    const std::string message = ErrorOf(Bearing(range));
    EXPECT_EQ(message.rfind("lrb.yaml" + where, 0), 0u) << message;
  };
  expect("  identified_range: {displacement: 0, velocity: 1, cycles: 1, data: [a]}\n", ":3:36:");
  EXPECT_NE(ErrorOf(Bearing("  identified_range: {displacement: -1, velocity: 1, cycles: 1, "
                            "data: [a]}\n"))
                .find("isolation.identified_range.displacement: -1 (must be > 0)"),
            std::string::npos);
  EXPECT_NE(ErrorOf(Bearing("  identified_range: {displacement: 1, velocity: 2 kN, cycles: 1, "
                            "data: [a]}\n"))
                .find("isolation.identified_range.velocity"),
            std::string::npos);
  expect("  identified_range: {displacement: 1, velocity: 1, cycles: -2, data: [a]}\n", ":3:60:");
  EXPECT_NE(ErrorOf(Bearing("  identified_range: {displacement: 1, velocity: 1, cycles: -2, "
                            "data: [a]}\n"))
                .find("isolation.identified_range.cycles: -2 (expected a number of cycles >= 0)"),
            std::string::npos);
  EXPECT_NE(ErrorOf(Bearing("  identified_range: {displacement: 1, velocity: 1, cycles: 1, "
                            "data: []}\n"))
                .find("isolation.identified_range.data: the list is empty"),
            std::string::npos);
  EXPECT_NE(ErrorOf(Bearing("  identified_range: {displacement: 1, velocity: 1, cycles: 1}\n"))
                .find("isolation.identified_range: missing key 'data'"),
            std::string::npos);
  EXPECT_NE(ErrorOf(Bearing("  identified_range: {displacement: 1, velocity: 1, cycle: 1, "
                            "data: [a]}\n"))
                .find("isolation.identified_range.cycle: unknown key (did you mean 'cycles'?)"),
            std::string::npos);
  EXPECT_NE(ErrorOf(Bearing("  identified_range: 108\n"))
                .find("isolation.identified_range: expected a mapping of keys to values"),
            std::string::npos);
  const std::string both = ErrorOf(
      "units: {force: kN, length: mm, time: s}\nisolation:\n  file: other.yaml\n"
      "  identified_range: {displacement: 1, velocity: 1, cycles: 1, data: [a]}\n");
  EXPECT_EQ(both.rfind("lrb.yaml:4:21: isolation.identified_range: is the range of the "
                       "components given here; the file's laws carry their own",
                       0),
            0u)
      << both;
}

}  // namespace
}  // namespace isolab::model
