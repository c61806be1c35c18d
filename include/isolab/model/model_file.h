// Model files (YAML): one description for every kind of model isolab analyses. Every number is in
// the declared units; any quantity may also be a string with its own unit ("0.2 kN/mm", "250 t").
// Sections:
//
//   description: free text
//   units: {force: kN, length: mm, time: s}          # required
//   isolation:                                       # the isolation layer, or an SDOF's spring
//     name: lrb                                      # optional, with count: the bearing's name
//     count: 16                                      # optional: the layer is 16 such bearings in
//                                                    # parallel, isolators lrb_1 ... lrb_16
//     components:                                    # a parallel assembly, one entry per law
//       - {name: c1, type: thm1, k0: 1.0, k1: 0.2, k2: 0.45, uy: 20, uyh: 120}
//       - {name: c2, type: thm2, ke: "1 kN/mm", kh1: 0.2, kh2: 0.05, fs: 16, uc: 120}
//     modification: {c1: {k0: {testing: [0.9, 1.1], ageing: [1, 1.2], specification: [0.9,
//                    1.1]}}}                         # property_modification.h, bounds.h
//     identified_range: {displacement: 108.5, velocity: 338.7, cycles: 69.5, data: [ica50]}
//                                                    # optional, written by isolab fit and
//                                                    # diagnose: the range of the data the laws
//                                                    # were identified on (peak |u|, peak |v|,
//                                                    # cycles, the tests' names); a run beyond it
//                                                    # warns. The deformation of one bearing,
//                                                    # which in one direction is the layer's too.
//                                                    # Through `file:` the included file's range.
//   structure:                                       # one direction (structure_section.cpp)
//     type: sdof                                     # mass, damping: {ratio | coefficient}
//     type: shear_building                           # stories (list, uniform, or none: a slab
//                                                    # on its isolators), base_mass,
//                                                    # damping: {type: rayleigh|modal|none, ...}
//   plan:                                            # or a building in plan (plan_section.cpp):
//     footprint, base, stories, damping, isolators   # floors in plan, isolators at positions
//   excitation:
//     ground_motion: {file: rec.at2, units: g, scale: 1.0, dt: 0.01}      # one component, or
//       scale: {pga: 0.4 g}                          # or scaled to a target (ScaleTarget): PGA,
//       scale: {sa: 0.6 g, period: 2.5 s, damping: 0.05}   # or Sa at a period (damping 0.05
//                                                    # if not given); in a pair, given on h1 only,
//                                                    # and its one factor scales h1, h2 and v
//     ground_motion: {h1: {file: ...}, h2: {file: ...}, angle: 0}         # a pair (plan models)
//     ground_motion: {h1: {...}, h2: {...}, v: {file: ...}}               # with a vertical one
//     forces: [{dof: 0, dt: 0.1, values: [...]}]
//   axial_load: {vertical: true, overturning: true, base_height: 600}  # pendulums' N(t)
//   analysis: {dt: 0.005, duration: 30, integrator: newmark,   # or ida
//              free_vibration: auto,                         # or a time, 0 for none
//              newmark: {beta: 0.25, gamma: 0.5, newton: full, ...},
//              ida: {rtol: 1e-6, atol: 1e-9, max_step: 0.01, max_steps: 100000}}
//   output: {file: results.h5, every: 1, quantities: [...], levels: [...], summary_only: false}
//                                                    # what is recorded: output_selection.h
//   cyclic: {amplitude: 200, period: 1, cycles: 2, steps_per_cycle: 400}  # for `isolab cyclic`
//   uncertainty:                                     # a fitted model's (ParameterUncertainty)
//     parameters: [{name: isolation.c1.k0, value: 13.2, log: true}, ...]
//     covariance: [[...], ...]                       # of the coordinates, one row per parameter
//     model_form: [{fitted_on: [ica50], values: [...]}, ...]  # fits to subsets of the motions
//     priors: [{name: isolation.c2.k2, value: 0.8, sigma: 0.2, source: "design data"}, ...]
//
// A model with `structure` or `plan` can be run in time (build_structure.h lays it out); a model
// with only `isolation` is a bearing, for `cyclic` and `fit`. Every error is an InputError
// "file:line:col: key path: what (what was allowed)".
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "isolab/core/errors.h"
#include "isolab/core/units.h"
#include "isolab/hysteresis/cyclic_test.h"
#include "isolab/hysteresis/parallel_assembly.h"
#include "isolab/identification/cyclic_data.h"
#include "isolab/integrators/ida.h"
#include "isolab/integrators/newmark.h"
#include "isolab/model/output_selection.h"
#include "isolab/model/property_modification.h"
#include "isolab/structure/plan_building.h"
#include "isolab/structure/shear_building.h"

namespace isolab::model {

struct StructureSection {
  enum class Kind { kSdof, kShearBuilding, kPlanBuilding };
  Kind kind = Kind::kSdof;
  double mass = 0.0;                    // SDOF
  std::optional<double> damping_ratio;  // SDOF, on the initial stiffness
  double damping_coefficient = 0.0;     // SDOF, when no ratio is given
  structure::ShearBuilding building;    // shear building (its isolation is the model's)
  structure::PlanBuilding plan;         // building in plan, with its isolators
  hysteresis::Vec2 footprint_size;      // plan: the footprint's extents along x and y (length)
};

// What a record is scaled to, as design codes ask (`scale: {pga: 0.4 g}` or
// `scale: {sa: 0.6 g, period: 2.5 s, damping: 0.05}`): the factor is the one that makes the
// record's peak ground acceleration, or its pseudo-spectral acceleration at `period` and
// `damping` (spectra/elastic_spectrum.h), equal `value`. Sa is linear in the record, so the
// factor is value / Sa of the record as read.
struct ScaleTarget {
  enum class Measure { kPga, kSa };
  Measure measure = Measure::kPga;
  double value = 0.0;     // the target acceleration (model length/time^2), > 0
  double period = 0.0;    // kSa: the oscillator's period (model time), > 0
  double damping = 0.05;  // kSa: its damping ratio, in [0, 1)
  std::string text;       // for reports, in the units given: "PGA 0.4 g", "Sa(2.5 s, 5 %) 0.6 g"
};

struct GroundMotionSection {
  std::string file;   // resolved against the model file's folder
  std::string units;  // empty: from the record's header
  double scale = 1.0;
  // When given, the scale is computed from it (analysis/problem.h) and `scale` is not used. Only
  // the record's first component (h1) carries one: its factor scales every component.
  std::optional<ScaleTarget> target;
  double dt = 0.0;          // single-column records only
  std::string key;          // "excitation.ground_motion" (.h1, .h2), for messages about it
  SourceLocation location;  // where it is given
};

struct ForceSection {
  int dof = 0;
  double dt = 0.0;
  std::vector<double> values;
};

// An angle of a record's H1 from the x axis is a direction: beyond a turn either way it is a typo
// (and at 1e308 degrees its cosine is not a number).
inline constexpr double kMaxRecordAngle = 360.0;
// What is wrong with `angle` as a record's angle ("400 degrees (must be in [-360, 360])"), or
// empty where it is within kMaxRecordAngle: the model's key and --angle say the same.
std::string RecordAngleProblem(double angle);

struct ExcitationSection {
  // The record's horizontal components: H1, and H2 at angle + 90 degrees when there is a pair.
  std::vector<GroundMotionSection> ground_motion;
  // Its vertical component (upwards), `v` beside h1 and h2; it acts only through the axial loads
  // of friction pendulum bearings (axial_load.vertical).
  std::optional<GroundMotionSection> vertical;
  double angle = 0.0;  // degrees from the x axis to H1
  std::vector<ForceSection> forces;
};

// The axial loads N(t) of friction pendulum bearings (structure/axial_load.h): given at all, every
// pendulum bearing's laws are scaled by N / W, N its static share of the weight from rigid-slab
// statics of the bearing layout (a one-direction model: the whole weight on its layer), plus what
// is asked here. Absent: every law keeps its own W, as before.
struct AxialLoadSection {
  bool vertical = false;     // N_0 (1 + a_v / g) with the record's vertical component
  bool overturning = false;  // the story inertial forces' moments (a building in plan)
  double base_height = 0.0;  // the base level's mass above the bearing plane (length), >= 0
  SourceLocation location;   // where `axial_load` is given
};

// How long the structure vibrates freely after the excitation ends, so that the residual
// displacement is read where the structure comes to rest, not while it still swings.
struct FreeVibration {
  bool automatic = true;  // five times the structure's longest period (problem.h)
  double duration = 0.0;  // (time) when not automatic; 0: none
};

struct AnalysisSection {
  enum class Integrator { kNewmark, kIda };
  double dt = 0.0;        // 0: the record's step (IDA: its output step)
  double duration = 0.0;  // 0: the excitation's duration, then the free vibration
  FreeVibration free_vibration;
  Integrator integrator = Integrator::kNewmark;
  integrators::NewmarkOptions newmark;
  integrators::IdaOptions ida;
};

// A fitted model's parameters and their uncertainty (`uncertainty:`, written by
// `isolab fit --building`), which a prediction samples for a band: the names as
// analysis/building_parameters.h gives them, the values in the model's units, and the covariance
// of their coordinates (ln value where `log`, else the value).
// Model form (`model_form:`, written by `isolab fit --building --model-form`): the same
// parameters fitted to subsets of the motions (each motion held out in turn), whose spread about
// `values` (the fit to every motion) is what the data cannot tell apart; prediction bands add it
// to the covariance (analysis/parameter_draws.h).
struct ModelFormFit {
  std::vector<std::string> fitted_on;  // the motions the fit saw
  std::vector<double> values;          // one per parameter, in the model's units
};

// A parameter the data could not fix, given instead from what engineers know (`priors:`, from a
// building fit specification's priors): its value (model units, > 0), its standard deviation in
// ln p, and where it comes from (design data, a preset, a manufacturer's test). A band draws it
// log-normally about the model's own value, beside the fitted parameters.
struct ParameterPrior {
  std::string name;
  double value = 0.0;
  double sigma = 0.0;
  std::string source;
};

struct ParameterUncertainty {
  std::vector<std::string> names;
  std::vector<double> values;
  std::vector<bool> log;
  Eigen::MatrixXd covariance;
  std::vector<ModelFormFit> model_form;  // empty: the parameters' uncertainty alone
  std::vector<ParameterPrior> priors;    // not fitted: given from outside the data
};

struct ModelFile {
  std::string path;
  // The files its isolation section was read from (isolation: {file: ...}, and theirs in turn).
  std::vector<std::string> included_files;
  std::string text;  // the YAML as read, stored with results
  std::string description;
  UnitSystem units{"kN", "mm", "s"};
  // A one-direction model's isolation layer (or an SDOF's spring); empty when it has none, and in
  // a plan model, whose isolators carry their own laws.
  hysteresis::ParallelAssembly isolation;
  // The one-direction layer as `isolation`'s type used `count` times in parallel (isolation.count,
  // isolation.name): isolators "<name>_1" ... "<name>_<count>" (IsolationBearings). Without a
  // count, the layer is the one isolator "isolation" (an SDOF's "restoring").
  std::optional<int> isolation_count;
  std::string isolation_name = "bearing";
  // Property modification factors per bearing type (isolation.modification,
  // plan.isolators[i].modification): what bounds.h turns into upper- and lower-bound models. A
  // run uses the nominal properties.
  std::vector<BearingModification> modifications;
  // The range of the data the isolation's laws were identified on (isolation.identified_range,
  // or that of the file it names), in the model's units: a run beyond it warns
  // (analysis::IdentifiedRangeWarning). Absent for laws given without one, and for a plan
  // model's own isolators, whose laws are given in place.
  std::optional<identification::IdentifiedRange> identified_range;
  std::optional<StructureSection> structure;
  ExcitationSection excitation;
  std::optional<AxialLoadSection> axial_load;
  AnalysisSection analysis;
  std::string output_file;  // empty: not given
  OutputSelection output;
  std::optional<hysteresis::CyclicProtocol> cyclic;
  std::optional<ParameterUncertainty> uncertainty;
};

// The names of a one-direction layer's bearings: "<name>_1" ... "<name>_<count>"; empty without a
// count (the layer is then one isolator).
std::vector<std::string> IsolationBearings(const ModelFile& model);

// The record files the model's excitation names (its horizontal components and its vertical one),
// resolved against the model's folder: inputs no command may write its results over.
std::vector<std::string> RecordFiles(const ModelFile& model);

// Throws InputError for an unreadable file, bad YAML, unknown or missing keys, wrong types or
// units, and parameters that break a law's or a section's rules.
ModelFile LoadModelFile(const std::string& path);

// The same from a model's text (a model built in memory, e.g. from Python): `path` names it in
// messages, and files it names relative to themselves are found beside `path`.
ModelFile LoadModelText(const std::string& text, const std::string& path);

// The index of the first of `laws` without a coupled bidirectional form; laws.size() if none.
std::size_t FirstWithoutCoupledForm(const hysteresis::ParallelAssembly& laws);
// "degrading_bhm2 has no coupled bidirectional form", of laws[c].
std::string NoCoupledForm(const hysteresis::ParallelAssembly& laws, std::size_t c);

// The model with `laws` as its isolation (a study's isolation variant): a one-direction model's
// isolation layer, or every isolator of a plan model as coupled laws (or, `uncoupled`, each law
// along x and y independently), identified on `range` (none: the laws carry no range, and the
// replaced laws' range goes with them). Throws std::invalid_argument (NoCoupledForm) for a plan
// model, coupled, and a law without a coupled form.
void ReplaceIsolation(ModelFile* model, const hysteresis::ParallelAssembly& laws,
                      std::optional<identification::IdentifiedRange> range = std::nullopt,
                      bool uncoupled = false);

}  // namespace isolab::model
