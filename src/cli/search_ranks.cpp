#include "search_ranks.h"

#include "isolab/study/mpi_launch.h"
#include "isolab/study/mpi_task_spread.h"

namespace isolab::cli {

SearchRanks::SearchRanks() {
  if (!study::LaunchedByMpirun()) return;
  spread_ = study::MakeMpiTaskSpread();
  reports_ = SaysRefusals();  // MPI itself starts with the fit's first task
}

bool SaysRefusals() { return study::LaunchRank() == 0; }

}  // namespace isolab::cli
