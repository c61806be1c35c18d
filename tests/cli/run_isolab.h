// Runs the built isolab binary for end-to-end tests.
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace isolab::testing {

struct Outcome {
  int exit_code = -1;
  std::string output;  // stdout, or stderr alone when asked
};

// Runs a shell command line as written (redirections included): its exit code and stdout.
inline Outcome RunCommandLine(const std::string& line) {
  Outcome outcome;
  FILE* pipe = popen(line.c_str(), "r");
  if (pipe == nullptr) return outcome;
  std::array<char, 4096> buffer;
  std::size_t n = 0;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
    outcome.output.append(buffer.data(), n);
  const int status = pclose(pipe);
  outcome.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return outcome;
}

// A shell command's exit code and stdout (with stderr when `with_stderr`).
inline Outcome RunShell(const std::string& command, bool with_stderr = false) {
  return RunCommandLine(command + (with_stderr ? " 2>&1" : " 2>/dev/null"));
}

inline Outcome RunIsolab(const std::string& arguments, bool stderr_only = false) {
  return RunCommandLine(std::string(ISOLAB_BINARY) + " " + arguments +
                        (stderr_only ? " 2>&1 >/dev/null" : " 2>/dev/null"));
}

}  // namespace isolab::testing
