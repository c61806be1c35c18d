// A study's records read once (study/study_records.h): a job handed the record read before the
// study gives the result of a job that reads its file itself, to the bit; a record that cannot be
// read fails each job under it with the message reading it gives.
#include "isolab/study/study_records.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "isolab/core/errors.h"
#include "isolab/study/run_job.h"
#include "own_test_file.h"

namespace isolab::study {
namespace {

const std::string kData = std::string(ISOLAB_TEST_DATA_DIR) + "/study/data/";

std::string ReadError(const std::string& path) {
  try {
    io::ReadRecord(path);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(StudyRecords, AJobHandedItsRecordGivesWhatReadingItGives) {
  const model::StudyFile study = model::LoadStudyFile(kData + "failing_study.yaml");
  const StudyRecords records(study);
  const io::Record* pulse = records.Find(0, 0, 0.0);
  ASSERT_NE(pulse, nullptr);
  const io::Record read = io::ReadRecord(study.records[0].components[0].file);
  EXPECT_EQ(pulse->values, read.values);
  EXPECT_EQ(pulse->dt, read.dt);
  EXPECT_EQ(pulse->path, read.path);
  // Asked for another step (a variant in another time unit): not this read.
  EXPECT_EQ(records.Find(0, 0, 0.01), nullptr);

  const Job job = ExpandJobs(study.variants.size(), study.records.size(), 1)[0];
  const std::string out = testing::OwnTestDirectory().string();
  const JobResult alone = RunJob(study, job, out, "test");
  const JobResult handed = RunJob(study, job, out, "test", &records);
  ASSERT_TRUE(alone.completed) << alone.message;
  ASSERT_TRUE(handed.completed) << handed.message;
  ASSERT_EQ(alone.values.size(), handed.values.size());
  for (std::size_t q = 0; q < alone.values.size(); ++q) {
    // Bit for bit; a quantity the run does not have is NaN in both.
    EXPECT_TRUE(alone.values[q] == handed.values[q] ||
                (std::isnan(alone.values[q]) && std::isnan(handed.values[q])))
        << q;
  }
  EXPECT_EQ(alone.pga, handed.pga);
  EXPECT_EQ(alone.record_units, handed.record_units);
}

TEST(StudyRecords, ARecordThatCannotBeReadFailsEachJobWithItsMessage) {
  const model::StudyFile study = model::LoadStudyFile(kData + "failing_study.yaml");
  const StudyRecords records(study);
  const std::string expected = ReadError(study.records[1].components[0].file);
  ASSERT_FALSE(expected.empty());
  EXPECT_THROW(records.Find(1, 0, 0.0), InputError);
  const Job job = ExpandJobs(study.variants.size(), study.records.size(), 1)[1];
  ASSERT_EQ(job.record, 1u);
  const JobResult result =
      RunJob(study, job, testing::OwnTestDirectory().string(), "test", &records);
  EXPECT_FALSE(result.completed);
  EXPECT_EQ(result.message, expected);
}

}  // namespace
}  // namespace isolab::study
