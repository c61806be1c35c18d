#include "isolab/core/worker_count.h"

#include <fmt/format.h>

#include "isolab/core/errors.h"
#include "isolab/core/hardware_threads.h"

namespace isolab {

int CheckedWorkers(int jobs, const std::string& key) {
  if (jobs < 0) throw InputError({key}, "must be >= 0 (0: every hardware thread)");
  const int hardware = HardwareThreads();
  if (jobs > kWorkersPerHardwareThread * hardware) {
    throw InputError({key}, fmt::format("{} workers on {} hardware threads: at most {} ({} per "
                                        "hardware thread)",
                                        jobs, hardware, kWorkersPerHardwareThread * hardware,
                                        kWorkersPerHardwareThread));
  }
  return ThreadsOrHardware(jobs);
}

}  // namespace isolab
