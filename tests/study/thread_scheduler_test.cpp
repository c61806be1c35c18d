// The thread scheduler runs every job once, returns results in job order whatever the number of
// threads, counts failures, reports each finished job once, and turns a job's exception into
// that job's failure.
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

#include "isolab/study/scheduler.h"

namespace isolab::study {
namespace {

JobResult Square(std::size_t job) {
  if (job == 7) throw std::runtime_error("job 7 throws");
  JobResult result;
  result.job = job;
  result.completed = job % 5 != 3;  // jobs 3, 8, 13, ... fail
  if (!result.completed) result.message = "failed on purpose";
  result.values[0] = static_cast<double>(job * job);
  return result;
}

TEST(ThreadScheduler, EveryJobOnceInJobOrderWhateverTheThreads) {
  for (const int threads : {1, 2, 5}) {
    std::vector<std::atomic<int>> calls(40);
    std::vector<std::size_t> progress_done;
    const auto scheduler = MakeThreadScheduler(threads);
    EXPECT_TRUE(scheduler->IsCoordinator());
    const ScheduleOutcome outcome = scheduler->Run(
        40,
        [&](std::size_t job) {
          ++calls[job];
          return Square(job);
        },
        [&](const JobResult&, std::size_t done, std::size_t total) {
          EXPECT_EQ(total, 40u);
          progress_done.push_back(done);
        });
    ASSERT_EQ(outcome.results.size(), 40u) << threads;
    for (std::size_t job = 0; job < 40; ++job) {
      EXPECT_EQ(calls[job], 1) << job;
      EXPECT_EQ(outcome.results[job].job, job);
      if (job != 7) {
        EXPECT_EQ(outcome.results[job].values[0], static_cast<double>(job * job));
      }
    }
    EXPECT_FALSE(outcome.results[7].completed);
    EXPECT_EQ(outcome.results[7].message, "job 7 throws");
    EXPECT_EQ(outcome.failed, 9u);  // 3, 8, ..., 38, and 7
    ASSERT_EQ(progress_done.size(), 40u);
    for (std::size_t i = 0; i < 40; ++i) EXPECT_EQ(progress_done[i], i + 1);
  }
  EXPECT_EQ(MakeThreadScheduler(2)->Describe(), "2 threads");
  EXPECT_EQ(MakeThreadScheduler(1)->Run(0, Square, nullptr).results.size(), 0u);
}

}  // namespace
}  // namespace isolab::study
