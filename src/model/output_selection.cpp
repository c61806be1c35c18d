#include "isolab/model/output_selection.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <charconv>

#include "isolab/core/errors.h"
#include "yaml_reader.h"

namespace isolab::model {

bool OutputSelection::Records(std::string_view quantity) const {
  if (summary_only) return false;
  return quantities.empty() ||
         std::find(quantities.begin(), quantities.end(), quantity) != quantities.end();
}

std::optional<int> ParseLevel(const std::string& text) {
  if (text == "roof") return kRoofLevel;
  int level = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), level);
  if (error != std::errc() || end != text.data() + text.size() || level < 0) return std::nullopt;
  return level;
}

std::string UnknownQuantity(const std::string& name) {
  if (std::find(kQuantityNames.begin(), kQuantityNames.end(), name) != kQuantityNames.end()) {
    return "";
  }
  const std::string_view nearest = NearestWord(name, kQuantityNames);
  return fmt::format("unknown quantity '{}'{} (one of: {})", name,
                     nearest.empty() ? "" : fmt::format("; did you mean '{}'?", nearest),
                     fmt::join(kQuantityNames, ", "));
}

}  // namespace isolab::model
