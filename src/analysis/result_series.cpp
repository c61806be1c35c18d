#include "isolab/analysis/result_series.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "isolab/core/errors.h"

namespace isolab::analysis {
namespace {

using hysteresis::Norm;
using hysteresis::Vec2;
using integrators::ResponseRow;
using structure::kGround;

// A series computed from the row by `fill` alone.
Series Computed(std::string name, std::string units, std::vector<std::string> columns,
                std::function<void(const ResponseRow&, double*)> fill) {
  return {std::move(name), std::move(units), std::move(columns), std::move(fill), {}};
}

// A series whose columns are all read off the row: `fill` reads them as a writer's staged
// gathering does.
Series ReadOff(std::string name, std::string units, std::vector<std::string> columns,
               std::vector<ColumnSource> sources) {
  Series series{std::move(name), std::move(units), std::move(columns), nullptr, std::move(sources)};
  series.fill = [sources = series.sources](const ResponseRow& row, double* out) {
    const RowArrays arrays(row);
    for (const ColumnSource& source : sources) *out++ = source.Value(arrays[source.array]);
  };
  return series;
}

// The chosen entries of one of the row's arrays.
Series Columns(std::string name, std::string units, std::vector<std::string> columns,
               RowArray array, const std::vector<int>& chosen) {
  std::vector<ColumnSource> sources;
  for (const int index : chosen) sources.push_back({array, index, false, {}, 1.0});
  return ReadOff(std::move(name), std::move(units), std::move(columns), std::move(sources));
}

// One of the row's scalars.
Series Scalar(std::string name, std::string units, RowScalar scalar) {
  return ReadOff(std::move(name), std::move(units), {},
                 {{RowArray::kScalars, static_cast<int>(scalar), false, {}, 1.0}});
}

// Direction `d` (0: x, 1: y) of a slot's deformation, times `factor`.
ColumnSource Deformation(const structure::Structure& structure, std::size_t slot, int d,
                         double factor = 1.0) {
  const structure::Structure::Influence influence = structure.SlotInfluence(slot);
  ColumnSource source{RowArray::kDisplacement, 0, true, {}, factor};
  for (int a = 0; a < influence.count; ++a) {
    source.terms.push_back(
        {influence.dofs[a], d == 0 ? influence.columns[a].x : influence.columns[a].y});
  }
  return source;
}

// "name" in one direction, "name.x" and "name.y" in two.
std::vector<std::string> Directional(const std::string& name, bool two) {
  if (!two) return {name};
  return {name + ".x", name + ".y"};
}

// A single column is a vector: a one-direction structure's one isolator keeps its (n) datasets.
std::vector<std::string> Named(std::vector<std::string> columns) {
  if (columns.size() == 1) columns.clear();
  return columns;
}

// The level each slot (member or coupled member) belongs to: the one above a story, an
// isolator's own; for the level selection.
std::vector<int> LevelsOfSlots(const Problem& problem) {
  std::vector<int> levels(problem.structure.slots(), -1);
  for (const structure::StoryLayout& story : problem.layout.stories) {
    for (const int member : story.members) {
      if (member >= 0) levels[member] = story.level;
    }
  }
  for (const structure::IsolatorLayout& isolator : problem.layout.isolators) {
    levels[isolator.slot] = isolator.level;
  }
  return levels;
}

bool IsSelected(const std::vector<int>& sorted_levels, int level) {
  return std::binary_search(sorted_levels.begin(), sorted_levels.end(), level);
}

// Time and the ground's accelerations.
void AppendGroundSeries(const Problem& problem, std::vector<Series>& series) {
  const UnitSystem& units = problem.units();
  const std::string acceleration = DescribeUnits(units, dimension::kAcceleration);
  series.push_back(Scalar("time", units.time(), RowScalar::kTime));
  if (!problem.records.empty()) {
    std::vector<std::string> columns;
    if (problem.layout.directions == 2) columns = {"x", "y"};
    series.push_back(Computed("ground_acceleration", acceleration, columns,
                              [&problem](const ResponseRow& row, double* out) {
                                for (const integrators::GroundMotion& motion :
                                     problem.excitation.ground) {
                                  *out++ = motion.acceleration.At(row.time);
                                }
                              }));
  }
  if (!problem.excitation.vertical.values.empty()) {
    series.push_back(Computed("vertical_ground_acceleration", acceleration, {},
                              [&problem](const ResponseRow& row, double* out) {
                                *out = problem.excitation.vertical.At(row.time);
                              }));
  }
}

// The selected levels' motions per dof, and the forces of the members that belong to them.
void AppendLevelSeries(const Problem& problem, const model::OutputSelection& selection,
                       const std::vector<int>& levels, std::vector<Series>& series) {
  const UnitSystem& units = problem.units();
  const structure::Structure& s = problem.structure;
  const structure::Layout& layout = problem.layout;
  const bool two = layout.directions == 2;
  std::vector<int> translations, rotations;
  std::vector<std::string> translation_names, rotation_names;
  for (const int level : levels) {
    const structure::Level& l = layout.levels[level];
    const std::vector<std::string> names = Directional(l.name, two);
    for (int d = 0; d < layout.directions; ++d) {
      translations.push_back(l.dofs[d]);
      translation_names.push_back(names[d]);
    }
    if (l.dofs[structure::kRotation] != kGround) {
      rotations.push_back(l.dofs[structure::kRotation]);
      rotation_names.push_back(l.name);
    }
  }
  // Torsion members' forces are torques: they are the stories' torque, not connection forces.
  std::vector<bool> torque(s.slots(), false);
  for (const structure::StoryLayout& story : layout.stories) {
    if (story.members[structure::kRotation] >= 0)
      torque[story.members[structure::kRotation]] = true;
  }
  const std::vector<int> slot_levels = LevelsOfSlots(problem);
  std::vector<int> force_columns;
  std::vector<std::string> force_names;
  for (std::size_t slot = 0; slot < s.slots(); ++slot) {
    if (torque[slot] || !IsSelected(levels, slot_levels[slot])) continue;
    int column = static_cast<int>(s.slot_force_column(slot));
    for (const std::string& name : Directional(s.slot_name(slot), s.slot_width(slot) == 2)) {
      force_names.push_back(name);
      force_columns.push_back(column++);
    }
  }
  const auto per_dof = [&](const char* name, Dimension dimension, RowArray array) {
    if (selection.Records(name)) {
      series.push_back(
          Columns(name, DescribeUnits(units, dimension), translation_names, array, translations));
    }
  };
  per_dof("displacement", dimension::kLength, RowArray::kDisplacement);
  if (selection.Records("displacement") && !rotations.empty()) {
    series.push_back(
        Columns("rotation", "rad", rotation_names, RowArray::kDisplacement, rotations));
  }
  per_dof("velocity", dimension::kVelocity, RowArray::kVelocity);
  per_dof("acceleration", dimension::kAcceleration, RowArray::kAcceleration);
  per_dof("absolute_acceleration", dimension::kAcceleration, RowArray::kAbsoluteAcceleration);
  if (selection.Records("connection_force") && !force_columns.empty()) {
    series.push_back(Columns("connection_force", DescribeUnits(units, dimension::kForce),
                             force_names, RowArray::kConnectionForce, force_columns));
  }
}

// Each isolator's (x[, y]) deformation and force, as the row gives them, its resultant, axial
// load and the forces of its components.
void AppendIsolatorSeries(const Problem& problem, std::vector<Series>& series) {
  const structure::Structure& s = problem.structure;
  const structure::Layout& layout = problem.layout;
  const std::string length = DescribeUnits(problem.units(), dimension::kLength);
  const std::string force = DescribeUnits(problem.units(), dimension::kForce);
  std::vector<std::string> names, resultants, components;
  std::vector<int> force_of;               // per column: its force column
  std::vector<ColumnSource> deformations;  // per column
  bool any_coupled = false;
  std::vector<int> component_laws;  // per component column: its law
  const bool many = layout.isolators.size() > 1;
  for (const structure::IsolatorLayout& isolator : layout.isolators) {
    const auto slot = static_cast<std::size_t>(isolator.slot);
    const int width = s.slot_width(slot);
    any_coupled = any_coupled || width == 2;
    for (const std::string& name : Directional(isolator.name, width == 2)) names.push_back(name);
    resultants.push_back(isolator.name);
    const std::string prefix = many ? isolator.name + "/" : "";
    for (int d = 0; d < width; ++d) {
      force_of.push_back(static_cast<int>(s.slot_force_column(slot)) + d);
      deformations.push_back(Deformation(s, slot, d));
    }
    int law = static_cast<int>(s.slot_law_offset(slot));
    s.VisitSlotAssembly(slot, [&](const auto& assembly) {
      for (const auto& component : assembly.components()) {
        for (const std::string& name : Directional(prefix + component.name, width == 2)) {
          components.push_back(name);
          component_laws.push_back(law++);
        }
      }
    });
  }
  series.push_back(ReadOff("isolator/displacement", length, Named(names), std::move(deformations)));
  series.push_back(
      Columns("isolator/force", force, Named(names), RowArray::kConnectionForce, force_of));
  if (any_coupled) {
    series.push_back(Computed(
        "isolator/resultant", length, Named(resultants),
        [&problem](const ResponseRow& row, double* out) {
          for (const structure::IsolatorLayout& isolator : problem.layout.isolators) {
            const Vec2 u = problem.structure.SlotDeformation(isolator.slot, row.displacement);
            *out++ = problem.structure.slot_width(isolator.slot) == 1 ? std::abs(u.x) : Norm(u);
          }
        }));
  }
  const structure::AxialLoads& axial = s.axial_loads();
  if (!axial.empty()) {
    std::vector<std::string> bearings;
    for (const structure::AxialBearing& bearing : axial.bearings) bearings.push_back(bearing.name);
    series.push_back(Computed("isolator/axial_load", force, Named(bearings),
                              [count = axial.bearings.size()](const ResponseRow& row, double* out) {
                                for (std::size_t j = 0; j < count; ++j) {
                                  out[j] = j < row.axial_load.size()
                                               ? row.axial_load[j]
                                               : std::numeric_limits<double>::quiet_NaN();
                                }
                              }));
  }
  series.push_back(
      Columns("isolator/component_force", force, components, RowArray::kLawForce, component_laws));
}

// Per selected story and direction: its drift (and drift ratio, where stories have heights) and
// shear; in plan its twist and torque.
void AppendStorySeries(const Problem& problem, const std::vector<std::size_t>& stories,
                       std::vector<Series>& series) {
  const structure::Layout& layout = problem.layout;
  const bool two = layout.directions == 2;
  const std::string length = DescribeUnits(problem.units(), dimension::kLength);
  const std::string force = DescribeUnits(problem.units(), dimension::kForce);
  const std::string energy =
      fmt::format("{}*{}", problem.units().force(), problem.units().length());
  std::vector<int> members, twists;
  std::vector<std::string> names, twist_names;
  std::vector<double> per_height;
  bool heights = false;
  for (const std::size_t k : stories) {
    const structure::StoryLayout& story = layout.stories[k];
    heights = heights || story.height > 0.0;
    const std::vector<std::string> directional = Directional(story.name, two);
    for (int d = 0; d < layout.directions; ++d) {
      if (story.members[d] < 0) continue;
      members.push_back(story.members[d]);
      names.push_back(directional[d]);
      per_height.push_back(story.height > 0.0 ? 100.0 / story.height
                                              : std::numeric_limits<double>::quiet_NaN());
    }
    if (story.members[structure::kRotation] >= 0) {
      twists.push_back(story.members[structure::kRotation]);
      twist_names.push_back(story.name);
    }
  }
  const auto drifts = [&](std::string name, std::string units,
                          const std::vector<int>& chosen_members, std::vector<std::string> columns,
                          const std::vector<double>& factors) {
    std::vector<ColumnSource> sources;
    for (std::size_t c = 0; c < chosen_members.size(); ++c) {
      sources.push_back(Deformation(problem.structure, static_cast<std::size_t>(chosen_members[c]),
                                    0, factors[c]));
    }
    return ReadOff(std::move(name), std::move(units), std::move(columns), std::move(sources));
  };
  series.push_back(
      drifts("story/drift", length, members, names, std::vector<double>(members.size(), 1.0)));
  if (heights) series.push_back(drifts("story/drift_ratio", "%", members, names, per_height));
  series.push_back(Columns("story/shear", force, names, RowArray::kConnectionForce, members));
  if (!twists.empty()) {
    series.push_back(
        drifts("story/twist", "rad", twists, twist_names, std::vector<double>(twists.size(), 1.0)));
    series.push_back(
        Columns("story/torque", energy, twist_names, RowArray::kConnectionForce, twists));
  }
}

void AppendEnergySeries(const Problem& problem, std::vector<Series>& series) {
  const std::string energy =
      fmt::format("{}*{}", problem.units().force(), problem.units().length());
  const auto energy_term = [&](const char* name, RowScalar term) {
    series.push_back(Scalar(fmt::format("energy/{}", name), energy, term));
  };
  energy_term("input", RowScalar::kInputEnergy);
  energy_term("kinetic", RowScalar::kKineticEnergy);
  energy_term("damping", RowScalar::kDampingEnergy);
  energy_term("elastic", RowScalar::kElasticEnergy);
  energy_term("hysteretic", RowScalar::kHystereticEnergy);
}

}  // namespace

RowArrays::RowArrays(const integrators::ResponseRow& row)
    : scalars_{row.time,
               row.energies.input,
               row.energies.kinetic,
               row.energies.damping,
               row.energies.elastic,
               row.energies.hysteretic},
      arrays_{row.displacement.data(),
              row.velocity.data(),
              row.acceleration.data(),
              row.absolute_acceleration.data(),
              row.connection_force.data(),
              row.law_force.data(),
              scalars_.data()} {}

std::size_t RowArrayWidth(RowArray array, const structure::Structure& structure) {
  switch (array) {
    case RowArray::kDisplacement:
    case RowArray::kVelocity:
    case RowArray::kAcceleration:
    case RowArray::kAbsoluteAcceleration:
      return static_cast<std::size_t>(structure.dofs());
    case RowArray::kConnectionForce:
      return structure.force_columns();
    case RowArray::kLawForce:
      return structure.law_count();
    case RowArray::kScalars:
      return kRowScalars;
  }
  return 0;
}

std::optional<RowArray> WholeArray(const Series& series, const structure::Structure& structure) {
  const std::vector<ColumnSource>& sources = series.sources;
  if (sources.empty() || sources.size() != RowArrayWidth(sources[0].array, structure)) {
    return std::nullopt;
  }
  for (std::size_t c = 0; c < sources.size(); ++c) {
    if (sources[c].sum || sources[c].array != sources[0].array ||
        sources[c].index != static_cast<int>(c)) {
      return std::nullopt;
    }
  }
  return sources[0].array;
}

std::vector<int> SelectedLevels(const model::OutputSelection& selection,
                                const structure::Layout& layout, const std::string& key) {
  const int levels = static_cast<int>(layout.levels.size());
  std::vector<int> selected;
  if (selection.levels.empty()) {
    for (int level = 0; level < levels; ++level) selected.push_back(level);
    return selected;
  }
  // Level 0 is the base when the building stands on one, or an SDOF's mass; floors count from 1.
  const bool has_level_zero = layout.isolated();
  for (const int level : selection.levels) {
    const int index = level == model::kRoofLevel ? levels - 1 : has_level_zero ? level : level - 1;
    if (index < 0 || index >= levels) {
      throw InputError(
          {key}, fmt::format("level {} is not in the structure (its levels are {} to "
                             "{}, or roof)",
                             level, has_level_zero ? 0 : 1, has_level_zero ? levels - 1 : levels));
    }
    selected.push_back(index);
  }
  std::sort(selected.begin(), selected.end());
  selected.erase(std::unique(selected.begin(), selected.end()), selected.end());
  return selected;
}

void CheckQuantitiesExist(const model::OutputSelection& selection, const structure::Layout& layout,
                          const std::string& key) {
  if (selection.summary_only) return;
  for (const std::string& name : selection.quantities) {
    if (name == "isolator" && !layout.isolated()) {
      throw InputError({key},
                       "isolator: the structure has no isolation layer in this run (a "
                       "fixed base): there is no isolator history to write");
    }
    if (name == "story" && layout.stories.empty()) {
      throw InputError({key},
                       "story: the structure has no stories (an SDOF): there is no story "
                       "history to write");
    }
  }
}

std::vector<std::string> RecordedQuantities(const model::OutputSelection& selection) {
  std::vector<std::string> quantities;
  for (const std::string_view name : model::kQuantityNames) {
    if (selection.Records(name)) quantities.emplace_back(name);
  }
  return quantities;
}

std::vector<std::string> RecordedLevels(const model::OutputSelection& selection,
                                        const Problem& problem) {
  std::vector<std::string> levels;
  if (selection.summary_only) return levels;
  for (const int level : SelectedLevels(selection, problem.layout, "output.levels")) {
    levels.push_back(problem.layout.levels[level].name);
  }
  return levels;
}

std::vector<Series> ResultSeries(const Problem& problem, const model::OutputSelection& selection) {
  std::vector<Series> series;
  if (selection.summary_only) return series;
  const structure::Layout& layout = problem.layout;
  const std::vector<int> levels = SelectedLevels(selection, layout, "output.levels");
  AppendGroundSeries(problem, series);
  AppendLevelSeries(problem, selection, levels, series);
  if (layout.isolated() && selection.Records("isolator")) AppendIsolatorSeries(problem, series);
  std::vector<std::size_t> stories;  // the selected stories
  for (std::size_t k = 0; k < layout.stories.size(); ++k) {
    if (IsSelected(levels, layout.stories[k].level)) stories.push_back(k);
  }
  if (!stories.empty() && selection.Records("story")) AppendStorySeries(problem, stories, series);
  if (selection.Records("energy")) AppendEnergySeries(problem, series);
  return series;
}

}  // namespace isolab::analysis
