// Local threads pulling job indices from one atomic counter: a thread that finishes early takes
// the next job, so runs of different lengths balance without a plan.
#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>

#include "guarded_run.h"
#include "isolab/study/scheduler.h"

namespace isolab::study {
namespace {

class ThreadScheduler final : public Scheduler {
 public:
  explicit ThreadScheduler(int threads) : threads_(std::max(1, threads)) {}

  ScheduleOutcome Run(std::size_t count, const RunFunction& run,
                      const ProgressFunction& progress) override {
    const auto start = std::chrono::steady_clock::now();
    ScheduleOutcome outcome;
    outcome.results.resize(count);
    std::atomic<std::size_t> next{0};
    std::mutex mutex;  // guards `done`, `failed`, `waiting_seconds` and the progress callback
    std::size_t done = 0;
    const auto work = [&] {
      for (std::size_t job = next++; job < count; job = next++) {
        // Each job writes only its own slot, so results need no lock.
        outcome.results[job] = GuardedRun(run, job);
        const auto asked = std::chrono::steady_clock::now();
        const std::lock_guard lock(mutex);
        outcome.waiting_seconds +=
            std::chrono::duration<double>(std::chrono::steady_clock::now() - asked).count();
        if (!outcome.results[job].completed) ++outcome.failed;
        ++done;
        if (progress) progress(outcome.results[job], done, count);
      }
    };
    const std::size_t helpers =
        std::min<std::size_t>(static_cast<std::size_t>(threads_), std::max<std::size_t>(count, 1)) -
        1;
    std::vector<std::jthread> pool;
    for (std::size_t i = 0; i < helpers; ++i) pool.emplace_back(work);
    work();        // this thread is one of the workers
    pool.clear();  // joins
    outcome.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return outcome;
  }

  bool IsCoordinator() const override { return true; }
  std::string Describe() const override {
    return fmt::format("{} thread{}", threads_, threads_ == 1 ? "" : "s");
  }

 private:
  int threads_;
};

}  // namespace

std::unique_ptr<Scheduler> MakeThreadScheduler(int threads) {
  return std::make_unique<ThreadScheduler>(threads);
}

}  // namespace isolab::study
