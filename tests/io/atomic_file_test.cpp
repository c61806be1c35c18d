// Output files: only new or regular files are replaced, a missing folder is an error that says
// so, every writer has its own temporary file, and nothing is left behind.
#include "isolab/io/atomic_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

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
    EXPECT_EQ(fs::path(first.temporary_path()).parent_path(), folder);
    { std::ofstream(first.temporary_path()) << "first"; }
    { std::ofstream(second.temporary_path()) << "second"; }
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

}  // namespace
}  // namespace isolab::io
