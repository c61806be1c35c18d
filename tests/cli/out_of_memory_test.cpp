// Memory running out is a resource error (exit code 3, docs/errors.md), not a crash or an
// "internal error", and leaves no output behind. The memory is really exhausted: isolab runs in a
// shell whose address space is limited (ulimit -v, RLIMIT_AS) to 400 MB. A run streams its
// histories, but its residual displacement is the middle of each isolator's range over the last
// longest period (response_peaks.h), which needs every step of that window: the plan model at
// dt = 5e-7 s holds 5.2 million steps of 2.59 s for each of its four isolators, 500 MB.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli/run_isolab.h"
#include "leftover_temporaries.h"
#include "own_test_file.h"

namespace {

namespace fs = std::filesystem;

const std::string kPlanModel =
    std::string(ISOLAB_SOURCE_DIR) + "/models/plan/five_story_table9_plan.yaml";

// isolab's exit code and stderr, run with at most 400 MB of address space.
isolab::testing::Outcome RunUnder400Mb(const std::string& arguments) {
  return isolab::testing::RunCommandLine("sh -c \"ulimit -v 400000; exec " +
                                         std::string(ISOLAB_BINARY) + " " + arguments +
                                         "\" 2>&1 >/dev/null");
}

TEST(OutOfMemory, ARunBeyondTheMemoryLimitExitsThreeAndWritesNothing) {
#ifdef ISOLAB_SANITIZE
  // ASan reserves terabytes of address space for its shadow memory at start: under any RLIMIT_AS
  // a program cannot even start.
  GTEST_SKIP() << "no address-space limit under AddressSanitizer";
#endif
  // The same limit lets the model's own run (dt = 0.005 s, 8,600 rows) finish.
  const fs::path fits = isolab::testing::OwnTestFile("fits.h5");
  const auto ordinary = RunUnder400Mb("run " + kPlanModel + " -o " + fits.string());
  EXPECT_EQ(ordinary.exit_code, 0) << ordinary.output;
  EXPECT_TRUE(fs::exists(fits));

  const fs::path output = isolab::testing::OwnTestFile("too_large.h5");
  const auto run =
      RunUnder400Mb("run " + kPlanModel + " --dt 5e-7 --max-steps 100000000 -o " + output.string());
  EXPECT_EQ(run.exit_code, 3) << run.output;
  EXPECT_EQ(run.output.rfind("isolab: out of memory", 0), 0u) << run.output;
  EXPECT_FALSE(fs::exists(output));
  EXPECT_TRUE(isolab::testing::LeftoverTemporaries(output).empty());
}

}  // namespace
