// Study files: variants built on the model-file machinery, records expanded from globs in byte
// order, and errors located at file:line:column with the key path and what was expected.
#include "isolab/model/study_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "isolab/core/errors.h"
#include "own_test_file.h"

namespace isolab::model {
namespace {

namespace fs = std::filesystem;

std::string TestData(const std::string& relative) {
  return std::string(ISOLAB_TEST_DATA_DIR) + "/" + relative;
}
std::string Source(const std::string& relative) {
  return std::string(ISOLAB_SOURCE_DIR) + "/" + relative;
}

// A folder of its own per test, with the study written into it.
class StudyFileTest : public ::testing::Test {
 protected:
  void SetUp() override { directory_ = testing::FreshTestDirectory(); }

  std::string Write(const std::string& name, const std::string& text) const {
    const fs::path path = directory_ / name;
    std::ofstream(path) << text;
    return path.string();
  }

  // The building, then `rest`; line 1 is the building, so `rest` starts on line 2.
  std::string Study(const std::string& rest) const {
    return Write("study.yaml",
                 "building: " + TestData("study/data/small_building.yaml") + "\n" + rest);
  }

  std::string ErrorOf(const std::string& path) const {
    try {
      LoadStudyFile(path);
    } catch (const InputError& error) {
      return error.what();
    }
    ADD_FAILURE() << path << " loaded without error";
    return {};
  }

  void ExpectError(const std::string& rest, const std::string& location,
                   const std::string& text) const {
    const std::string path = Study(rest);
    const std::string message = ErrorOf(path);
    EXPECT_EQ(message.rfind(path + location, 0), 0u) << message;
    EXPECT_NE(message.find(text), std::string::npos) << message;
  }

  fs::path directory_;
};

const std::string kRecords = "records: [" + Source("ground_motions/pulse_tp2.at2") + "]\n";

TEST_F(StudyFileTest, BundledStudyBuildsEachVariantOnTheBuilding) {
  const StudyFile study = LoadStudyFile(Source("models/studies/five_story_isolators.yaml"));
  ASSERT_EQ(study.variants.size(), 4u);
  EXPECT_EQ(study.variants[0].name, "table9_thm1");
  EXPECT_EQ(study.variants[0].model.isolation.size(), 9u);
  EXPECT_EQ(study.variants[1].model.isolation.size(), 6u);
  EXPECT_EQ(study.variants[2].model.isolation.size(), 1u);
  EXPECT_EQ(study.variants[2].model.isolation.components()[0].name, "bilinear");
  EXPECT_TRUE(study.variants[3].fixed_base);
  EXPECT_FALSE(study.variants[0].fixed_base);
  for (const StudyVariant& variant : study.variants) {
    ASSERT_TRUE(variant.model.structure.has_value()) << variant.name;
    EXPECT_EQ(variant.model.structure->building.stories.size(), 5u) << variant.name;
  }
  // The replaced isolation is recorded in the YAML kept with each run's results.
  EXPECT_NE(study.variants[2].model.text.find("variant bilinear_equivalent"), std::string::npos);
  EXPECT_EQ(study.reference, 0u);
  EXPECT_EQ(study.units.length(), "mm");
  ASSERT_EQ(study.records.size(), 3u);
  EXPECT_EQ(study.records[0].name, "fwn_firm_seed1");
  EXPECT_EQ(study.records[1].name, "fwn_soft_seed2");
  EXPECT_EQ(study.records[2].name, "pulse_tp2");
  EXPECT_EQ(study.scales, (std::vector<double>{0.25, 0.5, 0.75}));
  EXPECT_TRUE(study.output_directory.empty());
}

TEST_F(StudyFileTest, BundledPlanStudyHasPairsAtItsAngles) {
  const StudyFile study = LoadStudyFile(Source("models/studies/five_story_plan_angles.yaml"));
  EXPECT_EQ(study.directions, 2);
  EXPECT_TRUE(study.rotations);
  ASSERT_EQ(study.variants.size(), 1u);
  ASSERT_TRUE(study.variants[0].model.structure.has_value());
  EXPECT_EQ(study.variants[0].model.structure->plan.isolators.size(), 4u);
  ASSERT_EQ(study.records.size(), 4u);
  const double angles[] = {0, 45, 90, 135};
  for (std::size_t r = 0; r < 4; ++r) {
    const StudyRecord& record = study.records[r];
    ASSERT_EQ(record.components.size(), 2u) << record.name;
    EXPECT_EQ(record.name, "firm_at" + std::to_string(static_cast<int>(angles[r])));
    EXPECT_EQ(record.angle, angles[r]);
    // Resolved against the study's folder, as single records are.
    EXPECT_EQ(record.components[0].file, Source("ground_motions/fwn_firm_seed1.at2"));
    EXPECT_EQ(record.components[1].file, Source("ground_motions/h2_fwn_firm_seed3.at2"));
    EXPECT_EQ(record.components[0].scale, 1.0);
  }
  EXPECT_EQ(study.scales, (std::vector<double>{0.6}));
}

TEST_F(StudyFileTest, GlobsExpandInByteOrderAndKeepTheListOrder) {
  fs::create_directories(directory_ / "records");
  for (const char* name : {"b.at2", "B.at2", "a.at2", "c.csv"}) {
    fs::copy_file(Source("ground_motions/pulse_tp2.at2"), directory_ / "records" / name);
  }
  fs::create_directories(directory_ / "records" / "d.at2");  // a folder: not a record
  const std::string path = Study(
      "variants: [{name: thm1}]\n"
      "records: [records/c.csv, 'records/*.at2']\n"
      "scales: [1]\n"
      "output: {directory: out}\n");
  const StudyFile study = LoadStudyFile(path);
  ASSERT_EQ(study.records.size(), 4u);
  EXPECT_EQ(study.records[0].name, "c");
  EXPECT_EQ(study.records[1].name, "B");  // byte order: upper case first, whatever the locale
  EXPECT_EQ(study.records[2].name, "a");
  EXPECT_EQ(study.records[3].name, "b");
  EXPECT_EQ(study.records[2].components[0].file, (directory_ / "records" / "a.at2").string());
  EXPECT_EQ(study.output_directory, "out");
}

// A study's free vibration follows every record, unless a variant's model fixes the run's length:
// that is refused once, at the study's key, not in every run.
TEST_F(StudyFileTest, AFreeVibrationIsRefusedWhereAVariantFixesTheRunsDuration) {
  const std::string records =
      "records: [" + Source("ground_motions/pulse_tp2.at2") + "]\nscales: [1]\n";
  const std::string free =
      Write("free.yaml", "building: " + TestData("study/data/two_story_lrb.yaml") +
                             "\nvariants: [{name: lrb}]\n" + records + "free_vibration: 20\n");
  const StudyFile study = LoadStudyFile(free);
  ASSERT_TRUE(study.free_vibration.has_value());
  EXPECT_FALSE(study.free_vibration->automatic);
  EXPECT_EQ(study.free_vibration->duration, 20.0);
  EXPECT_EQ(study.free_vibration_given_by, free + ":5:17: free_vibration");

  // small_building.yaml fixes analysis.duration.
  ExpectError("variants: [{name: thm1}]\n" + records + "free_vibration: 20\n",
              ":5:17: free_vibration",
              "variant 'thm1' fixes the run's duration (analysis.duration in ");
  StudyFile fixed = LoadStudyFile(Study("variants: [{name: thm1}]\n" + records));
  try {
    SetStudyFreeVibration(fixed, {false, 3.0}, "--free-vibration");
    ADD_FAILURE() << "a free vibration was given to a run of fixed duration";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()).rfind("--free-vibration: variant 'thm1'", 0), 0u)
        << error.what();
  }
  EXPECT_FALSE(fixed.free_vibration.has_value());
}

TEST_F(StudyFileTest, RecordEntriesGiveUnitsStepAndScale) {
  const std::string pulse = Source("ground_motions/pulse_tp2.at2");
  const std::string path = Study(
      "variants: [{name: thm1}]\n"
      "records:\n"
      "  - {file: " +
      pulse +
      ", units: gal, dt: 10 ms, scale: 1.5}\n"
      "  - " +
      TestData("io/data/record_ngaw2.at2") +
      "\n"
      "scales: [1]\n");
  const StudyFile study = LoadStudyFile(path);
  ASSERT_EQ(study.records.size(), 2u);
  EXPECT_EQ(study.records[0].components[0].units, "gal");
  EXPECT_DOUBLE_EQ(study.records[0].components[0].dt, 0.01);
  EXPECT_EQ(study.records[0].components[0].scale, 1.5);
  EXPECT_NE(study.records[0].entry.find(":4:5: records[0]"), std::string::npos)
      << study.records[0].entry;
  EXPECT_EQ(study.records[1].components[0].units, "");
  EXPECT_EQ(study.records[1].components[0].scale, 1.0);

  ExpectError("variants: [{name: a}]\nrecords: [{file: " + pulse + ", unit: g}]\nscales: [1]\n",
              ":3:", "records[0].unit: unknown key (did you mean 'units'?)");
  ExpectError("variants: [{name: a}]\nrecords: [{file: " + pulse + ", units: kN}]\nscales: [1]\n",
              ":3:", "records[0].units: 'kN' is a force unit");
  ExpectError("variants: [{name: a}]\nrecords: [{file: " + pulse + ", scale: 0}]\nscales: [1]\n",
              ":3:", "records[0].scale: 0 (must be a finite number > 0)");
  ExpectError("variants: [{name: a}]\nrecords: [{units: g}]\nscales: [1]\n",
              ":3:", "records[0]: missing key 'file'");
}

TEST_F(StudyFileTest, ModelVariantsAndReferenceByName) {
  const std::string path = Study(
      "variants:\n"
      "  - {name: as_built}\n"
      "  - {name: stuck, model: " +
      TestData("study/data/non_converging_building.yaml") +
      "}\n"
      "  - {name: stuck_fixed, model: " +
      TestData("study/data/non_converging_building.yaml") +
      ", fixed_base: true}\n"
      "reference: stuck\n" +
      kRecords + "scales: [0.5, 1]\n");
  const StudyFile study = LoadStudyFile(path);
  EXPECT_EQ(study.reference, 1u);
  EXPECT_EQ(study.variants[1].model.analysis.newmark.max_iterations, 1);
  EXPECT_EQ(study.variants[0].model.analysis.newmark.max_iterations, 30);
  EXPECT_TRUE(study.variants[2].fixed_base);
}

TEST_F(StudyFileTest, OutputRunsChoosesThePerRunFiles) {
  EXPECT_EQ(LoadStudyFile(Study("variants: [{name: a}]\n" + kRecords + "scales: [1]\n")).runs,
            RunFiles::kFull);
  for (const RunFiles runs : {RunFiles::kNone, RunFiles::kSummary, RunFiles::kFull}) {
    const StudyFile study =
        LoadStudyFile(Study("variants: [{name: a}]\n" + kRecords +
                            "scales: [1]\noutput: {runs: " + RunFilesName(runs) + "}\n"));
    EXPECT_EQ(study.runs, runs) << RunFilesName(runs);
    EXPECT_TRUE(study.output_directory.empty());
  }
  const StudyFile both = LoadStudyFile(Study("variants: [{name: a}]\n" + kRecords +
                                             "scales: [1]\noutput: {directory: d, runs: none}\n"));
  EXPECT_EQ(both.output_directory, "d");
  EXPECT_EQ(both.runs, RunFiles::kNone);
  ExpectError("variants: [{name: a}]\n" + kRecords + "scales: [1]\noutput: {runs: all}\n",
              ":5:16:", "output.runs = all (must be none, summary or full)");
  EXPECT_EQ(ParseRunFiles("summary", "--runs"), RunFiles::kSummary);
  EXPECT_THROW(ParseRunFiles("Full", "--runs"), InputError);
}

TEST_F(StudyFileTest, MalformedStudiesAreLocated) {
  ExpectError("variants: [{name: a}]\n" + kRecords + "scale: [1]\n", ":4:1:",
              "scale: unknown key (did you mean 'scales'?); expected one of: description, "
              "building, variants");
  ExpectError("variants: [{name: a}]\n" + kRecords, ":1:1:", "missing key 'scales'");
  ExpectError("variants: [{name: a, isolaton: {file: x.yaml}}]\n" + kRecords + "scales: [1]\n",
              ":2:22:", "variants[0].isolaton: unknown key (did you mean 'isolation'?)");
  ExpectError("variants: {name: a}\n" + kRecords + "scales: [1]\n",
              ":2:11:", "variants: expected a list");
  ExpectError("variants: [{name: a}]\n" + kRecords + "scales: [1, -0.5]\n",
              ":4:13:", "scales[1]: -0.5 (must be a finite number > 0)");
  ExpectError("variants: [{name: a}]\n" + kRecords + "scales: [1, one]\n",
              ":4:13:", "scales[1]: 'one' is not a number");
  ExpectError("variants: [{name: a}, {name: b, fixed_base: yes}]\n" + kRecords + "scales: [1]\n",
              ":2:45:", "variants[1].fixed_base: 'yes' is not true or false");
  ExpectError("variants: [{name: thm1}, {name: thm1}]\n" + kRecords + "scales: [1]\n",
              ":2:33:", "variants[1].name: 'thm1' is already the name of variants[0]");
  ExpectError("variants: [{name: 'a b'}]\n" + kRecords + "scales: [1]\n",
              ":2:19:", "variants[0].name: 'a b' (a name takes letters, digits, '_', '-' and '.')");
  ExpectError("variants: [{name: thm1}]\nreference: thm2\n" + kRecords + "scales: [1]\n",
              ":3:12:", "reference: 'thm2' is not a variant (did you mean 'thm1'?)");
  ExpectError("variants: [{name: a}]\n" + kRecords + "scales: [1]\noutput: {directory: ''}\n",
              ":5:21:", "output.directory: an empty name (give one, or leave the key out)");
  ExpectError("variants: [{name: a}]\nrecords: ['nowhere/*.at2']\nscales: [1]\n", ":3:11:",
              "records[0]: '" + (directory_ / "nowhere/*.at2").string() + "' matches no file");
  ExpectError("variants: [{name: a}]\nrecords: [missing.at2]\nscales: [1]\n", ":3:11:",
              "records[0]: '" + (directory_ / "missing.at2").string() + "' is not a file");
  ExpectError("variants: [{name: a}]\nrecords: [" + Source("ground_motions/pulse_tp2.at2") + ", " +
                  TestData("cli/../../ground_motions/pulse_tp2.at2") + "]\nscales: [1]\n",
              ":3:", "has the name 'pulse_tp2' of");
  ExpectError("variants: [{name: a, fixed_base: true, isolation: {file: x.yaml}}]\n" + kRecords +
                  "scales: [1]\n",
              ":2:34:", "variants[0].fixed_base: a fixed-base variant has no isolation");
  ExpectError("variants: [{name: a, model: m.yaml, isolation: {file: x.yaml}}]\n" + kRecords +
                  "scales: [1]\n",
              ":2:12:", "variants[0]: give isolation or model, not both");
}

TEST_F(StudyFileTest, VariantIsolationErrorsPointIntoTheStudy) {
  // The model-file readers do the work, so their rules and messages hold here too.
  ExpectError(
      "variants:\n"
      "  - name: soft\n"
      "    isolation:\n"
      "      components: [{name: b, type: bhm2, k0: 1.0, k1: 1.2, uy: 20}]\n" +
          kRecords + "scales: [1]\n",
      ":5:55:", "variants[0].isolation.components[0].k1 = 1.2 (must be < k0 = 1)");
  ExpectError("variants: [{name: a, isolation: {file: " +
                  Source("models/chopra/case_b_elastoplastic_sdof.yaml") + "}}]\n" + kRecords +
                  "scales: [1]\n",
              ":2:40:", "variants[0].isolation.file: '");
  // Errors inside the building's own file name that file.
  const std::string path = Write("bad_building.yaml", "units: {force: kN, length: mm}\n");
  const std::string study = Write("study2.yaml",
                                  "building: bad_building.yaml\n"
                                  "variants: [{name: a}]\n" +
                                      kRecords + "scales: [1]\n");
  EXPECT_EQ(ErrorOf(study).rfind(path + ":1:1: missing key 'isolation'", 0), 0u) << ErrorOf(study);
}

// A record whose name has a glob's characters is that file when it is there (a look-alike that
// the pattern matches was run instead), and a pattern that matches something that is not a file
// (a broken link) is refused, not left out of the suite without a word.
TEST_F(StudyFileTest, ARecordNamedLikeAGlobIsItselfAndAGlobMatchesOnlyFiles) {
  fs::create_directories(directory_ / "recs");
  fs::copy_file(Source("ground_motions/pulse_tp2.at2"), directory_ / "recs" / "rec[1].at2");
  fs::copy_file(Source("ground_motions/elcentro_1940_ns.at2"), directory_ / "recs" / "rec1.at2");
  const StudyFile study =
      LoadStudyFile(Study("variants: [{name: a}]\nrecords: ['recs/rec[1].at2']\n"
                          "scales: [1]\n"));
  ASSERT_EQ(study.records.size(), 1u);
  EXPECT_EQ(study.records[0].name, "rec[1]");
  fs::create_directories(directory_ / "g");
  fs::copy_file(Source("ground_motions/pulse_tp2.at2"), directory_ / "g" / "a.at2");
  fs::create_symlink("/nonexistent/b.at2", directory_ / "g" / "b.at2");
  ExpectError("variants: [{name: a}]\nrecords: ['g/*.at2']\nscales: [1]\n", ":3:11:",
              "records[0]: '" + (directory_ / "g/b.at2").string() + "' (matched by '" +
                  (directory_ / "g/*.at2").string() + "') is not a file");
}

// A building or an isolation file that is not there is refused at the study's key that names it.
TEST_F(StudyFileTest, AFileThatIsNotThereIsRefusedAtTheStudysKey) {
  const std::string study = Write("missing_building.yaml",
                                  "building: no_such_building.yaml\n" + kRecords + "scales: [1]\n");
  EXPECT_EQ(ErrorOf(study).rfind(study + ":1:11: building: '", 0), 0u) << ErrorOf(study);
  EXPECT_NE(ErrorOf(study).find("no_such_building.yaml' is not a file"), std::string::npos);
  ExpectError("variants: [{name: a, isolation: {file: no_such_isolation.yaml}}]\n" + kRecords +
                  "scales: [1]\n",
              ":2:40:", "variants[0].isolation.file: '");
  EXPECT_NE(ErrorOf(Study("variants: [{name: a, isolation: {file: no_such_isolation.yaml}}]\n" +
                          kRecords + "scales: [1]\n"))
                .find("no_such_isolation.yaml' is not a file"),
            std::string::npos);
}

}  // namespace
}  // namespace isolab::model
