// Where a fit's independent tasks run beyond this process. A search's islands and the columns of
// a finite-difference Jacobian are tasks whose outputs are a few numbers. Under a spread over
// several processes (MPI ranks: study/mpi_task_spread.h) each process runs the tasks it owns,
// task % Ranks() == Rank(), on its own threads, and then every process receives every task's
// output: all processes take the same path through the fit, and each ends with the result one
// process alone would have found, to the last digit.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

namespace isolab::identification {

class TaskSpread {
 public:
  virtual ~TaskSpread() = default;
  virtual int Ranks() const = 0;
  virtual int Rank() const = 0;
  // Called by every process at the same point with the outputs of the `count` tasks' share it
  // owns, in task order, and whether one of its tasks failed. Returns every task's output in task
  // order, or nothing on every process when a task failed on any.
  virtual std::optional<std::vector<std::vector<double>>> Gather(
      std::size_t count, std::vector<std::vector<double>> owned, bool failed) const = 0;
};

// How many of `count` tasks the process `rank` of `ranks` owns.
inline std::size_t OwnedTasks(std::size_t count, int rank, int ranks) {
  const std::size_t r = std::size_t(rank), n = std::size_t(ranks);
  return count > r ? (count - r + n - 1) / n : 0;
}

}  // namespace isolab::identification
