#include "isolab/analysis/result_series.h"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "isolab/core/errors.h"

namespace isolab::analysis {
namespace {

using integrators::ResponseRow;
using RowValues = std::span<const double> ResponseRow::*;

// The chosen columns of one of the row's per-DOF or per-connection arrays.
Series Columns(std::string name, std::string units, std::vector<std::string> columns,
               RowValues values, std::vector<int> chosen) {
  return {std::move(name), std::move(units), std::move(columns),
          [values, chosen = std::move(chosen)](const ResponseRow& row, double* out) {
            const std::span<const double> all = row.*values;
            for (std::size_t c = 0; c < chosen.size(); ++c) out[c] = all[chosen[c]];
          }};
}

// One value per row.
template <typename Value>
Series Vector(std::string name, std::string units, Value value) {
  return {std::move(name), std::move(units), {}, [value](const ResponseRow& row, double* out) {
            *out = value(row);
          }};
}

}  // namespace

std::vector<int> SelectedDofs(const model::OutputSelection& selection, const AnalysisSetup& setup,
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
    const int dof = level == model::kRoofLevel ? dofs - 1 : has_level_zero ? level : level - 1;
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

std::vector<NamedPeak> FilePeaks(const AnalysisSetup& setup, const ResponsePeaks& peaks) {
  std::vector<NamedPeak> named;
  if (setup.layout.isolation >= 0) {
    named.push_back({"isolator_displacement", &peaks.isolator_displacement, dimension::kLength});
    named.push_back({"isolator_force", &peaks.isolator_force, dimension::kForce});
  }
  named.push_back({"base_shear", &peaks.base_shear, dimension::kForce});
  named.push_back(
      {"roof_absolute_acceleration", &peaks.roof_absolute_acceleration, dimension::kAcceleration});
  if (!setup.layout.stories.empty()) {
    named.push_back({"first_story_shear", &peaks.first_story_shear, dimension::kForce});
    named.push_back({"story_drift", &peaks.story_drift, dimension::kLength});
  }
  return named;
}

std::vector<std::string> RecordedQuantities(const model::OutputSelection& selection) {
  std::vector<std::string> quantities;
  for (const std::string_view name : model::kQuantityNames) {
    if (selection.Records(name)) quantities.emplace_back(name);
  }
  return quantities;
}

std::vector<std::string> RecordedLevels(const model::OutputSelection& selection,
                                        const AnalysisSetup& setup) {
  std::vector<std::string> levels;
  if (selection.summary_only) return levels;
  for (const int dof : SelectedDofs(selection, setup, "output.levels")) {
    levels.push_back(setup.layout.dof_names[dof]);
  }
  return levels;
}

std::vector<Series> ResultSeries(const model::ModelFile& model, const AnalysisSetup& setup,
                                 const model::OutputSelection& selection) {
  std::vector<Series> series;
  if (selection.summary_only) return series;
  const UnitSystem& units = model.units;
  const std::string length = DescribeUnits(units, dimension::kLength);
  const std::string force = DescribeUnits(units, dimension::kForce);
  const std::string velocity = DescribeUnits(units, dimension::kVelocity);
  const std::string acceleration = DescribeUnits(units, dimension::kAcceleration);
  const std::string energy = fmt::format("{}*{}", units.force(), units.length());
  const auto& connections = setup.structure.connections();

  // The selected levels: their DOFs, and the connections and stories just below them.
  const std::vector<int> dofs = SelectedDofs(selection, setup, "output.levels");
  const auto chosen = [&dofs](int dof) {
    return std::binary_search(dofs.begin(), dofs.end(), dof);
  };
  std::vector<std::string> dof_names;
  for (const int dof : dofs) dof_names.push_back(setup.layout.dof_names[dof]);
  std::vector<int> chosen_connections;
  std::vector<std::string> connection_names;
  for (std::size_t k = 0; k < connections.size(); ++k) {
    if (!chosen(connections[k].dof_j)) continue;
    chosen_connections.push_back(static_cast<int>(k));
    connection_names.push_back(connections[k].name);
  }
  std::vector<std::size_t> stories;  // indices into setup.layout.stories
  std::vector<std::string> story_names;
  for (std::size_t s = 0; s < setup.layout.stories.size(); ++s) {
    const auto& story = connections[setup.layout.stories[s]];
    if (!chosen(story.dof_j)) continue;
    stories.push_back(s);
    story_names.push_back(story.name);
  }

  series.push_back(Vector("time", units.time(), [](const ResponseRow& row) { return row.time; }));
  if (!setup.record.path.empty()) {
    series.push_back(Vector("ground_acceleration", acceleration, [&setup](const ResponseRow& row) {
      return setup.excitation.ground_acceleration.At(row.time);
    }));
  }
  const auto per_dof = [&](const char* name, const std::string& units, RowValues values) {
    if (selection.Records(name)) series.push_back(Columns(name, units, dof_names, values, dofs));
  };
  per_dof("displacement", length, &ResponseRow::displacement);
  per_dof("velocity", velocity, &ResponseRow::velocity);
  per_dof("acceleration", acceleration, &ResponseRow::acceleration);
  per_dof("absolute_acceleration", acceleration, &ResponseRow::absolute_acceleration);
  if (selection.Records("connection_force") && !chosen_connections.empty()) {
    series.push_back(Columns("connection_force", force, connection_names,
                             &ResponseRow::connection_force, chosen_connections));
  }

  if (setup.layout.isolation >= 0 && selection.Records("isolator")) {
    const int k = setup.layout.isolation;
    const int dof = connections[k].dof_j;
    series.push_back(Vector("isolator/displacement", length,
                            [dof](const ResponseRow& row) { return row.displacement[dof]; }));
    series.push_back(Vector("isolator/force", force,
                            [k](const ResponseRow& row) { return row.connection_force[k]; }));
    std::vector<std::string> components;
    for (const auto& component : connections[k].assembly.components()) {
      components.push_back(component.name);
    }
    const std::size_t first = setup.structure.law_offset(k);
    series.push_back({"isolator/component_force", force, components,
                      [first, count = components.size()](const ResponseRow& row, double* out) {
                        std::copy_n(row.law_force.data() + first, count, out);
                      }});
  }
  if (!stories.empty() && selection.Records("story")) {
    bool heights = false;
    for (const std::size_t s : stories) heights = heights || setup.layout.story_heights[s] > 0.0;
    std::vector<std::pair<int, int>> floors;  // (below, above); kGround: -1
    for (const std::size_t s : stories) {
      const auto& story = connections[setup.layout.stories[s]];
      floors.emplace_back(story.dof_i, story.dof_j);
    }
    // Each story's drift times a factor: 1 for the drift, 100 / height for its ratio (%).
    const auto drifts = [&](std::string name, std::string units, std::vector<double> factors) {
      return Series{std::move(name), std::move(units), story_names,
                    [floors, factors](const ResponseRow& row, double* out) {
                      const double* u = row.displacement.data();
                      for (std::size_t s = 0; s < floors.size(); ++s) {
                        const double below = floors[s].first >= 0 ? u[floors[s].first] : 0.0;
                        out[s] = factors[s] * (u[floors[s].second] - below);
                      }
                    }};
    };
    series.push_back(drifts("story/drift", length, std::vector<double>(stories.size(), 1.0)));
    if (heights) {
      std::vector<double> per_height;
      for (const std::size_t s : stories) {
        const double height = setup.layout.story_heights[s];
        per_height.push_back(height > 0.0 ? 100.0 / height
                                          : std::numeric_limits<double>::quiet_NaN());
      }
      series.push_back(drifts("story/drift_ratio", "%", per_height));
    }
    std::vector<int> story_connections;
    for (const std::size_t s : stories) story_connections.push_back(setup.layout.stories[s]);
    series.push_back(Columns("story/shear", force, story_names, &ResponseRow::connection_force,
                             story_connections));
  }
  if (selection.Records("energy")) {
    const auto energy_term = [&](const char* name, double integrators::Energies::*term) {
      series.push_back(Vector(fmt::format("energy/{}", name), energy,
                              [term](const ResponseRow& row) { return row.energies.*term; }));
    };
    energy_term("input", &integrators::Energies::input);
    energy_term("kinetic", &integrators::Energies::kinetic);
    energy_term("damping", &integrators::Energies::damping);
    energy_term("elastic", &integrators::Energies::elastic);
    energy_term("hysteretic", &integrators::Energies::hysteretic);
  }
  return series;
}

}  // namespace isolab::analysis
