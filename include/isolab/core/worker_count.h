// How many worker processes a study or a design may start: more than kWorkersPerHardwareThread
// per hardware thread only share the same cores, each with its own run buffers, so a count beyond
// that is a slip of the user's (10^6 for 16), refused before anything starts.
#pragma once

#include <string>

namespace isolab {

inline constexpr int kWorkersPerHardwareThread = 8;

// `jobs` (0: one per hardware thread) as the worker count to start; InputError({key}, ...) below
// 0 or beyond kWorkersPerHardwareThread per hardware thread.
int CheckedWorkers(int jobs, const std::string& key);

}  // namespace isolab
