#include "isolab/study/output_folder.h"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <system_error>

#include "isolab/core/errors.h"
#include "isolab/io/atomic_file.h"
#include "isolab/study/jobs.h"

namespace isolab::study {
namespace {

namespace fs = std::filesystem;

// What an earlier compare wrote into the folder: the manifest's paths, relative to the folder.
std::set<std::string> ReadManifest(const fs::path& folder) {
  std::set<std::string> listed;
  std::ifstream in(folder / kCompareManifest);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty()) listed.insert(line);
  }
  return listed;
}

// The files a compare of `study` writes into its folder, relative to it (the plots apart: their
// names are the plot script's).
std::vector<std::string> OwnFiles(const model::StudyFile& study) {
  std::vector<std::string> files = {"summary.csv", "summary.h5"};
  if (study.runs != model::RunFiles::kNone) {
    for (const Job& job : ExpandJobs(study)) files.push_back(RunFileName(study, job));
  }
  return files;
}

// The folder's files under `sub` (relative paths), for the plots a compare may have drawn.
std::vector<std::string> FilesUnder(const fs::path& folder, const std::string& sub) {
  std::vector<std::string> files;
  std::error_code error;
  if (!fs::is_directory(folder / sub, error)) return files;
  for (const auto& entry : fs::recursive_directory_iterator(folder / sub, error)) {
    if (entry.is_regular_file(error)) files.push_back(fs::relative(entry.path(), folder).string());
  }
  return files;
}

// A compare replaces only what an earlier compare wrote: any file it would write that is there
// and not in the folder's manifest is someone else's, and a folder it needs that is a file would
// fail every run after the runs.
void CheckFolderContents(const fs::path& folder, const model::StudyFile& study) {
  const std::set<std::string> listed = ReadManifest(folder);
  std::vector<std::string> targets = OwnFiles(study);
  for (const std::string& plot : FilesUnder(folder, "plots")) targets.push_back(plot);
  for (const std::string& file : targets) {
    std::error_code error;
    const fs::path path = folder / file;
    for (fs::path parent = path.parent_path(); parent != folder && !parent.empty();
         parent = parent.parent_path()) {
      if (fs::exists(parent, error) && !fs::is_directory(parent, error)) {
        throw InputError({folder.string()},
                         fmt::format("holds '{}' as a file, where the study writes the folder of "
                                     "its runs: choose another output folder",
                                     fs::relative(parent, folder).string()));
      }
    }
    // A folder where a file goes is no one's file to lose: that run fails when it writes.
    if (fs::exists(path, error) && !fs::is_directory(path, error) && !listed.count(file)) {
      throw InputError({folder.string()},
                       fmt::format("holds '{}', which an earlier compare did not write (its {} "
                                   "does not list it): choose another output folder, or move the "
                                   "file away",
                                   file, kCompareManifest));
    }
  }
}

}  // namespace

std::string PrepareOutputFolder(const std::string& requested, const std::string& study_path,
                                const model::StudyFile& study) {
  std::string folder = requested;
  if (folder.empty()) folder = study.output_directory;
  if (folder.empty()) folder = fs::path(study_path).stem().string();
  std::error_code error;
  if (fs::exists(folder, error) && !fs::is_directory(folder, error)) {
    throw InputError({folder}, "is a file, not an output folder");
  }
  if (fs::is_directory(folder, error)) CheckFolderContents(folder, study);
  fs::create_directories(folder, error);
  if (error || !fs::is_directory(folder)) {
    throw InputError({folder}, fmt::format("cannot create the output folder ({})",
                                           error ? error.message() : "not a folder"));
  }
  return folder;
}

void WriteCompareManifest(const std::string& folder, const model::StudyFile& study) {
  std::vector<std::string> written = OwnFiles(study);
  for (const std::string& plot : FilesUnder(folder, "plots")) written.push_back(plot);
  io::WriteTextFileAtomically((fs::path(folder) / kCompareManifest).string(),
                              [&](std::ostream& out) {
                                for (const std::string& file : written) out << file << "\n";
                              });
}

}  // namespace isolab::study
