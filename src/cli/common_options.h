// The options several commands share, declared here once so that each is spelt, checked and
// described alike in every command: -q/--quiet, --json, -o/--output, --seed, --threads (searches:
// the result does not depend on it) and -j/--jobs (studies: worker processes). The default count,
// 0, is one per hardware thread (core/hardware_threads.h).
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "finite_options.h"

namespace isolab::cli {

inline void AddQuietFlag(CLI::App* command, bool* quiet,
                         const std::string& what = "No progress on stderr") {
  command->add_flag("-q,--quiet", *quiet, what);
}

inline void AddJsonFlag(CLI::App* command, bool* json, const std::string& what) {
  command->add_flag("--json", *json, what);
}

// -o/--output: what the command writes (a file, a folder, or one of each kind); `what` says which
// and its default.
template <typename Output>
CLI::Option* AddOutputOption(CLI::App* command, Output* output, const std::string& what) {
  return command->add_option("-o,--output", *output, what);
}

// --seed: the seed of the command's random numbers; `what` says what they draw.
template <typename Seed>
CLI::Option* AddSeedOption(CLI::App* command, Seed* seed, const std::string& what) {
  return command->add_option("--seed", *seed, what);
}

inline void AddThreadsOption(CLI::App* command, int* threads,
                             const std::string& default_count = "every hardware thread") {
  command
      ->add_option("--threads", *threads,
                   "Threads (default: " + default_count + "); the result does not depend on it")
      ->check(CLI::Range(0, 1024));
}

inline void AddJobsOption(CLI::App* command, int* jobs,
                          const std::string& what = "Worker processes") {
  command->add_option("-j,--jobs", *jobs, what + " (default: every hardware thread)")
      ->check(Positive());
}

}  // namespace isolab::cli
