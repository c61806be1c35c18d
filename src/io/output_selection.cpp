#include "isolab/io/output_selection.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <charconv>

#include "isolab/core/errors.h"
#include "isolab/io/analysis_setup.h"
#include "yaml_reader.h"

namespace isolab::io {

bool OutputSelection::Records(std::string_view quantity) const {
  if (summary_only) return false;
  return quantities.empty() ||
         std::find(quantities.begin(), quantities.end(), quantity) != quantities.end();
}

std::vector<int> SelectedDofs(const OutputSelection& selection, const AnalysisSetup& setup,
                              const std::string& key) {
  const int dofs = setup.structure.dofs();
  std::vector<int> selected;
  if (selection.levels.empty()) {
    for (int dof = 0; dof < dofs; ++dof) selected.push_back(dof);
    return selected;
  }
  // Level 0 is the base when the building stands on one, or an SDOF's mass; floors count from 1.
  const bool has_level_zero = setup.layout.dof_names.front() != "floor 1";
  for (const int level : selection.levels) {
    const int dof = level == kRoofLevel ? dofs - 1 : has_level_zero ? level : level - 1;
    if (dof < 0 || dof >= dofs) {
      throw InputError(
          {key}, fmt::format("level {} is not in the structure (its levels are {} to "
                             "{}, or roof)",
                             level, has_level_zero ? 0 : 1, has_level_zero ? dofs - 1 : dofs));
    }
    selected.push_back(dof);
  }
  std::sort(selected.begin(), selected.end());
  selected.erase(std::unique(selected.begin(), selected.end()), selected.end());
  return selected;
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

}  // namespace isolab::io
