// The isolation section of a model (or of a study's variant): its own components, or those of
// another model file named by `file`.
#include <fmt/format.h>

#include <system_error>
#include <vector>

#include "isolab/model/model_file.h"
#include "model_sections.h"

namespace isolab::model {
namespace {

// The files whose isolation sections are being read on this thread, outermost first: a file that
// names one of them again is a cycle (A -> B -> A), refused instead of recursing without end.
thread_local std::vector<std::string> files_being_included;

// Pushes a file on the chain for as long as its included file is read.
class IncludeGuard {
 public:
  explicit IncludeGuard(std::string file) { files_being_included.push_back(std::move(file)); }
  ~IncludeGuard() { files_being_included.pop_back(); }
  IncludeGuard(const IncludeGuard&) = delete;
  IncludeGuard& operator=(const IncludeGuard&) = delete;
};

// The chain from the outermost file to `other` when `other` is one of the files on it (the same
// file, not the same spelling), else empty.
std::string CycleTo(const std::string& other) {
  for (std::size_t k = 0; k < files_being_included.size(); ++k) {
    std::error_code error;
    if (!std::filesystem::equivalent(files_being_included[k], other, error)) continue;
    std::string chain;
    for (std::size_t j = k; j < files_being_included.size(); ++j) {
      chain += files_being_included[j] + " -> ";
    }
    return chain + other;
  }
  return {};
}

}  // namespace

int ReadBearingCount(const YamlReader& reader, const YAML::Node& node, const std::string& path) {
  const int count = reader.ReadInteger(node, path);
  if (count < 1) {
    reader.Fail(node, path, fmt::format("{} (expected a number of bearings >= 1)", count));
  }
  return count;
}

std::vector<std::string> IsolationBearings(const ModelFile& model) {
  std::vector<std::string> names;
  if (!model.isolation_count) return names;
  for (int i = 1; i <= *model.isolation_count; ++i) {
    names.push_back(fmt::format("{}_{}", model.isolation_name, i));
  }
  return names;
}

hysteresis::ParallelAssembly ReadIsolation(const YamlReader& reader, const YAML::Node& isolation,
                                           const std::string& path,
                                           const std::filesystem::path& directory,
                                           const UnitSystem& units,
                                           std::vector<std::string>* included_files,
                                           BearingGroup* group) {
  reader.RequireMap(isolation, path);
  if (group) {
    reader.CheckKeys(isolation, path, {"components", "file", "count", "name", "modification"});
    if (isolation["count"]) {
      group->count = ReadBearingCount(reader, isolation["count"], ChildPath(path, "count"));
    }
    if (isolation["name"]) {
      if (!isolation["count"]) {
        reader.Fail(isolation["name"], ChildPath(path, "name"),
                    "names the bearings of a count; give count too");
      }
      group->name = reader.ReadString(isolation["name"], ChildPath(path, "name"));
    }
  } else {
    reader.CheckKeys(isolation, path, {"components", "file"});
  }
  if (!isolation["file"]) {
    const YAML::Node components = reader.Require(isolation, path, "components");
    hysteresis::ParallelAssembly laws =
        ReadAssembly(reader, components, ChildPath(path, "components"), units);
    if (group && isolation["modification"]) {
      group->modification = ReadModification(reader, isolation["modification"],
                                             ChildPath(path, "modification"), laws, components);
    }
    return laws;
  }
  if (isolation["modification"]) {
    reader.Fail(isolation["modification"], ChildPath(path, "modification"),
                "modifies the components given here, not those of a file (copy them here)");
  }
  // The isolation section of another model file (e.g. one written by isolab fit), relative to
  // the file that names it; in the same units, since its numbers are read in its own.
  if (isolation["components"]) reader.Fail(isolation, path, "give components or file, not both");
  const std::string file_path = ChildPath(path, "file");
  const std::string relative = reader.ReadString(isolation["file"], file_path);
  const std::string other = (directory / relative).string();
  const IncludeGuard guard(reader.file());
  if (const std::string cycle = CycleTo(other); !cycle.empty()) {
    reader.Fail(isolation["file"], file_path,
                fmt::format("the files include each other: {}", cycle));
  }
  const ModelFile included = LoadModelFile(other);
  if (included.isolation.size() == 0) {
    reader.Fail(isolation["file"], file_path, fmt::format("'{}' has no isolation section", other));
  }
  if (included.units.force() != units.force() || included.units.length() != units.length() ||
      included.units.time() != units.time()) {
    reader.Fail(isolation["file"], file_path,
                fmt::format("'{}' is in {} {} {}, the model in {} {} {}", other,
                            included.units.force(), included.units.length(), included.units.time(),
                            units.force(), units.length(), units.time()));
  }
  if (included_files) {
    included_files->push_back(other);
    included_files->insert(included_files->end(), included.included_files.begin(),
                           included.included_files.end());
  }
  return included.isolation;
}

}  // namespace isolab::model
