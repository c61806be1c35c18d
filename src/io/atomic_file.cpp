#include "isolab/io/atomic_file.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
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

// "<target>.<pid>.<tag>.tmp": the writer's process id in the name, so that the temporary files of
// writers that were killed can be told from those of writers still at work.
std::string NamedTemporary(const std::string& path) {
  return fmt::format("{}.{}.{}.tmp", path, getpid(), RandomTag());
}

// Creates a named temporary file beside `path`, exclusively (the name is ours alone); 0666 lets
// the umask set the permissions, as for any new file.
std::string CreateNamedTemporary(const std::string& path) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    const std::string candidate = NamedTemporary(path);
    const int fd = open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) {
      close(fd);
      return candidate;
    }
    if (errno != EEXIST) {
      throw InputError({path}, fmt::format("cannot create a temporary file beside it ({})",
                                           std::strerror(errno)));
    }
  }
  throw InputError({path}, "cannot find a free temporary file name beside it");
}

// Gives the unnamed file that `proc_path` reaches a named temporary's name.
std::string LinkNamedTemporary(const std::string& path, const std::string& proc_path) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    const std::string candidate = NamedTemporary(path);
    if (linkat(AT_FDCWD, proc_path.c_str(), AT_FDCWD, candidate.c_str(), AT_SYMLINK_FOLLOW) == 0) {
      return candidate;
    }
    if (errno != EEXIST) {
      throw InputError({path}, fmt::format("cannot give the output a name beside it ({})",
                                           std::strerror(errno)));
    }
  }
  throw InputError({path}, "cannot find a free temporary file name beside it");
}

// The process id in a named temporary of `path` ("<target>.<pid>.<tag>.tmp"), or 0.
pid_t WriterOf(const std::string& name, const std::string& target_name) {
  if (!name.starts_with(target_name + ".") || !name.ends_with(".tmp")) return 0;
  const std::string middle = name.substr(target_name.size() + 1,
                                         name.size() - target_name.size() - 1 - 4);  // pid.tag
  const auto dot = middle.find('.');
  if (dot == std::string::npos || dot == 0 || middle.size() - dot - 1 != 6) return 0;
  pid_t pid = 0;
  const auto [end, error] = std::from_chars(middle.data(), middle.data() + dot, pid);
  return error == std::errc() && end == middle.data() + dot && pid > 0 ? pid : 0;
}

}  // namespace

void RemoveStaleTemporaries(const std::string& path) {
  const std::filesystem::path target(path);
  const std::string folder = Folder(path), target_name = target.filename().string();
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
    const std::string name = entry.path().filename().string();
    const pid_t pid = WriterOf(name, target_name);
    // No such process: its writer was killed (a live one, or one of another user, answers 0 or
    // EPERM).
    if (pid > 0 && kill(pid, 0) != 0 && errno == ESRCH) {
      std::filesystem::remove(entry.path(), error);
    }
  }
}

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

AtomicFile::AtomicFile(std::string path, Temporary temporary) : path_(std::move(path)) {
  CheckOutputPath(path_);
  RemoveStaleTemporaries(path_);
  // A file without a name, linked to one only when complete: whatever ends the writer, even
  // SIGKILL or a power cut, the kernel frees it and nothing is left in the folder. It is reached
  // by a path through /proc (HDF5 opens files by name). File systems without O_TMPFILE, or a
  // system without /proc, get a named temporary instead.
  if (temporary == Temporary::kUnnamed && access("/proc/self/fd", X_OK) == 0) {
    fd_ = open(Folder(path_).c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0666);
    if (fd_ >= 0) {
      temporary_ = fmt::format("/proc/self/fd/{}", fd_);
      return;
    }
    if (errno != EOPNOTSUPP && errno != EISDIR && errno != EINVAL) {
      throw InputError({path_}, fmt::format("cannot create a temporary file beside it ({})",
                                            std::strerror(errno)));
    }
  }
  temporary_ = CreateNamedTemporary(path_);
}

AtomicFile::~AtomicFile() {
  if (fd_ >= 0) {
    close(fd_);
  } else if (!committed_) {
    std::remove(temporary_.c_str());
  }
}

void AtomicFile::Commit() {
  CheckReplaceable(path_);
  // The content reaches the disk before the name does: after a crash or a power cut the target
  // is the old file or the new one, never a new name on missing data.
  // A failure here (EIO, ENOSPC on some file systems) is a lost output, reported as such.
  if (const int error = fd_ >= 0 ? (fsync(fd_) == 0 ? 0 : errno) : SyncToDisk(temporary_);
      error != 0) {
    throw ResourceError(path_,
                        fmt::format("cannot write it to the disk ({})", std::strerror(error)));
  }
  // An unnamed file gets a name of its own first (a link cannot replace a file), then takes the
  // target's by rename, atomically; only between the two could a kill leave that name behind,
  // and the next writer of the target removes it (its pid is in the name).
  const std::string named = fd_ >= 0 ? LinkNamedTemporary(path_, temporary_) : temporary_;
  if (std::rename(named.c_str(), path_.c_str()) != 0) {
    const int error = errno;
    if (fd_ >= 0) std::remove(named.c_str());
    throw InputError({path_},
                     fmt::format("cannot rename {} to it ({})", named, std::strerror(error)));
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
