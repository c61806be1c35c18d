// Worker processes forked from this one, pulling job indices from one counter in shared memory:
// each has its own copy of everything, HDF5's global lock included, so a job that writes its
// file never waits for another's (threads of one process would share that lock, and at many
// cores it bounded a study's speed-up, docs/compare.md). A worker reports on its own pipe: the
// job it starts (so that a worker that dies is known to have died in that job), then the
// finished job's result as JobResult bytes, and at its end the time it spent handing results
// over. The coordinator only reads the pipes and keeps the results in job order.
#include <fcntl.h>
#include <fmt/format.h>
#include <poll.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "guarded_run.h"
#include "isolab/core/errors.h"
#include "isolab/study/scheduler.h"

namespace isolab::study {
namespace {

using Clock = std::chrono::steady_clock;

enum class Frame : std::uint64_t { kStarted, kFinished, kTotals };

struct FrameHeader {
  Frame kind;
  std::uint64_t size;  // payload bytes
};

struct WorkerTotals {
  double handover_seconds = 0.0;  // writing results into the pipe (blocked while it is full)
};

// The next job index, shared by every worker through an anonymous shared mapping.
class SharedCounter {
 public:
  SharedCounter() {
    void* page =
        mmap(nullptr, sizeof(Counter), PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
    if (page == MAP_FAILED) {
      throw ResourceError("worker processes",
                          fmt::format("cannot map a shared counter: {}", std::strerror(errno)));
    }
    counter_ = new (page) Counter(0);
  }
  ~SharedCounter() { munmap(counter_, sizeof(Counter)); }
  SharedCounter(const SharedCounter&) = delete;
  SharedCounter& operator=(const SharedCounter&) = delete;

  std::size_t Next() { return counter_->fetch_add(1); }

 private:
  using Counter = std::atomic<std::size_t>;
  static_assert(Counter::is_always_lock_free, "the counter is shared between processes");
  Counter* counter_ = nullptr;
};

bool WriteAll(int fd, const void* data, std::size_t size) {
  const char* bytes = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t written = write(fd, bytes, size);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) return false;
    bytes += written;
    size -= static_cast<std::size_t>(written);
  }
  return true;
}

void AppendFrame(Frame kind, const void* payload, std::size_t size, std::vector<char>* out) {
  const FrameHeader header{kind, size};
  const char* bytes = reinterpret_cast<const char*>(&header);
  out->insert(out->end(), bytes, bytes + sizeof header);
  bytes = static_cast<const char*>(payload);
  out->insert(out->end(), bytes, bytes + size);
}

// A worker's jobs, until none is left; false when the coordinator stopped reading. It takes the
// next job before reporting the last, so that both go in one write: one wake-up of the
// coordinator a job.
bool WorkJobs(int fd, SharedCounter& counter, std::size_t count, const RunFunction& run) {
  WorkerTotals totals;
  std::vector<char> message;
  std::uint64_t job = counter.Next();
  bool sent = true;
  if (job < count) {
    AppendFrame(Frame::kStarted, &job, sizeof job, &message);
    sent = WriteAll(fd, message.data(), message.size());
  }
  while (sent && job < count) {
    const std::vector<char> result = Serialize(GuardedRun(run, job));
    const Clock::time_point ran = Clock::now();
    message.clear();
    AppendFrame(Frame::kFinished, result.data(), result.size(), &message);
    job = counter.Next();
    if (job < count) AppendFrame(Frame::kStarted, &job, sizeof job, &message);
    sent = WriteAll(fd, message.data(), message.size());
    totals.handover_seconds += std::chrono::duration<double>(Clock::now() - ran).count();
  }
  message.clear();
  AppendFrame(Frame::kTotals, &totals, sizeof totals, &message);
  return sent && WriteAll(fd, message.data(), message.size());
}

// A worker's life: it never returns into the caller's stack, not even by an exception (its
// copies of the coordinator's objects are not its to destroy, nor its buffered output to flush);
// one that escapes the jobs (memory exhausted while sending a result) ends it with status 2.
[[noreturn]] void WorkerMain(int fd, SharedCounter& counter, std::size_t count,
                             const RunFunction& run) noexcept {
  int status = 2;
  try {
    status = WorkJobs(fd, counter, count, run) ? 0 : 1;
  } catch (...) {
  }
  close(fd);
  _exit(status);
}

std::string DescribeEnd(int status) {
  if (WIFSIGNALED(status)) {
    return fmt::format("killed by signal {} ({})", WTERMSIG(status), strsignal(WTERMSIG(status)));
  }
  if (WIFEXITED(status)) return fmt::format("exited with status {}", WEXITSTATUS(status));
  return "ended";
}

// One worker as the coordinator sees it: its pipe, the bytes read and not yet parsed, and the job
// it said it started.
struct Worker {
  pid_t pid = -1;
  int fd = -1;
  std::vector<char> buffer;
  std::optional<std::size_t> running;
};

class ProcessScheduler final : public Scheduler {
 public:
  explicit ProcessScheduler(int processes) : processes_(std::max(1, processes)) {}

  ScheduleOutcome Run(std::size_t count, const RunFunction& run,
                      const ProgressFunction& progress) override {
    const Clock::time_point start = Clock::now();
    outcome_ = {};
    outcome_.results.resize(count);
    reported_.assign(count, false);
    done_ = 0;
    if (count > 0) {
      SharedCounter counter;
      StartWorkers(std::min<std::size_t>(static_cast<std::size_t>(processes_), count), counter,
                   count, run);
      try {
        Collect(count, progress);
      } catch (...) {
        StopWorkers();
        throw;
      }
    }
    // A job no worker reported: its worker died after taking it and before saying so (or none
    // was left to take it).
    for (std::size_t job = 0; job < count; ++job) {
      if (!reported_[job])
        Fail(job, "not run: its worker process ended before starting it", progress);
    }
    outcome_.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return std::move(outcome_);
  }

  bool IsCoordinator() const override { return true; }
  std::string Describe() const override {
    return fmt::format("{} process{}", processes_, processes_ == 1 ? "" : "es");
  }

 private:
  void StartWorkers(std::size_t count, SharedCounter& counter, std::size_t jobs,
                    const RunFunction& run) {
    workers_.clear();
    workers_.reserve(count);  // no allocation (nor its failure) between a fork and its record
    for (std::size_t k = 0; k < count; ++k) {
      int fds[2];
      if (pipe2(fds, O_CLOEXEC) != 0) break;
      const pid_t pid = fork();
      if (pid == 0) {
        close(fds[0]);
        for (const Worker& other : workers_) close(other.fd);
        WorkerMain(fds[1], counter, jobs, run);
      }
      close(fds[1]);
      if (pid < 0) {
        close(fds[0]);
        break;
      }
      workers_.push_back({pid, fds[0], {}, std::nullopt});
    }
    if (workers_.empty()) {
      throw ResourceError("worker processes",
                          fmt::format("cannot start one: {}", std::strerror(errno)));
    }
  }

  // Reads every pipe until each worker has closed its own, then reaps the workers.
  void Collect(std::size_t count, const ProgressFunction& progress) {
    std::vector<pollfd> polled;
    char chunk[1 << 16];
    for (;;) {
      polled.clear();
      for (const Worker& worker : workers_) {
        if (worker.fd >= 0) polled.push_back({worker.fd, POLLIN, 0});
      }
      if (polled.empty()) break;
      if (poll(polled.data(), polled.size(), -1) < 0) {
        if (errno == EINTR) continue;
        throw ResourceError("worker processes",
                            fmt::format("cannot wait for them: {}", std::strerror(errno)));
      }
      for (Worker& worker : workers_) {
        const auto it = std::find_if(polled.begin(), polled.end(),
                                     [&](const pollfd& p) { return p.fd == worker.fd; });
        if (it == polled.end() || it->revents == 0) continue;
        const ssize_t got = read(worker.fd, chunk, sizeof chunk);
        if (got < 0 && errno == EINTR) continue;
        if (got > 0) {
          worker.buffer.insert(worker.buffer.end(), chunk, chunk + got);
          Parse(worker, count, progress);
          continue;
        }
        close(worker.fd);
        worker.fd = -1;
        int status = 0;
        pid_t reaped = -1;
        while ((reaped = waitpid(worker.pid, &status, 0)) < 0 && errno == EINTR) {
        }
        worker.pid = -1;
        if (worker.running) {
          Fail(*worker.running,
               fmt::format("its worker process ended while running it: {}",
                           reaped < 0 ? std::string("how, unknown") : DescribeEnd(status)),
               progress);
        }
      }
    }
  }

  void Parse(Worker& worker, std::size_t count, const ProgressFunction& progress) {
    std::size_t at = 0;
    while (worker.buffer.size() - at >= sizeof(FrameHeader)) {
      FrameHeader header;
      std::memcpy(&header, worker.buffer.data() + at, sizeof header);
      if (worker.buffer.size() - at - sizeof header < header.size) break;
      const char* payload = worker.buffer.data() + at + sizeof header;
      at += sizeof header + header.size;
      if (header.kind == Frame::kStarted && header.size == sizeof(std::uint64_t)) {
        std::uint64_t job = 0;
        std::memcpy(&job, payload, sizeof job);
        if (job < count) worker.running = job;
      } else if (header.kind == Frame::kFinished) {
        JobResult result = Deserialize({payload, header.size});
        worker.running.reset();
        if (result.job < count && !reported_[result.job]) Report(std::move(result), progress);
      } else if (header.kind == Frame::kTotals && header.size == sizeof(WorkerTotals)) {
        WorkerTotals totals;
        std::memcpy(&totals, payload, sizeof totals);
        outcome_.waiting_seconds += totals.handover_seconds;
      } else {
        throw std::runtime_error("a worker process sent what no worker writes");
      }
    }
    worker.buffer.erase(worker.buffer.begin(), worker.buffer.begin() + static_cast<long>(at));
  }

  void Report(JobResult result, const ProgressFunction& progress) {
    const std::size_t job = result.job;
    if (!result.completed) ++outcome_.failed;
    outcome_.results[job] = std::move(result);
    reported_[job] = true;
    ++done_;
    if (progress) progress(outcome_.results[job], done_, outcome_.results.size());
  }

  void Fail(std::size_t job, const std::string& message, const ProgressFunction& progress) {
    JobResult result;
    result.job = job;
    result.message = message;
    Report(std::move(result), progress);
  }

  // After a failure on the coordinator's side: the workers still running are of no use.
  void StopWorkers() {
    for (Worker& worker : workers_) {
      if (worker.fd >= 0) close(worker.fd);
      if (worker.pid > 0) {
        kill(worker.pid, SIGKILL);
        int status = 0;
        while (waitpid(worker.pid, &status, 0) < 0 && errno == EINTR) {
        }
      }
    }
    workers_.clear();
  }

  int processes_;
  std::vector<Worker> workers_;
  ScheduleOutcome outcome_;
  std::vector<bool> reported_;
  std::size_t done_ = 0;
};

}  // namespace

std::unique_ptr<Scheduler> MakeProcessScheduler(int processes) {
  return std::make_unique<ProcessScheduler>(processes);
}

int ThreadsOfThisProcess() {
  std::error_code error;
  int threads = 0;
  for (std::filesystem::directory_iterator it("/proc/self/task", error), end; !error && it != end;
       it.increment(error)) {
    ++threads;
  }
  return threads;
}

std::unique_ptr<Scheduler> MakeLocalScheduler(int workers) {
  if (workers <= 1) return MakeThreadScheduler(1);
  // A worker forked while another thread of this process is inside HDF5 would inherit HDF5's
  // lock held, and wait for it for ever. A process with threads of its own (Python's, in a
  // notebook) runs its jobs on threads instead: the same results, its files written one at a
  // time.
  if (ThreadsOfThisProcess() != 1) return MakeThreadScheduler(workers);
  return MakeProcessScheduler(workers);
}

}  // namespace isolab::study
