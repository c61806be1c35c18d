// A write that fails part way (a full disk; here a real "File too large" from RLIMIT_FSIZE, which
// needs neither root nor a mount) is reported as a ResourceError with the system's reason, leaves
// the old output as it was and no temporary file, and the process then exits normally: HDF5
// 1.10's exit handler once crashed on the file whose close had failed. In a test executable of
// its own, so that HDF5 is untouched when the child process starts, as in isolab.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "isolab/core/errors.h"
#include "isolab/io/hdf5_file.h"
#include "leftover_temporaries.h"
#include "own_test_file.h"

namespace isolab::io {
namespace {

constexpr int kReportedTheFailure = 42;

// In a child process: writes 800 kB of rows to `target` with files limited to 64 kB. Exits with
// kReportedTheFailure when the write failed as a ResourceError naming the system's reason.
[[noreturn]] void WriteTooMuch(const std::string& target) {
  signal(SIGXFSZ, SIG_IGN);  // the write fails with EFBIG instead of killing the process
  const rlimit limit{64 * 1024, 64 * 1024};
  setrlimit(RLIMIT_FSIZE, &limit);
  int code = 1;
  try {
    Hdf5File file(target);
    {
      Hdf5File::Rows rows = file.CreateRows("history", 10, "mm", 10000);
      const std::vector<double> values(10 * 1000, 1.0);
      for (int k = 0; k < 10; ++k) rows.Append(values);
    }
    file.Commit();
  } catch (const ResourceError& error) {
    const std::string message = error.what();
    if (message.find("File too large") != std::string::npos) code = kReportedTheFailure;
  } catch (...) {
  }
  std::exit(code);  // exit handlers run, as at the end of isolab
}

TEST(Hdf5WriteFailure, ReportsTheCauseKeepsTheOldFileAndExitsCleanly) {
  const auto target = testing::FreshTestDirectory() / "out.h5";
  std::ofstream(target) << "the previous results";
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) WriteTooMuch(target.string());
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), kReportedTheFailure);
  std::ifstream in(target);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "the previous results");
  EXPECT_TRUE(testing::LeftoverTemporaries(target).empty());
}

}  // namespace
}  // namespace isolab::io
