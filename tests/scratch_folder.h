// A fresh, empty folder for one test in one process. ctest runs every test in its own process,
// several at a time, and other checkouts may run theirs on the same machine: a fixed /tmp path
// shared by two tests is a race, so the folder is named after the suite, the process and the
// test.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

namespace isolab::testing {

inline std::filesystem::path ScratchFolder(const std::string& suite) {
  const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path folder = std::filesystem::temp_directory_path() /
                                       (suite + "_" + std::to_string(getpid())) /
                                       (test != nullptr ? test->name() : "outside_a_test");
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder;
}

}  // namespace isolab::testing
