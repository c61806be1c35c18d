// Jobs over MPI ranks. Rank 0 hands out job indices one at a time as ranks finish jobs (so long
// and short runs balance themselves; each rank holds one index ahead, so it never waits for
// rank 0 between runs) and runs jobs itself on a second thread meanwhile; the other ranks run
// each job they get, write its HDF5 results (the output folder must be shared) and send back
// the JobResult. MPI is initialised by MakeMpiScheduler and finalised
// when the scheduler is destroyed; a process not started by mpirun never touches MPI.
#pragma once

#include <memory>

#include "isolab/study/mpi_launch.h"
#include "isolab/study/scheduler.h"

namespace isolab::study {

// Throws std::runtime_error when MPI cannot be initialised.
std::unique_ptr<Scheduler> MakeMpiScheduler();

}  // namespace isolab::study
