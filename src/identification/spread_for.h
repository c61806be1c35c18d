// ParallelFor for tasks that may also run on other processes (task_spread.h): each process runs
// the tasks it owns on its threads and ends with every task's output.
#pragma once

#include <exception>
#include <stdexcept>
#include <utility>
#include <vector>

#include "isolab/identification/task_spread.h"
#include "parallel_for.h"

namespace isolab::identification {

// task(i) returns task i's output; `spread` null runs every task here. Rethrows a task's
// exception on the process where it was thrown, and throws std::runtime_error on the others.
template <typename Task>
std::vector<std::vector<double>> SpreadFor(const TaskSpread* spread, std::size_t count, int threads,
                                           const Task& task) {
  const int ranks = spread ? spread->Ranks() : 1, rank = spread ? spread->Rank() : 0;
  std::vector<std::vector<double>> owned(OwnedTasks(count, rank, ranks));
  std::exception_ptr failure;
  try {
    ParallelFor(owned.size(), threads, [&](std::size_t k) {
      owned[k] = task(std::size_t(rank) + k * std::size_t(ranks));
    });
  } catch (...) {
    if (!spread) throw;
    failure = std::current_exception();
  }
  if (!spread) return owned;
  auto all = spread->Gather(count, std::move(owned), failure != nullptr);
  if (failure) std::rethrow_exception(failure);
  if (!all) throw std::runtime_error("a task of the fit failed on another MPI rank");
  return std::move(*all);
}

}  // namespace isolab::identification
