#include "plot_script.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "beside_executable.h"
#include "isolab/core/errors.h"

extern char** environ;

namespace isolab::cli {
namespace {

constexpr const char* kInstallHint =
    "install Debian's python3-matplotlib and python3-h5py (scripts/setup.sh does), or set "
    "ISOLAB_PYTHON to a Python 3 that has matplotlib and h5py";

std::string Python() {
  const char* chosen = std::getenv("ISOLAB_PYTHON");
  return chosen != nullptr && *chosen != '\0' ? chosen : "/usr/bin/python3";
}

struct Outcome {
  int exit_code = -1;  // -1: killed by a signal
  std::string errors;  // the script's standard error
};

// Runs python with `arguments`, its stdout on our stderr (or /dev/null), its stderr captured.
Outcome Spawn(const std::string& python, const std::vector<std::string>& arguments, bool quiet) {
  int pipe_fds[2];
  if (pipe(pipe_fds) != 0) {
    throw InputError({"--plot"}, fmt::format("cannot create a pipe ({})", std::strerror(errno)));
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (quiet) {
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  } else {
    posix_spawn_file_actions_adddup2(&actions, STDERR_FILENO, STDOUT_FILENO);
  }
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], STDERR_FILENO);
  posix_spawn_file_actions_addclose(&actions, pipe_fds[0]);
  posix_spawn_file_actions_addclose(&actions, pipe_fds[1]);

  std::vector<std::string> words{python};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);

  // Our own buffered output first, so the terminal shows it before the script's.
  std::cout.flush();
  std::fflush(stdout);
  pid_t pid = 0;
  // posix_spawnp: a name without a slash ("python3.11") is looked up on PATH.
  const int spawned = posix_spawnp(&pid, python.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(pipe_fds[1]);
  if (spawned != 0) {
    close(pipe_fds[0]);
    throw InputError({"--plot"}, fmt::format("cannot run {} ({}); {}", python,
                                             std::strerror(spawned), kInstallHint));
  }
  Outcome outcome;
  char buffer[4096];
  for (ssize_t n; (n = read(pipe_fds[0], buffer, sizeof buffer)) != 0;) {
    if (n < 0) {
      if (errno == EINTR) continue;
      break;
    }
    outcome.errors.append(buffer, static_cast<std::size_t>(n));
  }
  close(pipe_fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  outcome.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return outcome;
}

// The last non-empty lines of a script's error output: enough for a traceback's point.
std::string Tail(const std::string& text, std::size_t max_lines = 12) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty()) lines.push_back(line);
  }
  std::string tail;
  for (std::size_t k = lines.size() > max_lines ? lines.size() - max_lines : 0; k < lines.size();
       ++k) {
    tail += (tail.empty() ? "" : "\n") + lines[k];
  }
  return tail.empty() ? "(no message)" : tail;
}

}  // namespace

std::string PlotScriptPath(const std::string& script_name) {
  return BesideExecutable("share/isolab/scripts/" + script_name, "scripts/" + script_name);
}

std::string PlotDirectory(const std::string& requested, const std::string& output_file) {
  if (!requested.empty()) return requested;
  const std::filesystem::path parent = std::filesystem::path(output_file).parent_path();
  return parent.empty() ? "." : parent.string();
}

void CheckPlotScript(const std::string& script_name) {
  const std::string script = PlotScriptPath(script_name);
  if (!std::filesystem::exists(script)) {
    throw InputError({"--plot"}, fmt::format("the plot script {} is missing (isolab looks for "
                                             "it in ../share/isolab/scripts and scripts beside "
                                             "its executable; cmake --install puts it there)",
                                             script));
  }
  const std::string python = Python();
  const Outcome outcome = Spawn(python, {script, "--check"}, true);
  if (outcome.exit_code != 0) {
    throw InputError({"--plot"}, fmt::format("{} cannot run {}: {}; {}", python, script_name,
                                             Tail(outcome.errors, 3), kInstallHint));
  }
}

void RunPlotScript(const std::string& script_name, const std::vector<std::string>& arguments,
                   bool quiet) {
  const std::string script = PlotScriptPath(script_name);
  std::vector<std::string> words{script};
  words.insert(words.end(), arguments.begin(), arguments.end());
  const std::string python = Python();
  const Outcome outcome = Spawn(python, words, quiet);
  if (outcome.exit_code != 0) {
    throw InputError({"--plot"}, fmt::format("{} {} failed (exit {}):\n{}", python, script_name,
                                             outcome.exit_code, Tail(outcome.errors)));
  }
  if (!quiet && !outcome.errors.empty()) std::cerr << outcome.errors;  // warnings
}

}  // namespace isolab::cli
