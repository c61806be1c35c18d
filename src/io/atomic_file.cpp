#include "isolab/io/atomic_file.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>

#include "isolab/core/errors.h"

namespace isolab::io {
namespace {

std::string Folder(const std::string& path) {
  const std::string parent = std::filesystem::path(path).parent_path().string();
  return parent.empty() ? "." : parent;
}

// What a non-regular file is, for messages; empty for a regular file.
std::string KindOf(mode_t mode) {
  if (S_ISREG(mode)) return "";
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISLNK(mode)) return "a symbolic link (give the path of the file it points to)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a named pipe";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

// Throws when `path` exists and is not a regular file (a symbolic link counts as not one).
void CheckReplaceable(const std::string& path) {
  struct stat status {};
  if (lstat(path.c_str(), &status) != 0) {
    if (errno == ENOENT) return;
    throw InputError({path},
                     fmt::format("cannot inspect the output file ({})", std::strerror(errno)));
  }
  const std::string kind = KindOf(status.st_mode);
  if (!kind.empty()) {
    throw InputError({path}, fmt::format("is {}; isolab writes its output only to a new or a "
                                         "regular file and never replaces anything else",
                                         kind));
  }
}

// Forces `path` (a file or a folder) to the disk; returns 0 or the errno of the failure.
int SyncToDisk(const std::string& path) {
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return errno;
  const int result = fsync(fd) == 0 ? 0 : errno;
  close(fd);
  return result;
}

// Six random letters and digits: distinct for every temporary file of every process.
std::string RandomTag() {
  static constexpr char kAlphabet[] =
      "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
  thread_local std::mt19937_64 generator{std::random_device{}() ^
                                         (static_cast<std::uint64_t>(getpid()) << 32)};
  std::uniform_int_distribution<std::size_t> pick(0, sizeof kAlphabet - 2);
  std::string tag(6, ' ');
  for (char& c : tag) c = kAlphabet[pick(generator)];
  return tag;
}

}  // namespace

void CheckOutputPath(const std::string& path) {
  if (path.empty()) throw InputError({"output"}, "the output file name is empty");
  const std::string folder = Folder(path);
  struct stat status {};
  if (stat(folder.c_str(), &status) != 0) {
    throw InputError(
        {path},
        errno == ENOENT
            ? fmt::format("the folder '{}' does not exist (create it first)", folder)
            : fmt::format("cannot reach the folder '{}' ({})", folder, std::strerror(errno)));
  }
  if (!S_ISDIR(status.st_mode)) {
    throw InputError({path}, fmt::format("'{}' is not a folder", folder));
  }
  if (access(folder.c_str(), W_OK | X_OK) != 0) {
    throw InputError(
        {path}, fmt::format("cannot write in the folder '{}' ({})", folder, std::strerror(errno)));
  }
  CheckReplaceable(path);
}

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  CheckOutputPath(path_);
  // O_EXCL: the name is ours alone; 0666 lets the umask set the permissions, as for any new file.
  for (int attempt = 0; attempt < 100; ++attempt) {
    const std::string candidate = fmt::format("{}.{}.tmp", path_, RandomTag());
    const int fd = open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      close(fd);
      temporary_ = candidate;
      return;
    }
    if (errno != EEXIST) {
      throw InputError({path_}, fmt::format("cannot create a temporary file beside it ({})",
                                            std::strerror(errno)));
    }
  }
  throw InputError({path_}, "cannot find a free temporary file name beside it");
}

AtomicFile::~AtomicFile() {
  if (!committed_) std::remove(temporary_.c_str());
}

void AtomicFile::Commit() {
  CheckReplaceable(path_);
  // The content reaches the disk before the name does: after a crash or a power cut the target
  // is the old file or the new one, never a new name on missing data.
  // A failure here (EIO, ENOSPC on some file systems) is a lost output, reported as such.
  if (const int error = SyncToDisk(temporary_); error != 0) {
    throw ResourceError(
        path_, fmt::format("cannot write {} to the disk ({})", temporary_, std::strerror(error)));
  }
  if (std::rename(temporary_.c_str(), path_.c_str()) != 0) {
    throw InputError({path_},
                     fmt::format("cannot rename {} to it ({})", temporary_, std::strerror(errno)));
  }
  committed_ = true;
  // The rename itself; the output is in place whatever this says (some file systems cannot sync
  // a folder), so it is not an error.
  SyncToDisk(Folder(path_));
}

void WriteTextFileAtomically(const std::string& path,
                             const std::function<void(std::ostream&)>& write) {
  AtomicFile file(path);
  {
    std::ofstream stream(file.temporary_path(), std::ios::trunc);
    if (!stream) {
      throw InputError(
          {path}, fmt::format("cannot open {} ({})", file.temporary_path(), std::strerror(errno)));
    }
    write(stream);
    stream.flush();
    if (!stream) throw ResourceError(path, "the write failed (is the disk full?)");
  }
  file.Commit();
}

}  // namespace isolab::io
