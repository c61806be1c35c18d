#include "isolab/analysis/analysis_setup.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

#include "isolab/core/errors.h"
#include "isolab/io/record.h"
#include "isolab/structure/shear_building.h"

namespace isolab::analysis {
namespace {

structure::Structure BuildStructure(const model::ModelFile& model, bool fixed_base,
                                    StructureLayout* layout) {
  const model::StructureSection& section = *model.structure;
  if (section.kind == model::StructureSection::Kind::kSdof) {
    double c = section.damping_coefficient;
    if (section.damping_ratio) {
      c = 2.0 * *section.damping_ratio *
          std::sqrt(structure::InitialStiffness(model.isolation) * section.mass);
    }
    layout->isolation = 0;
    layout->dof_names = {"mass"};
    return structure::BuildSdof(section.mass, c, model.isolation);
  }
  structure::ShearBuilding building = section.building;
  building.isolated = !fixed_base && model.isolation.size() > 0;
  if (building.isolated) building.isolation = model.isolation;
  const int first_story = building.isolated ? 1 : 0;
  if (building.isolated) {
    layout->isolation = 0;
    layout->dof_names.push_back("base");
  }
  for (std::size_t s = 0; s < building.stories.size(); ++s) {
    layout->stories.push_back(first_story + static_cast<int>(s));
    layout->story_heights.push_back(building.stories[s].height);
    layout->dof_names.push_back(fmt::format("floor {}", s + 1));
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
  return StoryDrift(setup,
                    std::span<const double>(displacement.row(row).data(),
                                            static_cast<std::size_t>(displacement.cols())),
                    story);
}

double StoryDrift(const AnalysisSetup& setup, std::span<const double> displacement,
                  std::size_t story) {
  const structure::Connection& c = setup.structure.connections()[setup.layout.stories[story]];
  return displacement[c.dof_j] - (c.dof_i >= 0 ? displacement[c.dof_i] : 0.0);
}

namespace {

// The ground motion to apply: the model's, or the override's record with the override's units,
// dt and scale (the model's were given for its own record).
model::GroundMotionSection ChooseGroundMotion(const model::ModelFile& model,
                                              const RunOverrides& overrides,
                                              std::string* units_given_by,
                                              std::string* dt_given_by) {
  model::GroundMotionSection motion;
  const std::string in_model = fmt::format(" in {}", model.path);
  if (overrides.record_data) {
    motion.file = overrides.record_data->path;
  } else if (!overrides.record.empty()) {
    motion.file = overrides.record;
  } else {
    motion = *model.excitation.ground_motion;
    if (std::filesystem::path(motion.file).is_relative()) {
      motion.file = (std::filesystem::path(model.path).parent_path() / motion.file)
                        .lexically_normal()
                        .string();
    }
    *units_given_by = "excitation.ground_motion.units" + in_model;
    *dt_given_by = "excitation.ground_motion.dt" + in_model;
  }
  if (!overrides.record_units.empty()) {
    const auto size = [&](const std::string& unit) {
      try {
        return UnitSystem("N", "m", "s").Convert(1.0, unit, dimension::kAcceleration);
      } catch (const std::invalid_argument& error) {
        throw InputError({overrides.units_given_by}, error.what());
      }
    };
    if (!motion.units.empty() && size(motion.units) != size(overrides.record_units)) {
      throw InputError({overrides.units_given_by},
                       fmt::format("the record's units {} disagree with {} ({})",
                                   overrides.record_units, *units_given_by, motion.units));
    }
    motion.units = overrides.record_units;
    *units_given_by = overrides.units_given_by;
  }
  if (overrides.record_dt) {
    motion.dt = *overrides.record_dt;
    *dt_given_by = overrides.dt_given_by;
  }
  if (overrides.scale) motion.scale = *overrides.scale;
  return motion;
}

// How long the structure vibrates freely after the excitation: as chosen, or automatically a
// few of its longest periods.
double FreeVibrationLength(const model::AnalysisSection& analysis, const RunOverrides& overrides,
                           const ModelSummary& summary) {
  const model::FreeVibration choice = overrides.free_vibration.value_or(analysis.free_vibration);
  if (!choice.automatic) return choice.duration;
  const double period = summary.LongestPeriod();
  return std::isfinite(period) ? kAutomaticFreeVibrationPeriods * period : 0.0;
}

}  // namespace

io::AppliedRecord ApplyRecord(const model::GroundMotionSection& motion,
                              const std::string& units_given_by, const std::string& dt_given_by,
                              const UnitSystem& units, integrators::SampledHistory* acceleration,
                              const io::Record* data) {
  // Records keep their step in seconds; the model gives a single column's dt in its own unit.
  const double dt_seconds = motion.dt * units.SiFactor(dimension::kTime);
  const io::Record record =
      data ? *data
           : io::ReadRecord(motion.file, {motion.units, dt_seconds, units_given_by, dt_given_by});
  double to_model = 0.0;
  try {
    to_model = units.Convert(motion.scale, record.units, dimension::kAcceleration);
  } catch (const std::invalid_argument& error) {
    throw InputError({motion.file}, error.what());
  }
  acceleration->dt = units.Convert(record.dt, "s", dimension::kTime);
  acceleration->values.clear();
  for (const double a : record.values) acceleration->values.push_back(a * to_model);
  return {motion.file,
          record.format,
          record.units,
          record.units_source,
          record.dt,
          motion.scale,
          record.Peak() * std::abs(to_model)};
}

integrators::TimeGrid StepGrid(double dt, double duration, std::int64_t max_steps,
                               const std::string& where) {
  const double steps = std::round(duration / dt);
  // int is the integrators' step counter: no limit may pass it.
  const std::int64_t limit = std::min<std::int64_t>(max_steps, std::numeric_limits<int>::max());
  if (!(steps <= static_cast<double>(limit))) {
    throw InputError(
        {where}, fmt::format("the run would take {:.3g} steps of dt = {:g} over {:g} (time unit "
                             "of the model), more than the limit of {} steps: choose a larger dt "
                             "or a shorter duration, or raise the limit with isolab run "
                             "--max-steps N (at most {})",
                             steps, dt, duration, limit, std::numeric_limits<int>::max()));
  }
  return {dt, static_cast<int>(steps)};
}

AnalysisSetup PrepareAnalysis(const model::ModelFile& model, const RunOverrides& overrides) {
  if (!model.structure) {
    throw InputError({model.path}, "no structure section: nothing to analyse in time");
  }
  if (overrides.fixed_base &&
      model.structure->kind != model::StructureSection::Kind::kShearBuilding) {
    throw InputError({"command line"}, "--fixed-base applies to a shear building only");
  }
  StructureLayout layout;
  structure::Structure structure = BuildStructure(model, overrides.fixed_base, &layout);
  AnalysisSetup setup{std::move(structure), std::move(layout), {}, {}, {}, {}, 0.0, 0.0, 0.0};
  const int dofs = setup.structure.dofs();
  // A fixed-base variant loses the base DOF: applied forces shift down by one.
  const int dof_shift = (overrides.fixed_base && model.isolation.size() > 0) ? -1 : 0;

  const model::ExcitationSection& excitation = model.excitation;
  const bool has_record =
      excitation.ground_motion || !overrides.record.empty() || overrides.record_data;
  if (!has_record && (!overrides.record_units.empty() || overrides.record_dt)) {
    throw InputError({overrides.units_given_by},
                     fmt::format("the record's units or step are given, but {} has no ground "
                                 "motion (give a record)",
                                 model.path));
  }
  double record_dt = 0.0;
  if (has_record) {
    std::string units_given_by, dt_given_by;
    const model::GroundMotionSection motion =
        ChooseGroundMotion(model, overrides, &units_given_by, &dt_given_by);
    setup.record = ApplyRecord(motion, units_given_by, dt_given_by, model.units,
                               &setup.excitation.ground_acceleration,
                               overrides.record_data ? &*overrides.record_data : nullptr);
    record_dt = setup.excitation.ground_acceleration.dt;
  }
  for (const model::ForceSection& force : excitation.forces) {
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
  if (!setup.record.path.empty() && dt > record_dt * (1.0 + 1e-9)) {
    throw InputError({overrides.dt ? "command line" : model.path},
                     fmt::format("dt = {:g} is coarser than the record's {:g}; the analysis step "
                                 "may only refine it",
                                 dt, record_dt));
  }
  const double trial = overrides.trial_displacement.value_or(
      model.units.Convert(kDefaultTrialDisplacement, "m", dimension::kLength));
  if (!(trial > 0.0)) {
    throw InputError({"command line"}, fmt::format("--trial-displacement {:g} must be > 0", trial));
  }
  setup.summary = SummariseModel(model, overrides.fixed_base, setup.record.pga, trial);

  setup.excitation_end = setup.excitation.duration();
  double duration = model.analysis.duration;
  if (duration > 0.0 && overrides.free_vibration) {
    throw InputError({"command line"},
                     fmt::format("the model fixes the run's duration (analysis.duration in {}); "
                                 "--free-vibration cannot lengthen it",
                                 model.path));
  }
  if (duration <= 0.0) {
    setup.free_vibration = FreeVibrationLength(model.analysis, overrides, setup.summary);
    duration = setup.excitation_end + setup.free_vibration;
  } else {
    setup.free_vibration = std::max(0.0, duration - setup.excitation_end);
  }
  setup.residual_window = std::min(setup.summary.LongestPeriod(), setup.free_vibration);
  setup.grid = StepGrid(dt, duration, overrides.max_steps, overrides.dt ? "--dt" : model.path);
  return setup;
}

}  // namespace isolab::analysis
