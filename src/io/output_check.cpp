#include "isolab/io/output_check.h"

#include <fmt/format.h>
#include <sys/stat.h>

#include <filesystem>
#include <optional>
#include <utility>

#include "isolab/core/errors.h"
#include "isolab/io/atomic_file.h"

namespace isolab::io {
namespace {

// A file's identity: the same pair for every name of it (relative, absolute, hard link).
std::optional<std::pair<dev_t, ino_t>> Identity(const std::string& path) {
  struct stat status {};
  if (stat(path.c_str(), &status) != 0) return std::nullopt;
  return std::pair{status.st_dev, status.st_ino};
}

// Two outputs that do not exist yet are one file when their absolute, normalised paths agree
// (the folders exist: CheckOutputPath made sure, so only the last name may be new).
bool SameOutput(const std::string& a, const std::string& b) {
  const auto identity_a = Identity(a), identity_b = Identity(b);
  if (identity_a && identity_b) return *identity_a == *identity_b;
  if (identity_a || identity_b) return false;
  std::error_code error_a, error_b;
  const auto canonical_a = std::filesystem::weakly_canonical(std::filesystem::absolute(a), error_a);
  const auto canonical_b = std::filesystem::weakly_canonical(std::filesystem::absolute(b), error_b);
  return !error_a && !error_b && canonical_a == canonical_b;
}

}  // namespace

void CheckInputFiles(const std::vector<std::string>& inputs) {
  for (const std::string& input : inputs) {
    struct stat status {};
    if (stat(input.c_str(), &status) != 0 || S_ISREG(status.st_mode)) continue;
    throw InputError({input}, S_ISDIR(status.st_mode)
                                  ? "is a folder, not a file"
                                  : "is not a regular file (a device or a pipe): isolab reads "
                                    "its inputs only from files");
  }
}

void CheckOutputs(const std::vector<std::string>& inputs, const std::vector<std::string>& outputs) {
  CheckInputFiles(inputs);
  for (std::size_t k = 0; k < outputs.size(); ++k) {
    const std::string& output = outputs[k];
    CheckOutputPath(output);
    if (const auto identity = Identity(output)) {
      for (const std::string& input : inputs) {
        if (Identity(input) != identity) continue;
        throw InputError(
            {output},
            input == output
                ? std::string("is an input of this command; writing it would destroy it (choose "
                              "another output file)")
                : fmt::format("is the input file '{}' under another name; writing it would "
                              "destroy it (choose another output file)",
                              input));
      }
    }
    for (std::size_t j = 0; j < k; ++j) {
      if (SameOutput(outputs[j], output)) {
        throw InputError(
            {output},
            fmt::format("is also the output '{}': each output needs its own file", outputs[j]));
      }
    }
  }
}

}  // namespace isolab::io
