#include "beside_executable.h"

#include <cstdlib>
#include <filesystem>

namespace isolab::cli {

std::string ExecutableDirectory() {
  std::error_code error;
  const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
  return error ? "." : executable.parent_path().string();
}

std::string BesideExecutable(const std::string& installed, const std::string& build_tree) {
  const char* front = std::getenv(kFrontDirectoryVariable);
  const std::filesystem::path bin = front != nullptr ? front : ExecutableDirectory();
  const std::filesystem::path candidates[] = {bin / ".." / installed, bin / build_tree};
  std::error_code error;
  for (const auto& candidate : candidates) {
    if (std::filesystem::exists(candidate, error)) return candidate.lexically_normal().string();
  }
  return candidates[0].lexically_normal().string();
}

}  // namespace isolab::cli
