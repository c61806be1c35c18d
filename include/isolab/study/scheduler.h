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

// `threads` >= 1 workers pulling job indices from a shared counter.
std::unique_ptr<Scheduler> MakeThreadScheduler(int threads);

}  // namespace isolab::study
