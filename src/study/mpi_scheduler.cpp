#include "isolab/study/mpi_scheduler.h"

#include <fmt/format.h>
#include <mpi.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#include "guarded_run.h"
#include "mpi_session.h"

namespace isolab::study {
namespace {

constexpr int kTagResult = 1;  // rank > 0 to 0: a JobResult's bytes; empty bytes ask for work
constexpr int kTagJob = 2;     // 0 to rank > 0: the next job index, or -1 when there is none

// How long rank 0's main thread sleeps between looks for messages: short against a run (a few
// ms at least; ranks hold their next job meanwhile), long enough that polling costs no core
// (OpenMPI's blocking receive would spin on one).
constexpr auto kPollInterval = std::chrono::microseconds(200);

class MpiScheduler final : public Scheduler {
 public:
  ScheduleOutcome Run(std::size_t count, const RunFunction& run,
                      const ProgressFunction& progress) override {
    return session_.rank() == 0 ? Coordinate(count, run, progress) : Work(run);
  }

  bool IsCoordinator() const override { return session_.rank() == 0; }
  std::string Describe() const override {
    return fmt::format("{} MPI rank{}", session_.size(), session_.size() == 1 ? "" : "s");
  }

 private:
  ScheduleOutcome Coordinate(std::size_t count, const RunFunction& run,
                             const ProgressFunction& progress) {
    const auto start = std::chrono::steady_clock::now();
    ScheduleOutcome outcome;
    outcome.results.resize(count);
    std::atomic<std::size_t> next{0};  // the next job to hand out, locally or to a rank
    std::mutex mutex;                  // guards results, counts and the progress callback
    std::size_t done = 0;
    const auto record = [&](JobResult result) {
      const std::lock_guard lock(mutex);
      const std::size_t job = result.job;
      outcome.results[job] = std::move(result);
      if (!outcome.results[job].completed) ++outcome.failed;
      ++done;
      if (progress) progress(outcome.results[job], done, count);
    };
    std::jthread local;
    // Rank 0 runs jobs on a second thread that makes no MPI call; FUNNELED is what that needs.
    if (session_.funneled()) {
      local = std::jthread([&] {
        for (std::size_t job = next++; job < count; job = next++) record(GuardedRun(run, job));
      });
    }
    // Each rank holds up to two jobs: the one it runs and the next, so it never waits for rank
    // 0's reply between runs. A rank is done once told to stop with no result outstanding.
    const int ranks = session_.size();
    std::vector<int> outstanding(static_cast<std::size_t>(ranks), 0);
    std::vector<bool> stopped(static_cast<std::size_t>(ranks), false);
    const auto hand_out = [&](int rank) {
      const std::size_t job = next++;
      long long reply = job < count ? static_cast<long long>(job) : -1;
      MPI_Send(&reply, 1, MPI_LONG_LONG, rank, kTagJob, MPI_COMM_WORLD);
      if (reply < 0) {
        stopped[rank] = true;
      } else {
        ++outstanding[rank];
      }
    };
    int working = ranks - 1;
    std::vector<char> bytes;
    while (working > 0) {
      int arrived = 0;
      MPI_Status status;
      MPI_Iprobe(MPI_ANY_SOURCE, kTagResult, MPI_COMM_WORLD, &arrived, &status);
      if (!arrived) {
        std::this_thread::sleep_for(kPollInterval);
        continue;
      }
      const int rank = status.MPI_SOURCE;
      int size = 0;
      MPI_Get_count(&status, MPI_BYTE, &size);
      bytes.resize(static_cast<std::size_t>(size));
      MPI_Recv(bytes.data(), size, MPI_BYTE, rank, kTagResult, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      if (size == 0) {  // ready: a job to run and the next
        hand_out(rank);
        if (!stopped[rank]) hand_out(rank);
      } else {
        record(Deserialize(bytes));
        --outstanding[rank];
        if (!stopped[rank]) hand_out(rank);
      }
      if (stopped[rank] && outstanding[rank] == 0) --working;
    }
    if (local.joinable()) local.join();
    outcome.wall_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return outcome;
  }

  // Receives one job ahead (see Coordinate), so the next index is there when a run ends.
  ScheduleOutcome Work(const RunFunction& run) {
    MPI_Send(nullptr, 0, MPI_BYTE, 0, kTagResult, MPI_COMM_WORLD);  // ready
    long long job = -1;
    MPI_Recv(&job, 1, MPI_LONG_LONG, 0, kTagJob, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    while (job >= 0) {
      long long next = -1;
      MPI_Request request;
      MPI_Irecv(&next, 1, MPI_LONG_LONG, 0, kTagJob, MPI_COMM_WORLD, &request);
      const std::vector<char> bytes = Serialize(GuardedRun(run, static_cast<std::size_t>(job)));
      MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, 0, kTagResult,
               MPI_COMM_WORLD);
      MPI_Wait(&request, MPI_STATUS_IGNORE);
      job = next;
    }
    return {};
  }

  MpiSession session_;
};

}  // namespace

std::unique_ptr<Scheduler> MakeMpiScheduler() { return std::make_unique<MpiScheduler>(); }

}  // namespace isolab::study
