#include "isolab/study/output_folder.h"

#include <fmt/format.h>

#include <filesystem>
#include <system_error>

#include "isolab/core/errors.h"

namespace isolab::study {

std::string PrepareOutputFolder(const std::string& requested, const std::string& study_path,
                                const model::StudyFile& study) {
  std::string folder = requested;
  if (folder.empty()) folder = study.output_directory;
  if (folder.empty()) folder = std::filesystem::path(study_path).stem().string();
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error || !std::filesystem::is_directory(folder)) {
    throw InputError({folder}, fmt::format("cannot create the output folder ({})",
                                           error ? error.message() : "not a folder"));
  }
  return folder;
}

}  // namespace isolab::study
