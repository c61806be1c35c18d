// A file in a temporary directory of the running test's own: ctest runs the tests of one suite
// in parallel, so a fixed name under /tmp would be shared between them.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace isolab::testing {

// <TempDir>/<Suite>_<Test>, created.
inline std::filesystem::path OwnTestDirectory() {
  const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
  const auto directory = std::filesystem::path(::testing::TempDir()) /
                         (std::string(test->test_suite_name()) + "_" + test->name());
  std::filesystem::create_directories(directory);
  return directory;
}

// <TempDir>/<Suite>_<Test>/<name>, any earlier file of that name gone.
inline std::filesystem::path OwnTestFile(const std::string& name) {
  const auto path = OwnTestDirectory() / name;
  std::filesystem::remove(path);
  return path;
}

}  // namespace isolab::testing
