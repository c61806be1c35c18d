// A directory of the running test's own. ctest runs every test in its own process, several at a
// time, and other checkouts may run theirs on the same machine: a fixed /tmp path shared by two
// tests is a race, so the directory is named after the suite, the process and the test.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

namespace isolab::testing {

// <tmp>/isolab_<Suite>_<pid>/<Test>, created; what earlier calls in the test wrote stays.
inline std::filesystem::path OwnTestDirectory() {
  const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::string suite = test != nullptr ? test->test_suite_name() : "outside_a_test";
  const std::filesystem::path directory =
      std::filesystem::temp_directory_path() /
      ("isolab_" + suite + "_" + std::to_string(getpid())) /
      (test != nullptr ? test->name() : "outside_a_test");
  std::filesystem::create_directories(directory);
  return directory;
}

// The same directory, emptied.
inline std::filesystem::path FreshTestDirectory() {
  const std::filesystem::path directory = OwnTestDirectory();
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  return directory;
}

// <OwnTestDirectory>/<name>, any earlier file of that name gone.
inline std::filesystem::path OwnTestFile(const std::string& name) {
  const auto path = OwnTestDirectory() / name;
  std::filesystem::remove(path);
  return path;
}

}  // namespace isolab::testing
