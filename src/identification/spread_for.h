// ParallelFor for tasks that may also run on other processes (task_spread.h): each process runs
// the tasks it owns on its threads and ends with every task's output.
#pragma once

#include <fmt/format.h>

#include <exception>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "isolab/core/errors.h"
#include "isolab/identification/task_spread.h"
#include "parallel_for.h"

namespace isolab::identification {

// The failure of a task as the other processes learn of it.
inline TaskFailure FailureOf(std::exception_ptr thrown, int rank) {
  TaskFailure failure{rank, TaskFailure::Kind::kOther, "unknown error"};
  try {
    std::rethrow_exception(thrown);
  } catch (const InputError& error) {
    failure = {rank, TaskFailure::Kind::kInput, error.what()};
  } catch (const ResourceError& error) {
    failure = {rank, TaskFailure::Kind::kResource, error.what()};
  } catch (const std::exception& error) {
    failure.message = error.what();
  } catch (...) {
  }
  return failure;
}

// A failure on another process, thrown here as the kind of error it was there, naming where.
[[noreturn]] inline void ThrowFailureFrom(const TaskFailure& failure) {
  const std::string where = fmt::format("MPI rank {}", failure.rank);
  switch (failure.kind) {
    case TaskFailure::Kind::kInput:
      throw InputError({where}, failure.message);
    case TaskFailure::Kind::kResource:
      throw ResourceError(where, failure.message);
    case TaskFailure::Kind::kOther:
      break;
  }
  throw std::runtime_error(where + ": " + failure.message);
}

// task(i) returns task i's output; `spread` null runs every task here. A task's exception is
// rethrown on the process where it was thrown, and thrown on the others as ThrowFailureFrom says.
template <typename Task>
std::vector<std::vector<double>> SpreadFor(const TaskSpread* spread, std::size_t count, int threads,
                                           const Task& task) {
  const int ranks = spread ? spread->Ranks() : 1, rank = spread ? spread->Rank() : 0;
  std::vector<std::vector<double>> owned(OwnedTasks(count, rank, ranks));
  std::exception_ptr thrown;
  try {
    ParallelFor(owned.size(), threads, [&](std::size_t k) {
      owned[k] = task(std::size_t(rank) + k * std::size_t(ranks));
    });
  } catch (...) {
    if (!spread) throw;
    thrown = std::current_exception();
  }
  if (!spread) return owned;
  std::optional<TaskFailure> mine;
  if (thrown) mine = FailureOf(thrown, rank);
  TaskSpread::Gathered gathered = spread->Gather(count, std::move(owned), mine);
  if (thrown) std::rethrow_exception(thrown);
  if (gathered.failure) ThrowFailureFrom(*gathered.failure);
  return std::move(gathered.all);
}

}  // namespace isolab::identification
