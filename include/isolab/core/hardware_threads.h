// How many workers or threads a command uses: the count the user asked for, or with 0 (every
// such option's default) one per hardware thread. std::thread::hardware_concurrency reports 0
// where it cannot tell: then one.
#pragma once

#include <algorithm>
#include <thread>

namespace isolab {

inline int HardwareThreads() {
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

inline int ThreadsOrHardware(int requested) {
  return requested > 0 ? requested : HardwareThreads();
}

}  // namespace isolab
