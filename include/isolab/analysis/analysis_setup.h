// From a model file (and command-line or study overrides) to what an integrator runs: the
// structure, the excitation in model units, the output time grid (the excitation, then free
// vibration), where the isolation layer and stories are, what the record was read as, and the
// model summary (model_summary.h).
//
// A record that replaces the model's (`run --record`, a study's records) is a different record:
// the model's ground_motion units, dt and scale were given for the model's own record and do not
// carry over to it. Its units and step come from its own header, or from the override that names
// it; its scale is the override's, else 1.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "isolab/analysis/model_summary.h"
#include "isolab/integrators/excitation.h"
#include "isolab/integrators/newmark.h"
#include "isolab/integrators/response.h"
#include "isolab/io/record.h"
#include "isolab/model/model_file.h"
#include "isolab/structure/structure.h"

namespace isolab::analysis {

// The most analysis steps a run takes unless told otherwise (isolab run --max-steps): 10^7 steps
// is 10,000 s at dt = 0.001 s, hours of computing and gigabytes of results. A dt or a duration
// typed wrong by orders of magnitude is refused before anything is allocated or run.
inline constexpr std::int64_t kDefaultMaxSteps = 10'000'000;

// The grid of `duration` in steps of `dt`, the count taken in 64 bits. Throws InputError at
// `where` (the file or option that set dt or the duration) when it exceeds `max_steps`.
integrators::TimeGrid StepGrid(double dt, double duration, std::int64_t max_steps,
                               const std::string& where);

struct RunOverrides {
  std::string record;  // replaces excitation.ground_motion.file (relative to the cwd)
  // A record already in memory (e.g. a numpy array from Python) replacing the model's; `record`
  // is ignored when it is given, and its units and step are its own.
  std::optional<io::Record> record_data;
  std::string record_units;  // the record's units (must agree with its header, if it has any)
  std::optional<double> record_dt;         // the record's sampling step (model time unit)
  std::string units_given_by = "--units";  // who gives record_units and record_dt, for messages
  std::string dt_given_by = "--record-dt";
  std::optional<double> scale;               // replaces its scale
  std::optional<double> dt;                  // replaces analysis.dt (model time unit)
  bool fixed_base = false;                   // analyse the building without its isolation layer
  std::optional<double> trial_displacement;  // model length; default 0.1 m
  std::optional<model::FreeVibration> free_vibration;  // replaces analysis.free_vibration
  std::int64_t max_steps = kDefaultMaxSteps;           // the most analysis steps (StepGrid)
};

// Where the parts of interest sit among the structure's connections.
struct StructureLayout {
  int isolation = -1;                  // connection of the isolation layer (SDOF: its spring)
  std::vector<int> stories;            // connection of each story, bottom to top
  std::vector<double> story_heights;   // (length), 0 where not given
  std::vector<std::string> dof_names;  // "base", "floor 1", ...; an SDOF's "mass"
};

struct AnalysisSetup {
  structure::Structure structure;
  StructureLayout layout;
  integrators::Excitation excitation;
  integrators::TimeGrid grid;
  io::AppliedRecord record;
  ModelSummary summary;
  double excitation_end = 0.0;  // (time) the record's (or applied forces') end
  double free_vibration = 0.0;  // (time) run after it
  // (time) the window at the end of the run whose mid-range is the residual displacement
  // (response_peaks.h): the structure's longest period, within the free vibration.
  double residual_window = 0.0;
};

// Drift of story `story` (bottom = 0) at output row `row`: its top floor less its bottom floor.
double StoryDrift(const AnalysisSetup& setup, const integrators::RowMatrix& displacement, int row,
                  std::size_t story);
// The same from one row's displacements.
double StoryDrift(const AnalysisSetup& setup, std::span<const double> displacement,
                  std::size_t story);

// Automatic free vibration: kAutomaticFreeVibrationPeriods x the model's longest period.
inline constexpr double kAutomaticFreeVibrationPeriods = 5.0;

// Reads the record `motion` names (its file resolved already), or takes `data` when given (a
// record already in memory), into `acceleration` in the model's `units`, scaled; returns it as
// applied. Throws InputError as io::ReadRecord does, and for units that are not an acceleration.
io::AppliedRecord ApplyRecord(const model::GroundMotionSection& motion,
                              const std::string& units_given_by, const std::string& dt_given_by,
                              const UnitSystem& units, integrators::SampledHistory* acceleration,
                              const io::Record* data = nullptr);

// Throws InputError (naming the file, or "command line") for records that cannot be read or whose
// units or step disagree with what is given, a dt coarser than the record's, or a structure
// without what the analysis needs.
AnalysisSetup PrepareAnalysis(const model::ModelFile& model, const RunOverrides& overrides);

}  // namespace isolab::analysis
