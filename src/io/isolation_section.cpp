// The isolation section of a model (or of a study's variant): its own components, or those of
// another model file named by `file`.
#include <fmt/format.h>

#include "isolab/io/model_file.h"
#include "model_sections.h"

namespace isolab::io {

hysteresis::ParallelAssembly ReadIsolation(const YamlReader& reader, const YAML::Node& isolation,
                                           const std::string& path,
                                           const std::filesystem::path& directory,
                                           const UnitSystem& units) {
  reader.RequireMap(isolation, path);
  reader.CheckKeys(isolation, path, {"components", "file"});
  if (!isolation["file"]) {
    return ReadAssembly(reader, reader.Require(isolation, path, "components"),
                        ChildPath(path, "components"), units);
  }
  // The isolation section of another model file (e.g. one written by isolab fit), relative to
  // the file that names it; in the same units, since its numbers are read in its own.
  if (isolation["components"]) reader.Fail(isolation, path, "give components or file, not both");
  const std::string file_path = ChildPath(path, "file");
  const std::string relative = reader.ReadString(isolation["file"], file_path);
  const std::string other = (directory / relative).string();
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
  return included.isolation;
}

}  // namespace isolab::io
