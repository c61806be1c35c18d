#include "isolab/analysis/problem.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>

#include "isolab/core/errors.h"
#include "isolab/model/build_structure.h"
#include "isolab/spectra/elastic_spectrum.h"

namespace isolab::analysis {
namespace {

// A ground motion component to read: what it is, who gave its units and step, and where it is
// named (for a pair that does not match).
struct Component {
  model::GroundMotionSection motion;
  std::string units_given_by, dt_given_by;
  std::string scale_given_by;  // the option that replaced the scale; empty: the model's own
  const io::Record* data = nullptr;
};

// The components to apply: the model's (files relative to the model's folder), or the overrides'
// (the model's units, dt and scale were given for the model's own record and do not carry over).
Component FromOverride(const RecordOverride& record) {
  Component c;
  c.motion.file = record.data ? record.data->path : record.file;
  c.motion.units = record.units;
  c.motion.dt = record.dt;
  c.motion.scale = record.scale;
  c.motion.target = record.target;
  c.motion.key = record.name;
  c.motion.location = {record.name};
  c.units_given_by = record.units_given_by;
  c.dt_given_by = record.dt_given_by;
  c.data = record.data ? &*record.data : nullptr;
  return c;
}

Component FromModel(const model::ModelFile& model, const model::GroundMotionSection& motion) {
  Component c;
  c.motion = motion;
  if (std::filesystem::path(motion.file).is_relative()) {
    c.motion.file =
        (std::filesystem::path(model.path).parent_path() / motion.file).lexically_normal().string();
  }
  const std::string in_model = fmt::format(" in {}", model.path);
  c.units_given_by = motion.key + ".units" + in_model;
  c.dt_given_by = motion.key + ".dt" + in_model;
  return c;
}

// The horizontal components, then the vertical one when there is one (the last entry, flagged by
// `vertical`).
std::vector<Component> ChooseComponents(const model::ModelFile& model,
                                        const RunOverrides& overrides, bool* vertical) {
  // A step of 0 reads as none given, and a file's own step would then stand in silently.
  if (overrides.record_dt && !(*overrides.record_dt > 0.0 && std::isfinite(*overrides.record_dt))) {
    throw InputError(
        {overrides.dt_given_by},
        fmt::format("{:g}: a sampling step must be finite and > 0", *overrides.record_dt));
  }
  std::vector<Component> components;
  *vertical = false;
  if (!overrides.records.empty()) {
    for (const RecordOverride& record : overrides.records) {
      components.push_back(FromOverride(record));
    }
    if (overrides.vertical) {
      components.push_back(FromOverride(*overrides.vertical));
      *vertical = true;
    }
  } else {
    for (const model::GroundMotionSection& motion : model.excitation.ground_motion) {
      components.push_back(FromModel(model, motion));
    }
    if (model.excitation.vertical) {
      components.push_back(FromModel(model, *model.excitation.vertical));
      *vertical = true;
    }
  }
  if (components.empty() && (!overrides.record_units.empty() || overrides.record_dt)) {
    throw InputError({overrides.units_given_by},
                     fmt::format("the record's units or step are given, but {} has no ground "
                                 "motion (give a record)",
                                 model.path));
  }
  for (Component& c : components) {
    if (!overrides.record_units.empty()) {
      const auto size = [&](const std::string& unit) {
        try {
          return UnitSystem("N", "m", "s").Convert(1.0, unit, dimension::kAcceleration);
        } catch (const std::invalid_argument& error) {
          throw InputError({overrides.units_given_by}, error.what());
        }
      };
      if (!c.motion.units.empty() && size(c.motion.units) != size(overrides.record_units)) {
        throw InputError({overrides.units_given_by},
                         fmt::format("the record's units {} disagree with {} ({})",
                                     overrides.record_units, c.units_given_by, c.motion.units));
      }
      c.motion.units = overrides.record_units;
      c.units_given_by = overrides.units_given_by;
    }
    if (overrides.record_dt) {
      c.motion.dt = *overrides.record_dt;
      c.dt_given_by = overrides.dt_given_by;
    }
    if (overrides.scale) {
      c.motion.scale = *overrides.scale;
      c.motion.target.reset();
      c.scale_given_by = overrides.names.scale;
    }
  }
  return components;
}

// The components along the structure's axes: one along x, or x and y turned by the angle.
void AddGroundMotion(const std::vector<integrators::SampledHistory>& components, double angle,
                     const structure::Layout& layout, integrators::Excitation* excitation) {
  if (components.empty()) return;
  const integrators::SampledHistory& h1 = components[0];
  if (layout.directions == 1) {
    *excitation = integrators::Excitation::Horizontal(layout, h1);
    return;
  }
  const double radians = angle * std::numbers::pi / 180.0;
  const double c = std::cos(radians), s = std::sin(radians);
  integrators::SampledHistory x{h1.dt, {}}, y{h1.dt, {}};
  for (std::size_t k = 0; k < h1.values.size(); ++k) {
    const double h2 = components.size() > 1 ? components[1].values[k] : 0.0;
    x.values.push_back(c * h1.values[k] - s * h2);
    y.values.push_back(s * h1.values[k] + c * h2);
  }
  *excitation = integrators::Excitation::Horizontal(layout, std::move(x), std::move(y));
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

// The factor that brings the record (`unscaled`, in model units) to `target`: PGA and Sa are both
// proportional to the record, so it is the target over the record's own value.
double TargetScale(const model::ScaleTarget& target, const model::GroundMotionSection& motion,
                   const integrators::SampledHistory& unscaled) {
  double measured = 0.0;
  if (target.measure == model::ScaleTarget::Measure::kPga) {
    for (const double a : unscaled.values) measured = std::max(measured, std::abs(a));
  } else {
    const double period = target.period, damping = target.damping;
    try {
      measured = spectra::ComputeElasticSpectrum(unscaled, {&period, 1}, {&damping, 1})
                     .at(0, 0)
                     .pseudo_acceleration;
    } catch (const InvalidParameter& error) {
      throw InputError(motion.location, fmt::format("{}.scale: {} (the record {})", motion.key,
                                                    error.what(), motion.file));
    }
  }
  if (!(measured > 0.0)) {
    throw InputError(
        motion.location,
        fmt::format("{}.scale: the record {} has no motion to scale to {} (its {} is "
                    "0)",
                    motion.key, motion.file, target.text,
                    target.measure == model::ScaleTarget::Measure::kPga ? "PGA" : "Sa"));
  }
  return target.value / measured;
}

// A record file that is not there is named where the model (or the option) gives it.
void RequireRecordFile(const model::GroundMotionSection& motion) {
  std::error_code error;
  if (std::filesystem::is_regular_file(motion.file, error)) return;
  const std::string key = motion.location.file == motion.key ? "" : motion.key + ".file: ";
  throw InputError(motion.location, fmt::format("{}'{}' is not a file{}", key, motion.file,
                                                error ? " (" + error.message() + ")" : ""));
}

}  // namespace

io::AppliedRecord ApplyRecord(const model::GroundMotionSection& motion,
                              const std::string& units_given_by, const std::string& dt_given_by,
                              const UnitSystem& units, integrators::SampledHistory* acceleration,
                              const io::Record* data) {
  // Records keep their step in seconds; the model gives a single column's dt in its own unit.
  const double dt_seconds = motion.dt * units.SiFactor(dimension::kTime);
  if (!data) RequireRecordFile(motion);
  const io::Record record =
      data ? *data
           : io::ReadRecord(motion.file, {motion.units, dt_seconds, units_given_by, dt_given_by});
  double unit = 0.0;  // the record's unit in the model's
  try {
    unit = units.Convert(1.0, record.units, dimension::kAcceleration);
  } catch (const std::invalid_argument& error) {
    throw InputError({motion.file}, error.what());
  }
  acceleration->dt = units.Convert(record.dt, "s", dimension::kTime);
  acceleration->values.clear();
  for (const double a : record.values) acceleration->values.push_back(a * unit);
  // A model's target leaves `scale` at 1; a study's scale multiplies its entry's target.
  const double scale = motion.target
                           ? TargetScale(*motion.target, motion, *acceleration) * motion.scale
                           : motion.scale;
  for (double& a : acceleration->values) a *= scale;
  return {motion.file,
          record.format,
          record.units,
          record.units_source,
          record.dt,
          scale,
          record.Peak() * std::abs(unit) * scale,
          !motion.target        ? std::string()
          : motion.scale == 1.0 ? motion.target->text
                                : fmt::format("{} x {:g}", motion.target->text, motion.scale)};
}

integrators::TimeGrid StepGrid(double dt, double duration, std::int64_t max_steps,
                               const std::string& where, const std::string& raise_with) {
  const double steps = std::round(duration / dt);
  // int is the integrators' step counter: no limit may pass it.
  const std::int64_t limit = std::min<std::int64_t>(max_steps, std::numeric_limits<int>::max());
  if (!(steps <= static_cast<double>(limit))) {
    const std::string raise = raise_with.empty()
                                  ? std::string()
                                  : fmt::format(", or raise the limit with {} (at most {})",
                                                raise_with, std::numeric_limits<int>::max());
    throw InputError(
        {where}, fmt::format("the run would take {:.3g} steps of dt = {:g} over {:g} (time unit "
                             "of the model), more than the limit of {} steps: choose a larger dt "
                             "or a shorter duration{}",
                             steps, dt, duration, limit, raise));
  }
  return {dt, static_cast<int>(steps)};
}

namespace {

// A command-line component's location is its option already; a model's names file and line.
std::string KeyOf(const Component& c) {
  return c.motion.location.file == c.motion.key ? std::string() : c.motion.key + ": ";
}

// A scale that overflows the record is named where it was given: the option, or the model's key.
void RequireFiniteScaledMotion(const Component& c, const io::AppliedRecord& applied,
                               const integrators::SampledHistory& history) {
  const bool by_option = !c.scale_given_by.empty();
  io::RequireFiniteScaledRecord(history.values, applied.scale, c.motion.file,
                                by_option ? SourceLocation{c.scale_given_by} : c.motion.location,
                                by_option ? std::string() : KeyOf(c));
}

// The run's horizontal components, and its vertical one into `vertical` where the record has one
// and the model asks for it (a vertical component acts only through the axial loads).
std::vector<Component> ChooseHorizontalComponents(const model::ModelFile& model,
                                                  const RunOverrides& overrides,
                                                  std::optional<Component>& vertical) {
  if (overrides.vertical && overrides.records.empty()) {
    throw InputError({overrides.vertical->name}, "needs --record: the record's first component");
  }
  bool has_vertical = false;
  std::vector<Component> components = ChooseComponents(model, overrides, &has_vertical);
  const bool vertical_asked = model.axial_load && model.axial_load->vertical;
  if (has_vertical && !vertical_asked) {
    throw InputError(components.back().motion.location,
                     fmt::format("{}a vertical component acts only through the axial loads of "
                                 "friction pendulum bearings: the model needs axial_load: "
                                 "{{vertical: true}}",
                                 KeyOf(components.back())));
  }
  if (vertical_asked && !has_vertical) {
    throw InputError(model.axial_load->location,
                     overrides.records.empty()
                         ? std::string("axial_load.vertical: the record has no vertical component "
                                       "(excitation.ground_motion.v)")
                         : std::string("axial_load.vertical: the record replacing the model's has "
                                       "no vertical component (give --record-v)"));
  }
  if (has_vertical) {
    vertical = std::move(components.back());
    components.pop_back();
  }
  return components;
}

// The components applied to the problem (scaled, in the model's units, turned by the angle), each
// checked against h1; returns the record's step (0 without a record).
double ApplyGroundMotions(const model::ModelFile& model, const RunOverrides& overrides,
                          std::vector<Component>& components, std::optional<Component>& vertical,
                          Problem& problem) {
  const structure::Layout& layout = problem.layout;
  const double angle = overrides.records.empty() ? model.excitation.angle : overrides.angle;
  // A command-line component's location is its option already; a model's names file and line.
  if (static_cast<int>(components.size()) > layout.directions) {
    throw InputError(components[1].motion.location,
                     fmt::format("{}the structure moves along x only: one component, along x "
                                 "(a second component needs a building in plan)",
                                 KeyOf(components[1])));
  }
  if (const std::string problem = model::RecordAngleProblem(angle);
      !overrides.records.empty() && !problem.empty()) {
    throw InputError({overrides.names.angle}, problem);
  }
  if (layout.directions == 1 && angle != 0.0) {
    throw InputError(overrides.records.empty() ? SourceLocation{model.path}
                                               : SourceLocation{overrides.names.angle},
                     "the structure moves along x only: an angle of the record to the x axis "
                     "needs a building in plan");
  }
  std::vector<integrators::SampledHistory> histories(components.size());
  // A target scales the whole record by the one factor computed from h1 (model_file.h).
  const auto h1_target = [&] { return !components.empty() && components[0].motion.target; };
  const auto take_h1_scale = [&](Component* c) {
    if (h1_target()) c->motion.scale = problem.records[0].scale;
  };
  const auto report_h1_scale = [&](io::AppliedRecord* applied) {
    if (h1_target()) applied->scaled_to = problem.records[0].scaled_to + " of h1";
  };
  for (std::size_t i = 0; i < components.size(); ++i) {
    Component& c = components[i];
    if (i > 0) take_h1_scale(&c);
    problem.records.push_back(
        ApplyRecord(c.motion, c.units_given_by, c.dt_given_by, model.units, &histories[i], c.data));
    RequireFiniteScaledMotion(c, problem.records.back(), histories[i]);
    if (i == 0) continue;
    report_h1_scale(&problem.records.back());
    const integrators::SampledHistory& h1 = histories[0];
    if (std::abs(histories[i].dt - h1.dt) > 1e-9 * h1.dt) {
      throw InputError(c.motion.location,
                       fmt::format("{}its step {:g} differs from h1's {:g}; a pair must share "
                                   "one step",
                                   KeyOf(c), histories[i].dt, h1.dt));
    }
    if (histories[i].values.size() != h1.values.size()) {
      throw InputError(c.motion.location,
                       fmt::format("{}{} samples, h1 has {}; a pair must have the same length",
                                   KeyOf(c), histories[i].values.size(), h1.values.size()));
    }
  }
  problem.angle = angle;
  AddGroundMotion(histories, angle, layout, &problem.excitation);
  if (vertical) {
    Component& c = *vertical;
    take_h1_scale(&c);
    problem.vertical_record = ApplyRecord(c.motion, c.units_given_by, c.dt_given_by, model.units,
                                          &problem.excitation.vertical, c.data);
    RequireFiniteScaledMotion(c, *problem.vertical_record, problem.excitation.vertical);
    report_h1_scale(&*problem.vertical_record);
    if (histories.empty()) {
      throw InputError(
          c.motion.location,
          fmt::format("{}a vertical component needs the horizontal h1 beside it", KeyOf(c)));
    }
    const integrators::SampledHistory& h1 = histories[0];
    if (std::abs(problem.excitation.vertical.dt - h1.dt) > 1e-9 * h1.dt ||
        problem.excitation.vertical.values.size() != h1.values.size()) {
      throw InputError(
          c.motion.location,
          fmt::format("{}its step {:g} and {} samples differ from h1's {:g} and {}; "
                      "the record's components must share their step and length",
                      KeyOf(c), problem.excitation.vertical.dt,
                      problem.excitation.vertical.values.size(), h1.dt, h1.values.size()));
    }
  }
  return histories.empty() ? 0.0 : histories[0].dt;
}

// The model's applied forces, on the variant's dofs; returns the step to run on where no record
// gives one.
double ApplyForces(const model::ModelFile& model, const RunOverrides& overrides, double record_dt,
                   Problem& problem) {
  const structure::Layout& layout = problem.layout;
  const int dofs = problem.structure.dofs();
  // A fixed-base variant loses the base's dofs: applied forces shift down by them.
  int dof_shift = 0;
  if (overrides.fixed_base && model::BuildStructure(model).layout.isolated()) {
    dof_shift = -(layout.directions + (layout.rotations ? 1 : 0));
  }
  for (const model::ForceSection& force : model.excitation.forces) {
    const int dof = force.dof + dof_shift;
    if (dof < 0 || dof >= dofs) {
      throw InputError({model.path}, fmt::format("excitation force on dof {} does not exist in "
                                                 "this variant ({} dofs)",
                                                 force.dof, dofs));
    }
    problem.excitation.forces.push_back({dof, {force.dt, force.values}});
    if (record_dt == 0.0) record_dt = force.dt;
  }
  if (problem.excitation.duration() <= 0.0 && record_dt == 0.0) {
    throw InputError({model.path}, "no excitation: give excitation.ground_motion or forces");
  }
  return record_dt;
}

// The step, the model's summary and the run's length: the excitation, then free vibration.
void SetTimeGrid(const model::ModelFile& model, const RunOverrides& overrides, double record_dt,
                 const structure::LaidOutStructure* fixed_base, Problem& problem) {
  const double dt = overrides.dt.value_or(model.analysis.dt > 0.0 ? model.analysis.dt : record_dt);
  const OverrideNames& names = overrides.names;
  if (!(dt > 0.0)) throw InputError({names.dt}, fmt::format("{:g} must be > 0", dt));
  if (!problem.records.empty() && dt > record_dt * (1.0 + 1e-9)) {
    throw InputError({overrides.dt ? names.dt : model.path},
                     fmt::format("dt = {:g} is coarser than the record's {:g}; the analysis step "
                                 "may only refine it",
                                 dt, record_dt));
  }
  const double trial = overrides.trial_displacement.value_or(
      model.units.Convert(kDefaultTrialDisplacement, "m", dimension::kLength));
  if (!(trial > 0.0)) {
    throw InputError({names.trial_displacement}, fmt::format("{:g} must be > 0", trial));
  }
  double pga = 0.0;
  for (const io::AppliedRecord& record : problem.records) pga = std::max(pga, record.pga);
  problem.summary =
      SummariseModel(problem.structure, problem.layout, fixed_base, model.units, pga, trial);

  problem.excitation_end = problem.excitation.duration();
  double duration = model.analysis.duration;
  if (duration > 0.0 && overrides.free_vibration) {
    throw InputError({names.free_vibration},
                     fmt::format("the model fixes the run's duration (analysis.duration in {}); "
                                 "free vibration cannot lengthen it",
                                 model.path));
  }
  if (duration <= 0.0) {
    problem.free_vibration = FreeVibrationLength(model.analysis, overrides, problem.summary);
    duration = problem.excitation_end + problem.free_vibration;
  } else {
    problem.free_vibration = std::max(0.0, duration - problem.excitation_end);
  }
  problem.residual_window = std::min(problem.summary.LongestPeriod(), problem.free_vibration);
  problem.grid = StepGrid(dt, duration, overrides.max_steps, overrides.dt ? names.dt : model.path,
                          names.max_steps);
}

}  // namespace

Problem Prepare(const model::ModelFile& model, const RunOverrides& overrides) {
  if (overrides.fixed_base && model.axial_load) {
    throw InputError(model.axial_load->location,
                     "axial_load: the run is on a fixed base (--fixed-base, fixed_base): no "
                     "bearing carries the weight; leave one of the two out");
  }
  if (overrides.fixed_base && overrides.trial_displacement) {
    throw InputError({overrides.names.trial_displacement},
                     fmt::format("sets where the isolated periods are read, and the run is on a "
                                 "fixed base ({}), which has none: leave one of the two out",
                                 overrides.names.fixed_base));
  }
  structure::LaidOutStructure built =
      model::BuildStructure(model, overrides.fixed_base, overrides.names.fixed_base);
  // The superstructure on a fixed base, for its periods: the run's own structure, or built once
  // more (an SDOF and a slab on isolators have none).
  std::optional<structure::LaidOutStructure> fixed_base;
  if (!overrides.fixed_base && !built.layout.stories.empty()) {
    fixed_base = model::BuildStructure(model, true);
  }
  Problem problem{model, std::move(built.structure), std::move(built.layout), {}, {}, {}, 0.0, {}};
  std::optional<Component> vertical;
  std::vector<Component> components = ChooseHorizontalComponents(model, overrides, vertical);
  double record_dt = ApplyGroundMotions(model, overrides, components, vertical, problem);
  record_dt = ApplyForces(model, overrides, record_dt, problem);
  SetTimeGrid(model, overrides, record_dt, fixed_base ? &*fixed_base : nullptr, problem);
  return problem;
}

}  // namespace isolab::analysis
