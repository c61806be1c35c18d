#include "isolab/study/design_folder.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <system_error>
#include <vector>

#include "isolab/core/errors.h"
#include "isolab/io/atomic_file.h"

namespace isolab::study {
namespace {

namespace fs = std::filesystem;

// The folder's regular files, relative to it, with their sizes; throws InputError for anything
// else (a link, a device), which a design never writes.
std::map<std::string, std::uintmax_t> FilesIn(const fs::path& folder, const std::string& option,
                                              const std::string& shown) {
  std::map<std::string, std::uintmax_t> files;
  try {
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(folder)) {
      const std::string relative = entry.path().lexically_relative(folder).generic_string();
      if (entry.is_symlink() || (!entry.is_regular_file() && !entry.is_directory())) {
        throw InputError({option}, fmt::format("'{}' holds '{}', which a design does not write "
                                               "(not a plain file): give a new or empty folder",
                                               shown, relative));
      }
      if (entry.is_regular_file()) files[relative] = entry.file_size();
    }
  } catch (const fs::filesystem_error& error) {  // a folder it may not read
    throw InputError({option},
                     fmt::format("cannot read the folder '{}': {}", shown, error.code().message()));
  }
  return files;
}

// design_manifest.txt: a line per file, "<size> <path relative to the folder>".
std::map<std::string, std::uintmax_t> ReadManifest(const fs::path& path) {
  std::map<std::string, std::uintmax_t> listed;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::uintmax_t size = 0;
    std::string name;
    fields >> size >> std::ws;
    std::getline(fields, name);
    if (fields.fail() && !fields.eof()) continue;
    listed[name] = size;
  }
  return listed;
}

// What scripts/plot_design.py draws into a design's folder after the design (Python's design()
// leaves the figures to it): its figures (with their metadata) and design.html. The folder is
// still only the design's.
bool DrawnFromTheDesign(const std::string& relative) {
  const fs::path path(relative);
  const std::string name = path.filename().string(), extension = path.extension().string();
  if (path.has_parent_path()) return false;
  if (name == "design.html") return true;
  const std::string stem = path.stem().string();
  const bool figure = stem == "design_spectra" || stem == "design_loops" ||
                      stem == "design_orbits" || stem == "design_drifts";
  return figure && (extension == ".png" || extension == ".pdf" || extension == ".json");
}

bool ProcessRuns(pid_t pid) { return pid > 0 && (kill(pid, 0) == 0 || errno == EPERM); }

// Takes the lock file, or throws InputError naming the design that holds it. A lock left by a
// process that is gone (killed) is taken over.
void TakeLock(const std::string& lock, const std::string& option, const std::string& shown) {
  for (int attempt = 0; attempt < 2; ++attempt) {
    const int fd = open(lock.c_str(), O_CREAT | O_EXCL | O_WRONLY | O_CLOEXEC, 0644);
    if (fd >= 0) {
      const std::string pid = std::to_string(getpid()) + "\n";
      const bool written = write(fd, pid.data(), pid.size()) == static_cast<ssize_t>(pid.size());
      close(fd);
      if (!written) {
        unlink(lock.c_str());
        throw ResourceError(lock, "cannot write the lock file");
      }
      return;
    }
    if (errno != EEXIST) {
      throw InputError({option}, fmt::format("cannot write beside '{}' (the lock file '{}': {})",
                                             shown, lock, std::strerror(errno)));
    }
    pid_t holder = 0;
    std::ifstream(lock) >> holder;
    if (ProcessRuns(holder)) {
      throw InputError({option}, fmt::format("another design (process {}) is writing into '{}': "
                                             "wait for it to finish, or give another folder",
                                             holder, shown));
    }
    std::error_code ignored;
    fs::remove(lock, ignored);
  }
  throw InputError({option}, fmt::format("cannot take the lock file '{}'", lock));
}

// Whether `file` lies inside `folder` (an absolute, normalised path), links and ".." resolved; a
// path that cannot be resolved is taken as outside (the reader names its own problem).
bool IsInside(const fs::path& file, const fs::path& folder) {
  std::error_code file_error, folder_error;
  const fs::path f = fs::weakly_canonical(fs::absolute(file), file_error);
  const fs::path d = fs::weakly_canonical(folder, folder_error);
  if (file_error || folder_error || d.empty()) return false;
  auto part = f.begin();
  for (const fs::path& name : d) {
    if (name.empty()) continue;  // a trailing separator
    if (part == f.end() || *part != name) return false;
    ++part;
  }
  return true;
}

}  // namespace

DesignFolder::DesignFolder(std::string folder, std::string option,
                           const std::vector<DesignInput>& inputs)
    : folder_(std::move(folder)), option_(std::move(option)) {
  fs::path target = fs::absolute(folder_).lexically_normal();
  if (!target.has_filename()) target = target.parent_path();  // "out/" is "out"
  target_ = target.string();
  const fs::path parent = target.parent_path();
  const std::string name = target.filename().string();
  std::error_code error;
  if (name.empty() || name == "." || name == "..") {
    throw InputError({option_}, fmt::format("'{}' is not a folder a design can be written to "
                                            "(give a folder of its own, e.g. {}/design)",
                                            folder_, folder_));
  }
  for (fs::path missing = parent; !missing.empty() && !fs::exists(missing, error);
       missing = missing.parent_path()) {
    created_parents_.push_back(missing.string());
  }
  try {
    if (!created_parents_.empty()) {
      fs::create_directories(parent, error);
      if (error) {
        throw InputError({option_}, fmt::format("cannot make the folder '{}': {}", parent.string(),
                                                error.message()));
      }
    }
    const std::string lock = (parent / ("." + name + ".design-lock")).string();
    TakeLock(lock, option_, folder_);
    lock_ = lock;
  } catch (...) {
    RollBack();
    throw;
  }
  previous_ = (parent / ("." + name + ".design-previous")).string();
  try {
    const fs::file_status status = fs::symlink_status(target);
    existed_ = fs::exists(status);
    if (existed_ && !fs::is_directory(status)) {
      throw InputError({option_}, fmt::format("'{}' is not a folder", folder_));
    }
    std::map<std::string, std::uintmax_t> files;
    if (existed_) files = FilesIn(target, option_, folder_);
    if (existed_ && !fs::is_empty(target)) {
      const fs::path manifest = target / kManifest;
      if (!fs::is_regular_file(manifest)) {
        throw InputError(
            {option_},
            fmt::format("'{}' holds '{}' and no {}: it is not a folder an earlier design wrote, "
                        "and a design replaces nothing else (give a new or empty folder)",
                        folder_, files.empty() ? "folders" : files.begin()->first, kManifest));
      }
      const std::map<std::string, std::uintmax_t> listed = ReadManifest(manifest);
      for (const auto& [file, size] : files) {
        if (file == kManifest || DrawnFromTheDesign(file)) continue;
        const auto it = listed.find(file);
        if (it == listed.end()) {
          throw InputError({option_},
                           fmt::format("'{}' holds '{}', which the earlier design did not write "
                                       "(its {} does not list it): move it out, or give another "
                                       "folder",
                                       folder_, file, kManifest));
        }
        if (it->second != size) {
          throw InputError({option_},
                           fmt::format("'{}': '{}' has changed since the earlier design wrote it "
                                       "({} bytes, the {} says {}): move it out, or give another "
                                       "folder",
                                       folder_, file, size, kManifest, it->second));
        }
      }
      if (fs::exists(fs::symlink_status(previous_))) {
        throw InputError({option_},
                         fmt::format("'{}' holds an earlier design that a design which did not "
                                     "finish moved aside: put it back or remove it, then run "
                                     "again",
                                     previous_));
      }
      for (const DesignInput& input : inputs) {
        if (IsInside(input.file, target)) {
          throw InputError({input.key},
                           fmt::format("'{}' is inside '{}', the earlier design this design "
                                       "replaces ({}): it would be moved aside with it before "
                                       "it is read; copy it out, or write the design to another "
                                       "folder",
                                       input.file, folder_, option_));
        }
      }
      fs::rename(target, previous_, error);
      if (error) {
        throw InputError({option_}, fmt::format("cannot move the earlier design in '{}' aside: {}",
                                                folder_, error.message()));
      }
      had_earlier_ = true;
    }
    if (!existed_ || had_earlier_) {
      fs::create_directory(target, error);
      if (error) {
        throw InputError({option_},
                         fmt::format("cannot make the folder '{}': {}", folder_, error.message()));
      }
    }
    owns_contents_ = true;
  } catch (...) {
    RollBack();
    throw;
  }
}

DesignFolder::~DesignFolder() {
  if (!committed_) RollBack();
}

void DesignFolder::RollBack() noexcept {
  std::error_code ignored;
  const fs::path target(target_);
  if (owns_contents_ && existed_ && !had_earlier_) {
    // The user's empty folder: emptied again, kept (what is in it listed first: a folder is not
    // changed while it is read).
    std::vector<fs::path> written;
    for (fs::directory_iterator it(target, ignored), end; !ignored && it != end;
         it.increment(ignored)) {
      written.push_back(it->path());
    }
    for (const fs::path& path : written) fs::remove_all(path, ignored);
  } else if (owns_contents_) {
    fs::remove_all(target, ignored);
  }
  if (had_earlier_) fs::rename(previous_, target, ignored);
  if (!lock_.empty()) fs::remove(lock_, ignored);
  // The folders made for it, deepest first, each only while empty.
  for (const std::string& folder : created_parents_) fs::remove(folder, ignored);
}

void DesignFolder::Commit() {
  const fs::path target(folder_);
  const std::map<std::string, std::uintmax_t> files = FilesIn(target, option_, folder_);
  io::WriteTextFileAtomically((target / kManifest).string(), [&](std::ostream& out) {
    out << "# The files an isolab design wrote, with their sizes in bytes. A later design\n"
           "# replaces this folder only while it holds these files and nothing else.\n";
    for (const auto& [file, size] : files) {
      if (file != kManifest) out << size << " " << file << "\n";
    }
  });
  committed_ = true;
  std::error_code ignored;
  if (had_earlier_) fs::remove_all(previous_, ignored);
  fs::remove(lock_, ignored);
}

}  // namespace isolab::study
