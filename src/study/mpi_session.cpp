#include "mpi_session.h"

#include <mpi.h>

#include <cstdlib>
#include <exception>
#include <initializer_list>
#include <stdexcept>

#include "isolab/study/mpi_launch.h"

namespace isolab::study {
namespace {

const char* FirstVariable(std::initializer_list<const char*> names) {
  for (const char* name : names) {
    if (const char* value = std::getenv(name)) return value;
  }
  return nullptr;
}

}  // namespace

bool LaunchedByMpirun() {
  return FirstVariable({"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"}) != nullptr;
}

int LaunchRank() {
  const char* rank = FirstVariable({"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"});
  return rank != nullptr ? std::atoi(rank) : 0;
}

MpiSession::MpiSession() : exceptions_at_start_(std::uncaught_exceptions()) {
  int initialised = 0;
  MPI_Initialized(&initialised);
  int provided = MPI_THREAD_SINGLE;
  if (initialised) {
    MPI_Query_thread(&provided);
  } else {
    if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
      throw std::runtime_error("MPI_Init_thread failed");
    }
    initialised_here_ = true;
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  funneled_ = provided >= MPI_THREAD_FUNNELED || size_ == 1;
}

MpiSession::~MpiSession() {
  const bool unwinding = std::uncaught_exceptions() > exceptions_at_start_;
  if (initialised_here_ && (!unwinding || size_ == 1)) MPI_Finalize();
}

}  // namespace isolab::study
