#include "yaml_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "isolab/core/text_file.h"

namespace isolab::model {
namespace {

std::size_t EditDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + cost});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string JoinWords(std::span<const std::string_view> words) {
  std::string joined;
  for (const std::string_view word : words) {
    if (!joined.empty()) joined += ", ";
    joined += word;
  }
  return joined;
}

// yaml-cpp keeps both entries of a key given twice and lookups find the first: a later value the
// user meant silently loses. Every mapping is checked once, walking with a stack of its own (no
// recursion on the file's depth) and visiting a node an alias repeats only once (by its position
// in the text), so the walk is linear in the file.
void RefuseDuplicateKeys(const std::string& file, const YAML::Node& root) {
  std::vector<std::pair<YAML::Node, std::string>> pending{{root, ""}};
  std::unordered_set<int> visited;  // text positions of the collections walked
  while (!pending.empty()) {
    const auto [node, path] = std::move(pending.back());
    pending.pop_back();
    if (!node.IsMap() && !node.IsSequence()) continue;
    if (!visited.insert(node.Mark().pos).second) continue;
    if (node.IsSequence()) {
      std::size_t index = 0;
      for (const YAML::Node& item : node) pending.emplace_back(item, IndexPath(path, index++));
      continue;
    }
    std::unordered_map<std::string, YAML::Mark> seen;
    for (const auto& entry : node) {
      if (!entry.first.IsScalar()) continue;  // refused where the key is read
      const std::string& key = entry.first.Scalar();
      const auto [first, inserted] = seen.try_emplace(key, entry.first.Mark());
      if (!inserted) {
        const YAML::Mark again = entry.first.Mark();
        throw InputError({file, again.line + 1, again.column + 1},
                         fmt::format("{}: key given twice, first at {}:{}:{} (YAML keeps only one "
                                     "of them): remove one",
                                     ChildPath(path, key), file, first->second.line + 1,
                                     first->second.column + 1));
      }
      pending.emplace_back(entry.second, ChildPath(path, key));
    }
  }
}

}  // namespace

std::string ChildPath(const std::string& path, std::string_view key) {
  return path.empty() ? std::string(key) : fmt::format("{}.{}", path, key);
}

std::string IndexPath(const std::string& path, std::size_t index) {
  return fmt::format("{}[{}]", path, index);
}

std::string_view NearestWord(std::string_view word, std::span<const std::string_view> candidates) {
  std::string_view best;
  std::size_t best_distance = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const std::string_view candidate : candidates) {
    const std::size_t distance = EditDistance(word, candidate);
    if (distance < best_distance) {
      best = candidate;
      best_distance = distance;
    }
  }
  return best;
}

std::string YamlReader::ReadFilePath(const YAML::Node& node, const std::string& path,
                                     const std::filesystem::path& directory) const {
  const std::string file = (directory / ReadString(node, path)).string();
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error)) {
    Fail(node, path,
         fmt::format("'{}' is not a file{}", file,
                     error ? fmt::format(" ({})", error.message()) : std::string()));
  }
  return file;
}

YAML::Node YamlReader::LoadFile(std::string* text) const {
  const std::string content = ReadText();
  if (text != nullptr) *text = content;
  return LoadText(content);
}

std::string YamlReader::ReadText() const { return ReadBoundedText(file_); }

YAML::Node YamlReader::LoadText(const std::string& content) const {
  try {
    YAML::Node root = YAML::Load(content);
    if (!root.IsDefined() || root.IsNull()) throw InputError({file_, 1, 1}, "the file is empty");
    RefuseDuplicateKeys(file_, root);
    return root;
  } catch (const YAML::ParserException& e) {
    throw InputError({file_, e.mark.line + 1, e.mark.column + 1},
                     fmt::format("YAML syntax error: {}", e.msg));
  }
}

SourceLocation YamlReader::Locate(const YAML::Node& node) const {
  const YAML::Mark mark = node.Mark();
  if (mark.is_null()) return {file_};
  return {file_, mark.line + 1, mark.column + 1};
}

void YamlReader::Fail(const YAML::Node& node, const std::string& path,
                      const std::string& what) const {
  throw InputError(Locate(node), path.empty() ? what : fmt::format("{}: {}", path, what));
}

void YamlReader::RequireMap(const YAML::Node& node, const std::string& path) const {
  if (!node.IsMap()) Fail(node, path, "expected a mapping of keys to values");
}

void YamlReader::RequireSequence(const YAML::Node& node, const std::string& path) const {
  if (!node.IsSequence()) Fail(node, path, "expected a list");
}

YAML::Node YamlReader::Require(const YAML::Node& map, const std::string& path,
                               std::string_view key) const {
  YAML::Node child = map[std::string(key)];
  if (!child.IsDefined() || child.IsNull()) {
    Fail(map, path, fmt::format("missing key '{}'", key));
  }
  return child;
}

void YamlReader::CheckKeys(const YAML::Node& map, const std::string& path,
                           std::span<const std::string_view> allowed) const {
  for (const auto& entry : map) {
    if (!entry.first.IsScalar()) Fail(entry.first, path, "a key must be a plain name");
    const std::string key = entry.first.Scalar();
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    const std::string_view nearest = NearestWord(key, allowed);
    const std::string hint = nearest.empty() ? "" : fmt::format(" (did you mean '{}'?)", nearest);
    throw InputError(Locate(entry.first),
                     fmt::format("{}: unknown key{}; expected one of: {}", ChildPath(path, key),
                                 hint, JoinWords(allowed)));
  }
}

double YamlReader::ReadNumber(const YAML::Node& node, const std::string& path) const {
  if (!node.IsScalar()) Fail(node, path, "expected a number");
  std::string problem;
  const std::optional<double> value = ParseFiniteNumber(node.Scalar(), &problem);
  if (!value) Fail(node, path, problem);
  return *value;
}

double YamlReader::ReadQuantity(const YAML::Node& node, const std::string& path,
                                Dimension dimension, const UnitSystem& units) const {
  if (!node.IsScalar()) Fail(node, path, "expected a number or a quantity with a unit");
  // Plain YAML scalars that parse as numbers are in the model's units.
  const std::string& text = node.Scalar();
  const bool has_unit = std::any_of(text.begin(), text.end(), [](unsigned char c) {
    return std::isalpha(c) && c != 'e' && c != 'E';
  });
  if (!has_unit || text.front() == '.') return ReadNumber(node, path);
  try {
    return units.Parse(text, dimension);
  } catch (const std::invalid_argument& error) {
    Fail(node, path,
         fmt::format("{} (expected {} in {} units)", error.what(), DescribeDimension(dimension),
                     DescribeUnits(units, dimension)));
  }
}

int YamlReader::ReadInteger(const YAML::Node& node, const std::string& path) const {
  const double value = ReadNumber(node, path);
  if (value != std::round(value)) {
    Fail(node, path, fmt::format("'{}' is not a whole number", node.Scalar()));
  }
  if (!(std::abs(value) < 1e9)) {
    Fail(node, path,
         fmt::format("'{}' is beyond the whole numbers a model takes (less than 10^9 in size)",
                     node.Scalar()));
  }
  return static_cast<int>(value);
}

std::string YamlReader::ReadString(const YAML::Node& node, const std::string& path) const {
  if (!node.IsScalar()) Fail(node, path, "expected a text value");
  return node.Scalar();
}

std::string YamlReader::ReadName(const YAML::Node& node, const std::string& path) const {
  std::string name = ReadString(node, path);
  if (name.empty()) Fail(node, path, "an empty name (give one, or leave the key out)");
  return name;
}

}  // namespace isolab::model
