#include "isolab/study/mpi_task_spread.h"

#include <mpi.h>

#include "mpi_session.h"

namespace isolab::study {
namespace {

class MpiTaskSpread final : public identification::TaskSpread {
 public:
  int Ranks() const override { return session_.size(); }
  int Rank() const override { return session_.rank(); }

  // Three collective steps: whether any rank failed, every task's length, every task's numbers.
  // Rank r's share is tasks r, r + R, r + 2R, ..., so each rank knows every other's count.
  std::optional<std::vector<std::vector<double>>> Gather(std::size_t count,
                                                         std::vector<std::vector<double>> owned,
                                                         bool failed) const override {
    int any_failed = failed ? 1 : 0;
    MPI_Allreduce(MPI_IN_PLACE, &any_failed, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    if (any_failed) return std::nullopt;

    const int ranks = Ranks();
    std::vector<int> tasks_of(std::size_t(ranks), 0), task_offsets(std::size_t(ranks), 0);
    for (int r = 0; r < ranks; ++r) {
      tasks_of[std::size_t(r)] = int(identification::OwnedTasks(count, r, ranks));
      if (r > 0)
        task_offsets[std::size_t(r)] =
            task_offsets[std::size_t(r - 1)] + tasks_of[std::size_t(r - 1)];
    }
    std::vector<int> my_lengths;
    std::vector<double> my_numbers;
    for (const std::vector<double>& output : owned) {
      my_lengths.push_back(int(output.size()));
      my_numbers.insert(my_numbers.end(), output.begin(), output.end());
    }
    std::vector<int> lengths(count, 0);  // in rank order: rank 0's tasks, then rank 1's, ...
    MPI_Allgatherv(my_lengths.data(), int(my_lengths.size()), MPI_INT, lengths.data(),
                   tasks_of.data(), task_offsets.data(), MPI_INT, MPI_COMM_WORLD);

    std::vector<int> numbers_of(std::size_t(ranks), 0), number_offsets(std::size_t(ranks), 0);
    std::size_t total = 0;
    for (int r = 0; r < ranks; ++r) {
      const std::size_t first = std::size_t(task_offsets[std::size_t(r)]);
      for (std::size_t k = 0; k < std::size_t(tasks_of[std::size_t(r)]); ++k) {
        numbers_of[std::size_t(r)] += lengths[first + k];
      }
      number_offsets[std::size_t(r)] = int(total);
      total += std::size_t(numbers_of[std::size_t(r)]);
    }
    std::vector<double> numbers(total);
    MPI_Allgatherv(my_numbers.data(), int(my_numbers.size()), MPI_DOUBLE, numbers.data(),
                   numbers_of.data(), number_offsets.data(), MPI_DOUBLE, MPI_COMM_WORLD);

    // Back to task order: rank r's k-th task is task r + k R.
    std::vector<std::vector<double>> all(count);
    std::size_t at = 0, slot = 0;
    for (int r = 0; r < ranks; ++r) {
      for (std::size_t k = 0; k < std::size_t(tasks_of[std::size_t(r)]); ++k, ++slot) {
        const auto from = numbers.begin() + long(at);
        all[std::size_t(r) + k * std::size_t(ranks)].assign(from, from + lengths[slot]);
        at += std::size_t(lengths[slot]);
      }
    }
    return all;
  }

 private:
  MpiSession session_;
};

}  // namespace

std::unique_ptr<identification::TaskSpread> MakeMpiTaskSpread() {
  return std::make_unique<MpiTaskSpread>();
}

}  // namespace isolab::study
