// Whether mpirun started this process, read from the environment before MPI is initialised:
// the commands that run on ranks (compare, fit, diagnose) decide with it whether to start MPI at
// all.
#pragma once

namespace isolab::study {

// True when this process was started by mpirun (OpenMPI's OMPI_COMM_WORLD_SIZE, or PMI/PMIx's
// variables, in the environment).
bool LaunchedByMpirun();
// This process's rank from the same variables, before MPI is initialised; 0 without mpirun.
int LaunchRank();

}  // namespace isolab::study
