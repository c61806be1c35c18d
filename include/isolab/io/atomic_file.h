// Output files appear whole or not at all, and only where a file may be replaced. Every writer
// (text, CSV, HDF5) goes through AtomicFile:
//  * the target's folder must exist (a missing folder is an error that says so, not a surprise
//    folder);
//  * the target must be absent or a regular file: a device (/dev/null), a folder, a pipe, a
//    socket or a symbolic link is never replaced;
//  * the content is written under a unique temporary name in the target's folder
//    ("<target>.<random>.tmp", created exclusively), so two writers to one output never share a
//    temporary file, and renamed over the target only once it is complete and on the disk
//    (fsync of the file before the rename, of its folder after); a writer that fails or is
//    abandoned removes its own temporary file and nobody else's.
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
  // Checks `path` (CheckOutputPath) and creates the temporary file, empty. Throws InputError.
  explicit AtomicFile(std::string path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  const std::string& path() const { return path_; }
  // Where to write: an existing, empty file of this process's making.
  const std::string& temporary_path() const { return temporary_; }

  // Renames the temporary file over `path`, checking again that `path` is not something other
  // than a regular file (it may have changed during a long run). Throws InputError, or
  // ResourceError when the content cannot be synced to the disk.
  void Commit();

 private:
  std::string path_;
  std::string temporary_;
  bool committed_ = false;
};

// Calls `write` on a stream to an AtomicFile and commits it. Throws InputError when the file
// cannot be created or written; nothing is left behind on failure.
void WriteTextFileAtomically(const std::string& path,
                             const std::function<void(std::ostream&)>& write);

}  // namespace isolab::io
