// The local schedulers (threads of this process, worker processes) run every job once, return
// results in job order whatever the number of workers, count failures, report each finished job
// once and turn a job's exception into that job's failure. A worker process that dies fails the
// job it was running, saying how it ended, and the jobs it never reached run elsewhere or fail.
// More than one local worker are processes, unless this process runs threads of its own.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <filesystem>
#include <functional>
#include <future>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "isolab/study/scheduler.h"
#include "own_test_file.h"

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

// Worker processes share no memory with the test: each call leaves a file, and a second call of
// the same job finds it there and fails.
RunFunction CountedOnce(const std::filesystem::path& folder, const RunFunction& run) {
  return [folder, run](std::size_t job) {
    const std::string marker = (folder / std::to_string(job)).string();
    const int fd = open(marker.c_str(), O_CREAT | O_EXCL | O_WRONLY, 0644);
    if (fd < 0) throw std::runtime_error("job " + std::to_string(job) + " ran twice");
    close(fd);
    return run(job);
  };
}

void ExpectEveryJobOnceInJobOrder(Scheduler& scheduler) {
  const std::filesystem::path folder = testing::FreshTestDirectory();
  std::vector<std::size_t> progress_done;
  const ScheduleOutcome outcome = scheduler.Run(
      40, CountedOnce(folder, Square), [&](const JobResult&, std::size_t done, std::size_t total) {
        EXPECT_EQ(total, 40u);
        progress_done.push_back(done);
      });
  ASSERT_EQ(outcome.results.size(), 40u);
  for (std::size_t job = 0; job < 40; ++job) {
    EXPECT_TRUE(std::filesystem::exists(folder / std::to_string(job))) << job;
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
  EXPECT_GE(outcome.waiting_seconds, 0.0);
}

TEST(ThreadScheduler, EveryJobOnceInJobOrderWhateverTheThreads) {
  for (const int threads : {1, 2, 5}) {
    SCOPED_TRACE(threads);
    const auto scheduler = MakeThreadScheduler(threads);
    EXPECT_TRUE(scheduler->IsCoordinator());
    ExpectEveryJobOnceInJobOrder(*scheduler);
  }
  EXPECT_EQ(MakeThreadScheduler(2)->Describe(), "2 threads");
  EXPECT_EQ(MakeThreadScheduler(1)->Run(0, Square, nullptr).results.size(), 0u);
}

TEST(ProcessScheduler, EveryJobOnceInJobOrderWhateverTheProcesses) {
  for (const int processes : {1, 2, 5}) {
    SCOPED_TRACE(processes);
    const auto scheduler = MakeProcessScheduler(processes);
    EXPECT_TRUE(scheduler->IsCoordinator());
    ExpectEveryJobOnceInJobOrder(*scheduler);
  }
  EXPECT_EQ(MakeProcessScheduler(2)->Describe(), "2 processes");
  EXPECT_EQ(MakeProcessScheduler(1)->Describe(), "1 process");
  EXPECT_EQ(MakeProcessScheduler(3)->Run(0, Square, nullptr).results.size(), 0u);
}

TEST(ProcessScheduler, AWorkerThatDiesFailsItsJobAndTheOthersRunElsewhere) {
  const auto dies_in_11 = [](std::size_t job) {
    if (job == 11) _exit(3);
    JobResult result;
    result.job = job;
    result.completed = true;
    return result;
  };
  const ScheduleOutcome outcome = MakeProcessScheduler(2)->Run(30, dies_in_11, nullptr);
  ASSERT_EQ(outcome.results.size(), 30u);
  EXPECT_EQ(outcome.failed, 1u);
  EXPECT_FALSE(outcome.results[11].completed);
  EXPECT_EQ(outcome.results[11].message,
            "its worker process ended while running it: exited with status 3");
  for (std::size_t job = 0; job < 30; ++job) {
    if (job != 11) {
      EXPECT_TRUE(outcome.results[job].completed) << job;
    }
  }
}

// An exception that is no std::exception passes a job's guard: it must end its worker (status
// 2), never return into the test from the forked copy.
TEST(ProcessScheduler, AnExceptionOutsideTheGuardEndsItsWorkerOnly) {
  const ScheduleOutcome outcome = MakeProcessScheduler(2)->Run(
      8,
      [](std::size_t job) -> JobResult {
        if (job == 5) throw 42;
        JobResult result;
        result.job = job;
        result.completed = true;
        return result;
      },
      nullptr);
  EXPECT_EQ(outcome.failed, 1u);
  EXPECT_EQ(outcome.results[5].message,
            "its worker process ended while running it: exited with status 2");
}

TEST(ProcessScheduler, WithItsOnlyWorkerDeadTheJobsLeftFailSayingSo) {
  std::size_t reported = 0;
  const ScheduleOutcome outcome = MakeProcessScheduler(1)->Run(
      6,
      [](std::size_t job) {
        if (job == 2) raise(SIGKILL);
        JobResult result;
        result.job = job;
        result.completed = true;
        return result;
      },
      [&](const JobResult&, std::size_t done, std::size_t) { reported = done; });
  EXPECT_EQ(reported, 6u);
  EXPECT_EQ(outcome.failed, 4u);
  EXPECT_TRUE(outcome.results[0].completed && outcome.results[1].completed);
  EXPECT_EQ(outcome.results[2].message,
            "its worker process ended while running it: killed by signal 9 (Killed)");
  for (std::size_t job = 3; job < 6; ++job) {
    EXPECT_EQ(outcome.results[job].message, "not run: its worker process ended before starting it");
  }
}

// A fork while another thread may be inside HDF5 could leave a worker waiting for ever on a lock
// its copy holds: a process with threads of its own runs its jobs on threads.
TEST(LocalScheduler, OneWorkerIsThisProcessMoreAreProcessesUnlessThisProcessRunsThreads) {
  ASSERT_EQ(ThreadsOfThisProcess(), 1);
  EXPECT_EQ(MakeLocalScheduler(1)->Describe(), "1 thread");
  EXPECT_EQ(MakeLocalScheduler(4)->Describe(), "4 processes");
  std::promise<void> stop;
  std::thread other([done = stop.get_future()] { done.wait(); });
  EXPECT_EQ(ThreadsOfThisProcess(), 2);
  EXPECT_EQ(MakeLocalScheduler(4)->Describe(), "4 threads");
  stop.set_value();
  other.join();
}

}  // namespace
}  // namespace isolab::study
