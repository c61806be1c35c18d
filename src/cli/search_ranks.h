// `isolab fit` under mpirun: the search's islands and Jacobian columns run across the ranks
// (study/mpi_task_spread.h), each rank ends with the result one process would find, and rank 0
// alone prints and writes it. Without mpirun, MPI is never started.
#pragma once

#include <memory>

#include "isolab/identification/task_spread.h"

namespace isolab::cli {

class SearchRanks {
 public:
  // Starts MPI when mpirun launched this process; throws std::runtime_error when it cannot.
  SearchRanks();

  // Null without mpirun.
  const identification::TaskSpread* spread() const { return spread_.get(); }
  // This process prints progress and results and writes files: rank 0, or no mpirun.
  bool reports() const { return reports_; }
  // The threads each process runs: those given, else one per rank under mpirun (the ranks are
  // the parallelism; mpirun places them on the cores), else 0 (every hardware thread).
  int Threads(int given) const { return given > 0 || !spread_ ? given : 1; }

 private:
  std::unique_ptr<identification::TaskSpread> spread_;
  bool reports_ = true;
};

// --threads' default, as fit and diagnose describe it.
inline constexpr const char* kSearchThreadsDefault =
    "every hardware thread; one per rank under mpirun, over which each fit spreads";

// Under mpirun every rank reads the same inputs and refuses them alike: true where the refusal
// is to be said (rank 0, or no mpirun), so that it is said once.
bool SaysRefusals();

}  // namespace isolab::cli
