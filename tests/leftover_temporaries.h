// What an interrupted or failed write could leave behind: AtomicFile's named temporary files beside
// a target ("<name>.<pid>.<random>.tmp"). Tests expect none after any command.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace isolab::testing {

inline std::vector<std::string> LeftoverTemporaries(const std::filesystem::path& target) {
  std::vector<std::string> found;
  const std::filesystem::path folder =
      target.parent_path().empty() ? std::filesystem::path(".") : target.parent_path();
  const std::string prefix = target.filename().string() + ".";
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) == 0 && name.size() > 4 && name.ends_with(".tmp")) {
      found.push_back(name);
    }
  }
  return found;
}

}  // namespace isolab::testing
