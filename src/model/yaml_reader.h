// Reading YAML with errors that say where: every accessor knows the file, the node's line and
// column, and the key path from the document root ("isolation.components[2].k1").
#pragma once

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>

#include "isolab/core/errors.h"
#include "isolab/core/number.h"
#include "isolab/core/units.h"

namespace isolab::model {

class YamlReader {
 public:
  explicit YamlReader(std::string file) : file_(std::move(file)) {}

  const std::string& file() const { return file_; }

  // Parses the file, keeping its text in `text` when given; throws InputError for an unreadable
  // file or a syntax error.
  YAML::Node LoadFile(std::string* text = nullptr) const;
  // The file's text; throws InputError when it cannot be read.
  std::string ReadText() const;
  // Parses `text` as if it were the file's content (a model built in memory).
  YAML::Node LoadText(const std::string& text) const;

  SourceLocation Locate(const YAML::Node& node) const;
  [[noreturn]] void Fail(const YAML::Node& node, const std::string& path,
                         const std::string& what) const;

  void RequireMap(const YAML::Node& node, const std::string& path) const;
  void RequireSequence(const YAML::Node& node, const std::string& path) const;
  // The child `key` of a map, or a "missing key" error at the map.
  YAML::Node Require(const YAML::Node& map, const std::string& path, std::string_view key) const;

  // Rejects keys outside `allowed`, suggesting the nearest valid one.
  void CheckKeys(const YAML::Node& map, const std::string& path,
                 std::span<const std::string_view> allowed) const;
  void CheckKeys(const YAML::Node& map, const std::string& path,
                 std::initializer_list<std::string_view> allowed) const {
    CheckKeys(map, path, std::span<const std::string_view>(allowed.begin(), allowed.size()));
  }

  double ReadNumber(const YAML::Node& node, const std::string& path) const;
  // A number in the model's units, or a string "value unit" converted into them.
  double ReadQuantity(const YAML::Node& node, const std::string& path, Dimension dimension,
                      const UnitSystem& units) const;
  int ReadInteger(const YAML::Node& node, const std::string& path) const;
  std::string ReadString(const YAML::Node& node, const std::string& path) const;
  // A text value that names a file or a folder: an empty one is refused, never read as "the
  // default" (as `-o ''` is refused on the command line).
  std::string ReadName(const YAML::Node& node, const std::string& path) const;
  // A file this one names at `node`, resolved against `directory` (this file's folder); one that
  // is not a regular file is refused here, so that the message names this file's line and key.
  std::string ReadFilePath(const YAML::Node& node, const std::string& path,
                           const std::filesystem::path& directory) const;

 private:
  std::string file_;
};

// "path.key", or "key" at the root.
std::string ChildPath(const std::string& path, std::string_view key);
std::string IndexPath(const std::string& path, std::size_t index);

// The candidate nearest to `word` by edit distance, or empty when none is plausibly meant.
std::string_view NearestWord(std::string_view word, std::span<const std::string_view> candidates);

}  // namespace isolab::model
