// `isolab fit` and `isolab diagnose` under mpirun: each fit's islands and Jacobian columns run
// across the ranks (study/mpi_task_spread.h), each rank ends with the result one process would
// find, and rank 0 alone prints and writes it. Without mpirun, MPI is never started.
#pragma once

#include <memory>

#include "isolab/core/errors.h"
#include "isolab/identification/task_spread.h"

namespace isolab::cli {

class SearchRanks {
 public:
  // The fit's spread when mpirun launched this process; MPI starts with the first task.
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
// is to be said (rank 0, or no mpirun), so that it is said once. Read from the environment, so
// that it holds after MPI has been finalised.
bool SaysRefusals();

// Runs `command(ranks)` on this process's ranks: exit code 0, or 2 without a word on a rank
// other than 0 that meets a refusal (rank 0 says it); other errors propagate.
template <typename Command>
int RunOnSearchRanks(const Command& command) {
  try {
    const SearchRanks ranks;
    command(ranks);
    return 0;
  } catch (const InputError&) {
    if (!SaysRefusals()) return 2;
    throw;
  }
}

}  // namespace isolab::cli
