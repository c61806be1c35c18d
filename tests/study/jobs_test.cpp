// Job expansion: variant, then record, then scale, the same list whoever runs it.
#include "isolab/study/jobs.h"

#include <gtest/gtest.h>

namespace isolab::study {
namespace {

TEST(Jobs, VariantThenRecordThenScale) {
  const std::vector<Job> jobs = ExpandJobs(2, 3, 2);
  ASSERT_EQ(jobs.size(), 12u);
  std::size_t k = 0;
  for (std::size_t v = 0; v < 2; ++v) {
    for (std::size_t r = 0; r < 3; ++r) {
      for (std::size_t s = 0; s < 2; ++s, ++k) {
        EXPECT_EQ(jobs[k].index, k);
        EXPECT_EQ(jobs[k].variant, v);
        EXPECT_EQ(jobs[k].record, r);
        EXPECT_EQ(jobs[k].scale, s);
      }
    }
  }
  EXPECT_TRUE(ExpandJobs(0, 3, 2).empty());
}

TEST(Jobs, LabelsAndRunFilesNameVariantRecordAndScale) {
  model::StudyFile study;
  study.variants.resize(2);
  study.variants[0].name = "thm1";
  study.variants[1].name = "fixed";
  study.records.resize(2);
  study.records[0].name = "fwn_firm_seed1";
  study.records[1].name = "pulse";
  study.scales = {0.5, 1.0, 1.25};
  const std::vector<Job> jobs = ExpandJobs(study);
  ASSERT_EQ(jobs.size(), 12u);
  EXPECT_EQ(JobLabel(study, jobs[0]), "thm1 / fwn_firm_seed1 x0.5");
  EXPECT_EQ(JobLabel(study, jobs[11]), "fixed / pulse x1.25");
  EXPECT_EQ(RunFileName(study, jobs[4]), "runs/thm1/pulse_x1.h5");
  EXPECT_EQ(RunFileName(study, jobs[6]), "runs/fixed/fwn_firm_seed1_x0.5.h5");
  EXPECT_EQ(ScaleName(0.1), "0.1");
  EXPECT_EQ(ScaleName(1.0 / 3.0), "0.3333333333333333");  // exact: no two scales share a file
}

}  // namespace
}  // namespace isolab::study
