// Output files appear whole or not at all, and only where a file may be replaced. Every writer
// (text, CSV, HDF5) goes through AtomicFile:
//  * the target's folder must exist (a missing folder is an error that says so, not a surprise
//    folder);
//  * the target must be absent or a regular file: a device (/dev/null), a folder, a pipe, a
//    socket or a symbolic link is never replaced;
//  * the content is written to a file of its own in the target's folder that has no name
//    (O_TMPFILE), so two writers to one output never share one and a writer that is killed
//    (SIGKILL, a power cut) leaves nothing behind; once complete and on the disk (fsync) it is
//    linked as "<target>.<pid>.<random>.tmp" and renamed over the target (then its folder is
//    synced). HDF5 files, which HDF5 opens by a path it resolves (realpath(3) fails on an
//    unnamed file's /proc path), and file systems without O_TMPFILE (or a system without /proc)
//    get a temporary file named so from the start, created exclusively;
//  * a writer that fails or is abandoned removes its own temporary file and nobody else's; the
//    named temporary files of the same target whose writer no longer runs (no process has its
//    pid: it was killed) are removed by the next writer of that target.
// Commands check their outputs (output_check.h) before a long analysis, so a bad -o fails at
// once.
#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace isolab::io {

// Throws InputError({path}, ...) when `path` cannot become an output file: its folder is
// missing (or not a folder), or it names something other than a regular file.
void CheckOutputPath(const std::string& path);

// A temporary file beside `path`, renamed to `path` by Commit() or removed on destruction.
class AtomicFile {
 public:
  enum class Temporary {
    kUnnamed,  // O_TMPFILE where the file system has it, else named
    kNamed,    // "<target>.<pid>.<random>.tmp", for writers that resolve the path (HDF5)
  };
  // Checks `path` (CheckOutputPath), removes the named temporary files of its dead writers
  // (RemoveStaleTemporaries) and creates the temporary file, empty. Throws InputError.
  explicit AtomicFile(std::string path, Temporary temporary = Temporary::kUnnamed);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  const std::string& path() const { return path_; }
  // Where to write: an existing, empty file of this process's making, opened by this name
  // ("/proc/self/fd/<n>" for an unnamed file) while the AtomicFile lives.
  const std::string& temporary_path() const { return temporary_; }

  // Renames the temporary file over `path`, checking again that `path` is not something other
  // than a regular file (it may have changed during a long run). Throws InputError, or
  // ResourceError when the content cannot be synced to the disk.
  void Commit();

 private:
  std::string path_;
  std::string temporary_;
  int fd_ = -1;  // the unnamed file (O_TMPFILE); -1 for a named temporary
  bool committed_ = false;
};

// Removes the named temporary files of `path` ("<path>.<pid>.<random>.tmp") whose process no
// longer exists. Another host's writer on a shared file system is not seen: its pid means nothing
// here, so outputs shared between hosts should not be written at the same time.
void RemoveStaleTemporaries(const std::string& path);

// Calls `write` on a stream to an AtomicFile and commits it. Throws InputError when the file
// cannot be created or written; nothing is left behind on failure.
void WriteTextFileAtomically(const std::string& path,
                             const std::function<void(std::ostream&)>& write);

}  // namespace isolab::io
