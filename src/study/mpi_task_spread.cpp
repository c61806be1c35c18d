#include "isolab/study/mpi_task_spread.h"

#include <mpi.h>

#include <optional>

#include "mpi_session.h"

namespace isolab::study {
namespace {

// MPI starts at the first task, not before: the inputs are read and checked by then, and a rank
// that refuses them exits before MPI exists, which has mpirun end the job at once.
class MpiTaskSpread final : public identification::TaskSpread {
 public:
  int Ranks() const override { return Session().size(); }
  int Rank() const override { return Session().rank(); }

  // Whether any rank failed first (the lowest that did then tells the others what), else every
  // task's length and then every task's numbers. Rank r's share is tasks r, r + R, r + 2R, ...,
  // so each rank knows every other's count.
  Gathered Gather(std::size_t count, std::vector<std::vector<double>> owned,
                  const std::optional<identification::TaskFailure>& failure) const override {
    int first_failed = failure ? Rank() : Ranks();
    MPI_Allreduce(MPI_IN_PLACE, &first_failed, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    if (first_failed < Ranks()) return {{}, Broadcast(failure, first_failed)};

    const int ranks = Ranks();
    std::vector<int> tasks_of(std::size_t(ranks), 0), task_offsets(std::size_t(ranks), 0);
    for (int r = 0; r < ranks; ++r) {
      tasks_of[std::size_t(r)] = int(identification::OwnedTasks(count, r, ranks));
      if (r > 0) {
        task_offsets[std::size_t(r)] =
            task_offsets[std::size_t(r - 1)] + tasks_of[std::size_t(r - 1)];
      }
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
    return {std::move(all), std::nullopt};
  }

 private:
  // `failure` as rank `root` holds it, on every rank.
  static identification::TaskFailure Broadcast(
      const std::optional<identification::TaskFailure>& failure, int root) {
    identification::TaskFailure shared = failure.value_or(identification::TaskFailure{});
    int head[2] = {static_cast<int>(shared.kind), static_cast<int>(shared.message.size())};
    MPI_Bcast(head, 2, MPI_INT, root, MPI_COMM_WORLD);
    shared.rank = root;
    shared.kind = static_cast<identification::TaskFailure::Kind>(head[0]);
    shared.message.resize(static_cast<std::size_t>(head[1]));
    MPI_Bcast(shared.message.data(), head[1], MPI_CHAR, root, MPI_COMM_WORLD);
    return shared;
  }

  const MpiSession& Session() const {
    if (!session_) session_.emplace();
    return *session_;
  }

  mutable std::optional<MpiSession> session_;
};

}  // namespace

std::unique_ptr<identification::TaskSpread> MakeMpiTaskSpread() {
  return std::make_unique<MpiTaskSpread>();
}

}  // namespace isolab::study
