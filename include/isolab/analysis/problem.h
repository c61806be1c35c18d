// From a model file (and command-line, study or Python overrides) to a problem an integrator can
// run, whatever the kind of model: the structure and its layout (model/build_structure.h), the
// excitation in model units, the output time grid (the excitation, then free vibration), the
// records as applied and the model summary (model_summary.h).
//
// A record's horizontal components H1 (and H2, at angle + 90 degrees) are turned to the
// structure's axes: a_x = cos(angle) H1 - sin(angle) H2, a_y = sin(angle) H1 + cos(angle) H2. A
// structure that moves along x only takes one component at angle 0. A pair must share its step
// and its length (PEER's pairs do): anything else is refused.
//
// A record that replaces the model's (`run --record`, a study's records, an array from Python) is
// a different record: the model's ground_motion units, dt and scale were given for the model's own
// record and do not carry over to it. Its units and step come from its own header, or from the
// override that names it; its scale is the override's, else 1.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "isolab/analysis/model_summary.h"
#include "isolab/integrators/excitation.h"
#include "isolab/integrators/response.h"
#include "isolab/io/record.h"
#include "isolab/model/model_file.h"
#include "isolab/structure/layout.h"

namespace isolab::analysis {

// The most analysis steps a run takes unless told otherwise (isolab run --max-steps): 10^7 steps
// is 10,000 s at dt = 0.001 s, hours of computing and gigabytes of results. A dt or a duration
// typed wrong by orders of magnitude is refused before anything is allocated or run.
inline constexpr std::int64_t kDefaultMaxSteps = 10'000'000;

// Automatic free vibration: this many times the model's longest period.
inline constexpr double kAutomaticFreeVibrationPeriods = 5.0;

// The grid of `duration` in steps of `dt`, the count taken in 64 bits. Throws InputError at
// `where` (the file or option that set dt or the duration) when it exceeds `max_steps`, naming
// `raise_with` (how the caller raises the limit; empty: it cannot).
integrators::TimeGrid StepGrid(double dt, double duration, std::int64_t max_steps,
                               const std::string& where,
                               const std::string& raise_with = "isolab run --max-steps N");

// A record component replacing the model's ground motion.
struct RecordOverride {
  std::string name = "--record";     // what gives it, for messages ("--record-h2", "records[2]")
  std::string file{};                // relative to the working directory
  std::optional<io::Record> data{};  // a record in memory (a numpy array), instead of a file
  std::string units{};               // its acceleration unit; empty: from its header
  double dt = 0.0;                   // its sampling step (model time unit); 0: from the file
  double scale = 1.0;
  // A target the record is scaled to (a study's record entry: `scale: {pga: ...}`), `scale` then
  // multiplying the factor it gives; none: `scale` alone.
  std::optional<model::ScaleTarget> target{};
  std::string units_given_by = "--units";  // who gives `units` and `dt`, for messages
  std::string dt_given_by = "--record-dt";
};

// How the caller names the overrides in its messages: the command line's options (the default),
// or the Python module's keywords. An empty max_steps: the caller has no way to raise the limit.
struct OverrideNames {
  std::string dt = "--dt", trial_displacement = "--trial-displacement",
              free_vibration = "--free-vibration", angle = "--angle", fixed_base = "--fixed-base",
              max_steps = "isolab run --max-steps N", scale = "--scale";
};

struct RunOverrides {
  // H1 (and H2) replacing the model's ground motion; empty: the model's own.
  std::vector<RecordOverride> records;
  // With `records`, the vertical component (upwards) replacing the model's (--record-v); it needs
  // axial_load: {vertical: true} in the model.
  std::optional<RecordOverride> vertical;
  double angle = 0.0;  // with `records`: degrees from the x axis to H1
  // The units and step of every component in use (the model's own, or `records`'), which must
  // agree with what its header or its entry says.
  std::string record_units;
  std::optional<double> record_dt;  // (model time unit)
  std::string units_given_by = "--units", dt_given_by = "--record-dt";
  std::optional<double> scale;               // replaces every component's scale
  std::optional<double> dt;                  // replaces analysis.dt (model time unit)
  bool fixed_base = false;                   // analyse the superstructure without its isolation
  std::optional<double> trial_displacement;  // model length; default 0.1 m
  std::optional<model::FreeVibration> free_vibration;  // replaces analysis.free_vibration
  std::int64_t max_steps = kDefaultMaxSteps;           // the most analysis steps (StepGrid)
  OverrideNames names;
};

struct Problem {
  model::ModelFile model;  // what was prepared: its units, path and text go with the results
  structure::Structure structure;
  structure::Layout layout;
  integrators::Excitation excitation;
  integrators::TimeGrid grid;
  std::vector<io::AppliedRecord> records;  // H1 (and H2) as applied; empty without a record
  double angle = 0.0;                      // degrees from x to H1
  ModelSummary summary;
  double excitation_end = 0.0;  // (time) the record's (or applied forces') end
  double free_vibration = 0.0;  // (time) run after it
  // (time) the window at the end of the run whose mid-range is the residual displacement
  // (response_peaks.h): the structure's longest period, within the free vibration.
  double residual_window = 0.0;
  std::optional<io::AppliedRecord> vertical_record{};  // the vertical component as applied

  const UnitSystem& units() const { return model.units; }
  // The angle of H1 from x where it means something: a structure that moves in two directions,
  // under a record. Every output that states the angle asks this.
  std::optional<double> IncidenceAngle() const {
    if (layout.directions > 1 && !records.empty()) return angle;
    return std::nullopt;
  }
};

// Reads the record `motion` names (its file resolved already), or takes `data` when given (a
// record already in memory), into `acceleration` in the model's `units`, scaled; returns it as
// applied. Throws InputError as io::ReadRecord does, and for units that are not an acceleration.
io::AppliedRecord ApplyRecord(const model::GroundMotionSection& motion,
                              const std::string& units_given_by, const std::string& dt_given_by,
                              const UnitSystem& units, integrators::SampledHistory* acceleration,
                              const io::Record* data = nullptr);

// Throws InputError (naming the file, or the option) for records that cannot be read or whose
// units or step disagree with what is given, a pair that does not match, more components than the
// structure has directions, a dt coarser than the record's, or a model without what the analysis
// needs.
Problem Prepare(const model::ModelFile& model, const RunOverrides& overrides);

}  // namespace isolab::analysis
