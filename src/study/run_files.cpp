#include "isolab/study/run_files.h"

#include <algorithm>
#include <chrono>
#include <exception>

#include "isolab/analysis/results_file.h"

namespace isolab::study {
namespace {

double Since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

RunFileWriter::RunFileWriter(std::size_t writers, std::size_t capacity)
    : capacity_(std::max<std::size_t>({capacity, writers, 1})) {
  for (std::size_t k = 0; k < writers; ++k) threads_.emplace_back([this] { Loop(); });
}

RunFileWriter::~RunFileWriter() { Finish(); }

void RunFileWriter::Write(RunFile& file) {
  const auto start = std::chrono::steady_clock::now();
  const analysis::RunDescription run{file.problem.get(), &file.analysis, &file.run,
                                     &file.peaks,        file.version,   file.selection};
  try {
    file.held->Write(run);
  } catch (...) {
    const std::lock_guard lock(mutex_);
    writing_seconds_ += Since(start);
    throw;
  }
  const std::lock_guard lock(mutex_);
  writing_seconds_ += Since(start);
}

double RunFileWriter::Submit(RunFile file) {
  const auto start = std::chrono::steady_clock::now();
  if (threads_.empty()) {
    Write(file);
    return Since(start);
  }
  std::unique_lock lock(mutex_);
  changed_.wait(lock, [&] { return queue_.size() + writing_ < capacity_; });
  queue_.push_back(std::move(file));
  lock.unlock();
  changed_.notify_all();
  return Since(start);
}

void RunFileWriter::Loop() {
  for (;;) {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return !queue_.empty() || stopping_; });
    if (queue_.empty()) return;  // stopping, and nothing left
    // Its room in the queue frees once it is written.
    RunFile file = std::move(queue_.front());
    queue_.pop_front();
    ++writing_;
    lock.unlock();
    std::string failure;
    try {
      Write(file);
    } catch (const std::exception& error) {
      failure = error.what();
    }
    lock.lock();
    if (!failure.empty()) failures_.emplace_back(file.job, std::move(failure));
    --writing_;
    lock.unlock();
    changed_.notify_all();
  }
}

std::vector<std::pair<std::size_t, std::string>> RunFileWriter::Finish() {
  if (!threads_.empty()) {
    {
      const std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    changed_.notify_all();
    for (std::thread& thread : threads_) thread.join();
    threads_.clear();
  }
  const std::lock_guard lock(mutex_);
  return std::exchange(failures_, {});
}

double RunFileWriter::writing_seconds() const {
  const std::lock_guard lock(mutex_);
  return writing_seconds_;
}

}  // namespace isolab::study
