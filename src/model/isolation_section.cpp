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

// `identified_range` at key path `path`, in the model's units.
identification::IdentifiedRange ReadIdentifiedRange(const YamlReader& reader,
                                                    const YAML::Node& node, const std::string& path,
                                                    const UnitSystem& units) {
  reader.RequireMap(node, path);
  reader.CheckKeys(node, path, {"displacement", "velocity", "cycles", "data"});
  identification::IdentifiedRange range;
  range.displacement = ReadPositive(reader, node, path, "displacement", dimension::kLength, units);
  range.velocity = ReadPositive(reader, node, path, "velocity", dimension::kVelocity, units);
  const std::string cycles_path = ChildPath(path, "cycles");
  const YAML::Node cycles = reader.Require(node, path, "cycles");
  range.cycles = reader.ReadNumber(cycles, cycles_path);
  if (!(range.cycles >= 0.0)) {
    reader.Fail(cycles, cycles_path,
                fmt::format("{:g} (expected a number of cycles >= 0)", range.cycles));
  }
  const std::string data_path = ChildPath(path, "data");
  const YAML::Node data = reader.Require(node, path, "data");
  reader.RequireSequence(data, data_path);
  if (data.size() == 0) {
    reader.Fail(data, data_path, "the list is empty; name the tests the laws were identified on");
  }
  for (std::size_t i = 0; i < data.size(); ++i) {
    range.data.push_back(reader.ReadString(data[i], IndexPath(data_path, i)));
  }
  return range;
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
                                           BearingGroup* group,
                                           std::optional<identification::IdentifiedRange>* range) {
  reader.RequireMap(isolation, path);
  if (group) {
    reader.CheckKeys(isolation, path,
                     {"components", "file", "count", "name", "modification", "identified_range"});
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
    reader.CheckKeys(isolation, path, {"components", "file", "identified_range"});
  }
  if (!isolation["file"]) {
    if (isolation["identified_range"]) {
      const auto read = ReadIdentifiedRange(reader, isolation["identified_range"],
                                            ChildPath(path, "identified_range"), units);
      if (range) *range = read;
    }
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
  if (isolation["identified_range"]) {
    reader.Fail(isolation["identified_range"], ChildPath(path, "identified_range"),
                "is the range of the components given here; the file's laws carry their own");
  }
  // The isolation section of another model file (e.g. one written by isolab fit), relative to
  // the file that names it; in the same units, since its numbers are read in its own.
  if (isolation["components"]) reader.Fail(isolation, path, "give components or file, not both");
  const std::string file_path = ChildPath(path, "file");
  const std::string other = reader.ReadFilePath(isolation["file"], file_path, directory);
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
  // The units agree (above), so the file's range is in this model's units as it stands.
  if (range) *range = included.identified_range;
  if (included_files) {
    included_files->push_back(other);
    included_files->insert(included_files->end(), included.included_files.begin(),
                           included.included_files.end());
  }
  return included.isolation;
}

}  // namespace isolab::model
