// MPI for as long as a session lives: initialised by the first session in the process (threads
// FUNNELED: only the main thread calls MPI; rank 0 of a study runs jobs on a second thread that
// makes no MPI call) and finalised by that session when it is destroyed, unless an exception is
// unwinding it on a job of several ranks: the error may be this rank's alone, and MPI_Finalize
// waits for ranks that wait in a collective for this one. Exiting unfinalised with the error's
// exit code, the rank has mpirun end the job.
#pragma once

namespace isolab::study {

class MpiSession {
 public:
  // Throws std::runtime_error when MPI cannot be initialised.
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  // MPI_THREAD_FUNNELED (or better) provided, or a single rank, which never needs it.
  bool funneled() const { return funneled_; }

 private:
  bool initialised_here_ = false;
  int exceptions_at_start_ = 0;  // std::uncaught_exceptions() when the session began
  int rank_ = 0, size_ = 1;
  bool funneled_ = true;
};

}  // namespace isolab::study
