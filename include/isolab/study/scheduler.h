// Who runs a study's jobs: local threads, or MPI ranks (mpi_scheduler.h). Either way each job
// runs exactly once and the results come back in job order on the coordinating process, so the
// summary does not depend on how many threads or ranks shared the work.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "isolab/study/job_result.h"

namespace isolab::study {

using RunFunction = std::function<JobResult(std::size_t job)>;
// Called on the coordinator as each job finishes, one call at a time; `done` counts up to
// `total` in finishing order.
using ProgressFunction =
    std::function<void(const JobResult& result, std::size_t done, std::size_t total)>;

struct ScheduleOutcome {
  std::vector<JobResult> results;  // every job in job order on the coordinator; empty elsewhere
  std::size_t failed = 0;          // failed jobs, on the coordinator
  double wall_seconds = 0.0;       // from the first job handed out to the last result
  // The workers' time blocked on one another outside their jobs: waiting for the scheduler's
  // lock, or for room to hand a result to the coordinator (local schedulers; zero under MPI). A
  // thread's wait for HDF5's lock while writing its file is inside its job (writing time).
  double waiting_seconds = 0.0;
};

class Scheduler {
 public:
  virtual ~Scheduler() = default;
  virtual ScheduleOutcome Run(std::size_t count, const RunFunction& run,
                              const ProgressFunction& progress) = 0;
  // True on the process that assembles results (the only one without MPI; rank 0 with it).
  virtual bool IsCoordinator() const = 0;
  // "2 threads", "2 MPI ranks".
  virtual std::string Describe() const = 0;
};

// `threads` >= 1 threads of this process pulling job indices from a shared counter.
std::unique_ptr<Scheduler> MakeThreadScheduler(int threads);

// `processes` >= 1 worker processes forked from this one, pulling job indices from a counter
// they share; this process collects their results. Each worker has its own HDF5 (threads share
// the library's global lock, so their files are written one at a time), so a study's runs scale
// as separate processes do. It forks: while it runs, no other thread of this process may be
// inside HDF5. A job's exception is its failure; a worker that dies fails the job it was
// running, saying how the worker ended.
std::unique_ptr<Scheduler> MakeProcessScheduler(int processes);

// What a study on one machine runs on (isolab compare and design, isolab.compare and
// isolab.design): this process alone for one worker; worker processes for more, unless this
// process runs other threads (which a fork could catch inside HDF5), then as many threads.
std::unique_ptr<Scheduler> MakeLocalScheduler(int workers);

// The threads this process runs now (Linux: /proc/self/task); 0 where that cannot be read.
int ThreadsOfThisProcess();

}  // namespace isolab::study
