// Output files: only new or regular files are replaced, a missing folder is an error that says
// so, every writer has its own temporary file, and nothing is left behind.
#include "isolab/io/atomic_file.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
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

namespace fs = std::filesystem;

fs::path FreshFolder(const std::string& name) {
  const fs::path folder = isolab::testing::OwnTestDirectory() / name;
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

std::string Read(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string ErrorOf(const std::string& path) {
  try {
    CheckOutputPath(path);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(AtomicFile, RefusesToReplaceAnythingButARegularFile) {
  const fs::path folder = FreshFolder("kinds");
  EXPECT_NE(ErrorOf("/dev/null").find("/dev/null: is a character device"), std::string::npos)
      << ErrorOf("/dev/null");
  EXPECT_NE(ErrorOf(folder.string()).find("is a folder"), std::string::npos);
  const fs::path fifo = folder / "pipe.csv";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_NE(ErrorOf(fifo.string()).find("is a named pipe"), std::string::npos);
  EXPECT_THROW(WriteTextFileAtomically(fifo.string(), [](std::ostream& out) { out << "x"; }),
               InputError);
  EXPECT_TRUE(fs::is_fifo(fifo));
  // A symbolic link to a regular file is not replaced by a file either.
  const fs::path target = folder / "target.csv", link = folder / "link.csv";
  { std::ofstream(target) << "kept"; }
  fs::create_symlink(target, link);
  EXPECT_NE(ErrorOf(link.string()).find("is a symbolic link"), std::string::npos);
  EXPECT_THROW(Hdf5File{link.string()}, InputError);
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(Read(target), "kept");
  EXPECT_TRUE(testing::LeftoverTemporaries(link).empty());
}

TEST(AtomicFile, MissingFolderIsAnErrorThatSaysSo) {
  const fs::path folder = FreshFolder("missing");
  const std::string message = ErrorOf((folder / "no" / "such" / "out.h5").string());
  EXPECT_NE(message.find("the folder '" + (folder / "no" / "such").string() + "' does not exist"),
            std::string::npos)
      << message;
  EXPECT_FALSE(fs::exists(folder / "no"));  // and it is not created behind the user's back
  EXPECT_NE(ErrorOf("").find("empty"), std::string::npos);
}

TEST(AtomicFile, EachWriterHasItsOwnTemporaryFile) {
  const fs::path folder = FreshFolder("writers");
  const std::string path = (folder / "out.csv").string();
  {
    AtomicFile first(path), second(path);
    EXPECT_NE(first.temporary_path(), second.temporary_path());
    { std::ofstream(first.temporary_path()) << "first"; }
    { std::ofstream(second.temporary_path()) << "second"; }
    // Unnamed while they are written (O_TMPFILE on this file system): nothing shows in the folder.
    EXPECT_TRUE(testing::LeftoverTemporaries(folder / "out.csv").empty());
    first.Commit();
    EXPECT_EQ(Read(path), "first");
    second.Commit();  // the last writer wins, whole
    EXPECT_EQ(Read(path), "second");
  }
  EXPECT_TRUE(testing::LeftoverTemporaries(folder / "out.csv").empty());
  {
    AtomicFile abandoned(path);  // destroyed without Commit: the target is untouched
    { std::ofstream(abandoned.temporary_path()) << "half"; }
  }
  EXPECT_EQ(Read(path), "second");
  EXPECT_TRUE(testing::LeftoverTemporaries(folder / "out.csv").empty());
}

TEST(AtomicFile, FailedWriterLeavesNothing) {
  const fs::path folder = FreshFolder("failed");
  const std::string path = (folder / "out.txt").string();
  EXPECT_THROW(
      WriteTextFileAtomically(path, [](std::ostream&) { throw InputError({"x"}, "failed"); }),
      InputError);
  EXPECT_FALSE(fs::exists(path));
  EXPECT_TRUE(testing::LeftoverTemporaries(path).empty());
}

// A writer killed with SIGKILL in the middle of its output runs no destructor: its temporary
// file had a name, "<target>.<random>.tmp", and stayed (8 after 10 kills, up to 46 MB each). A
// text file's is unnamed now and goes with the process; an HDF5 file's keeps a name (HDF5 opens
// it by a path it resolves), with the writer's pid in it, and the next writer of the target
// removes it.
TEST(AtomicFile, AWriterKilledWithSigkillLeavesNothingBehind) {
  const fs::path folder = FreshFolder("killed");
  for (const std::string name : {"out.csv", "out.h5"}) {
    const fs::path target = folder / name;
    int ready[2];
    ASSERT_EQ(pipe(ready), 0);
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      close(ready[0]);
      if (target.extension() == ".h5") {
        Hdf5File file(target.string());
        Hdf5File::Rows rows = file.CreateRows("history", 10, "mm", 1000);
        rows.Append(std::vector<double>(10 * 1000, 1.0));
        ASSERT_EQ(write(ready[1], "w", 1), 1);
        pause();  // killed here, the file half written
      }
      WriteTextFileAtomically(target.string(), [&](std::ostream& out) {
        out << std::string(1 << 20, 'x') << std::flush;
        EXPECT_EQ(write(ready[1], "w", 1), 1);
        pause();
      });
      _exit(0);
    }
    close(ready[1]);
    char byte = 0;
    ASSERT_EQ(read(ready[0], &byte, 1), 1) << name;  // the writer has written
    close(ready[0]);
    kill(child, SIGKILL);
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status));
    EXPECT_FALSE(fs::exists(target)) << name;
    EXPECT_EQ(testing::LeftoverTemporaries(target).size(), name == "out.h5" ? 1u : 0u) << name;
    // The next writer of the target writes it whole, and nothing else is left.
    WriteTextFileAtomically(target.string(), [](std::ostream& out) { out << "next"; });
    EXPECT_EQ(Read(target), "next");
    EXPECT_TRUE(testing::LeftoverTemporaries(target).empty()) << name;
  }
}

// Where a temporary file has a name (file systems without O_TMPFILE, or the instant between the
// link and the rename of a commit), the writer's pid is in it: the next writer of the target
// removes those of processes that no longer exist, and nobody else's.
TEST(AtomicFile, TheNextWriterRemovesTheNamedTemporariesOfDeadWriters) {
  const fs::path folder = FreshFolder("stale");
  const fs::path target = folder / "out.h5";
  const pid_t dead = fork();
  ASSERT_GE(dead, 0);
  if (dead == 0) _exit(0);
  ASSERT_EQ(waitpid(dead, nullptr, 0), dead);  // reaped: no process has its pid now
  const std::string stale = fmt::format("out.h5.{}.AbC123.tmp", dead);
  const std::string live = fmt::format("out.h5.{}.AbC123.tmp", getpid());
  for (const std::string& name : {stale, live, std::string("out.h5.AbC123.tmp"),
                                  fmt::format("other.h5.{}.AbC123.tmp", dead)}) {
    std::ofstream(folder / name) << "half";
  }
  WriteTextFileAtomically(target.string(), [](std::ostream& out) { out << "new"; });
  EXPECT_FALSE(fs::exists(folder / stale));
  EXPECT_TRUE(fs::exists(folder / live));                 // a writer still at work
  EXPECT_TRUE(fs::exists(folder / "out.h5.AbC123.tmp"));  // no pid: whose is unknown
  EXPECT_TRUE(fs::exists(folder / fmt::format("other.h5.{}.AbC123.tmp", dead)));  // not ours
  EXPECT_EQ(Read(target), "new");
}

}  // namespace
}  // namespace isolab::io
