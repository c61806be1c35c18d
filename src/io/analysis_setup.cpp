#include "isolab/io/analysis_setup.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>

#include "isolab/core/errors.h"
#include "isolab/io/record.h"
#include "isolab/structure/shear_building.h"

namespace isolab::io {
namespace {

structure::Structure BuildStructure(const ModelFile& model, bool fixed_base,
                                    StructureLayout* layout) {
  const StructureSection& section = *model.structure;
  if (section.kind == StructureSection::Kind::kSdof) {
    double c = section.damping_coefficient;
    if (section.damping_ratio) {
      c = 2.0 * *section.damping_ratio *
          std::sqrt(structure::InitialStiffness(model.isolation) * section.mass);
    }
    layout->isolation = 0;
    return structure::BuildSdof(section.mass, c, model.isolation);
  }
  structure::ShearBuilding building = section.building;
  building.isolated = !fixed_base && model.isolation.size() > 0;
  if (building.isolated) building.isolation = model.isolation;
  const int first_story = building.isolated ? 1 : 0;
  if (building.isolated) layout->isolation = 0;
  for (std::size_t s = 0; s < building.stories.size(); ++s) {
    layout->stories.push_back(first_story + static_cast<int>(s));
    layout->story_heights.push_back(building.stories[s].height);
  }
  try {
    return structure::BuildShearBuilding(building);
  } catch (const std::invalid_argument& error) {
    throw InputError({model.path}, error.what());
  }
}

}  // namespace

double StoryDrift(const AnalysisSetup& setup, const integrators::RowMatrix& displacement, int row,
                  std::size_t story) {
  const structure::Connection& c = setup.structure.connections()[setup.layout.stories[story]];
  return displacement(row, c.dof_j) - (c.dof_i >= 0 ? displacement(row, c.dof_i) : 0.0);
}

AnalysisSetup PrepareAnalysis(const ModelFile& model, const RunOverrides& overrides) {
  if (!model.structure) {
    throw InputError({model.path}, "no structure section: nothing to analyse in time");
  }
  if (overrides.fixed_base && model.structure->kind != StructureSection::Kind::kShearBuilding) {
    throw InputError({"command line"}, "--fixed-base applies to a shear building only");
  }
  StructureLayout layout;
  structure::Structure structure = BuildStructure(model, overrides.fixed_base, &layout);
  AnalysisSetup setup{std::move(structure), std::move(layout), {}, {}, {}, 1.0};
  const int dofs = setup.structure.dofs();
  // A fixed-base variant loses the base DOF: applied forces shift down by one.
  const int dof_shift = (overrides.fixed_base && model.isolation.size() > 0) ? -1 : 0;

  const ExcitationSection& excitation = model.excitation;
  double record_dt = 0.0;
  if (excitation.ground_motion || !overrides.record.empty()) {
    GroundMotionSection motion = excitation.ground_motion.value_or(GroundMotionSection{});
    if (!overrides.record.empty()) {
      motion.file = overrides.record;
    } else if (std::filesystem::path(motion.file).is_relative()) {
      motion.file = (std::filesystem::path(model.path).parent_path() / motion.file).string();
    }
    if (overrides.scale) motion.scale = *overrides.scale;
    // Records keep their step in seconds; the model gives a single column's dt in its own unit.
    const double dt_seconds = motion.dt * model.units.SiFactor(dimension::kTime);
    const Record record = ReadRecord(motion.file, {motion.units, dt_seconds});
    double to_model = 0.0;
    try {
      to_model = model.units.Convert(motion.scale, record.units, dimension::kAcceleration);
    } catch (const std::invalid_argument& error) {
      throw InputError({motion.file}, error.what());
    }
    setup.excitation.ground_acceleration.dt = model.units.Convert(record.dt, "s", dimension::kTime);
    for (const double a : record.values)
      setup.excitation.ground_acceleration.values.push_back(a * to_model);
    record_dt = setup.excitation.ground_acceleration.dt;
    setup.record_path = motion.file;
    setup.scale = motion.scale;
  }
  for (const ForceSection& force : excitation.forces) {
    const int dof = force.dof + dof_shift;
    if (dof < 0 || dof >= dofs) {
      throw InputError({model.path}, fmt::format("excitation force on dof {} does not exist in "
                                                 "this variant ({} dofs)",
                                                 force.dof, dofs));
    }
    setup.excitation.forces.push_back({dof, {force.dt, force.values}});
    if (record_dt == 0.0) record_dt = force.dt;
  }
  if (setup.excitation.duration() <= 0.0 && record_dt == 0.0) {
    throw InputError({model.path}, "no excitation: give excitation.ground_motion or forces");
  }

  const double dt = overrides.dt.value_or(model.analysis.dt > 0.0 ? model.analysis.dt : record_dt);
  if (!(dt > 0.0)) throw InputError({"command line"}, fmt::format("--dt {:g} must be > 0", dt));
  if (!setup.record_path.empty() && dt > record_dt * (1.0 + 1e-9)) {
    throw InputError({overrides.dt ? "command line" : model.path},
                     fmt::format("dt = {:g} is coarser than the record's {:g}; the analysis step "
                                 "may only refine it",
                                 dt, record_dt));
  }
  const double duration =
      model.analysis.duration > 0.0 ? model.analysis.duration : setup.excitation.duration();
  setup.grid = {dt, static_cast<int>(std::round(duration / dt))};
  return setup;
}

}  // namespace isolab::io
