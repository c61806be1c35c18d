// Where a fit's independent tasks run beyond this process. A search's islands and the columns of
// a finite-difference Jacobian are tasks whose outputs are a few numbers. Under a spread over
// several processes (MPI ranks: study/mpi_task_spread.h) each process runs the tasks it owns,
// task % Ranks() == Rank(), on its own threads, and then every process receives every task's
// output: all processes take the same path through the fit, and each ends with the result one
// process alone would have found, to the last digit.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace isolab::identification {

// A task that threw, as every process learns of it: the lowest process where one did, what it
// said, and what kind of error it was, so that the process that reports can say it as that
// process would have.
struct TaskFailure {
  enum class Kind { kInput, kResource, kOther };
  int rank = 0;
  Kind kind = Kind::kOther;
  std::string message;
};

class TaskSpread {
 public:
  virtual ~TaskSpread() = default;
  virtual int Ranks() const = 0;
  virtual int Rank() const = 0;
  // Called by every process at the same point with the outputs of the `count` tasks' share it
  // owns, in task order, and this process's failure, if one of its tasks threw. Every process
  // gets every task's output in task order in `all`, or, where a task failed on any process, the
  // failure of the lowest such process.
  struct Gathered {
    std::vector<std::vector<double>> all;
    std::optional<TaskFailure> failure;
  };
  virtual Gathered Gather(std::size_t count, std::vector<std::vector<double>> owned,
                          const std::optional<TaskFailure>& failure) const = 0;
};

// How many of `count` tasks the process `rank` of `ranks` owns.
inline std::size_t OwnedTasks(std::size_t count, int rank, int ranks) {
  const std::size_t r = std::size_t(rank), n = std::size_t(ranks);
  return count > r ? (count - r + n - 1) / n : 0;
}

}  // namespace isolab::identification
