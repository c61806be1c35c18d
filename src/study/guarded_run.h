// A scheduler's call of a job: an exception the job function lets through becomes that job's
// failure instead of ending the process (and with it every other job).
#pragma once

#include <exception>

#include "isolab/study/scheduler.h"

namespace isolab::study {

inline JobResult GuardedRun(const RunFunction& run, std::size_t job) {
  try {
    return run(job);
  } catch (const std::exception& error) {
    JobResult result;
    result.job = job;
    result.message = error.what();
    return result;
  }
}

}  // namespace isolab::study
