// Model files (YAML). Every number is in the declared units; any quantity may also be a string
// with its own unit ("0.2 kN/mm", "250 t"). Sections:
//
//   description: free text
//   units: {force: kN, length: mm, time: s}          # required
//   isolation:                                       # the isolation layer, or an SDOF's spring
//     components:                                    # a parallel assembly, one entry per law
//       - {name: c1, type: thm1, k0: 1.0, k1: 0.2, k2: 0.45, uy: 20, uyh: 120}
//       - {name: c2, type: thm2, ke: "1 kN/mm", kh1: 0.2, kh2: 0.05, fs: 16, uc: 120}
//   structure:                                       # for `isolab run`
//     type: sdof                                     # mass, damping: {ratio | coefficient}
//     type: shear_building                           # stories (list or uniform), base_mass,
//                                                    # damping: {type: rayleigh|modal|none, ...}
//   excitation:
//     ground_motion: {file: rec.at2, units: g, scale: 1.0, dt: 0.01}
//     forces: [{dof: 0, dt: 0.1, values: [...]}]
//   analysis: {dt: 0.005, duration: 30, integrator: newmark,   # or ida
//              free_vibration: auto,                         # or a time, 0 for none
//              newmark: {beta: 0.25, gamma: 0.5, newton: full, ...},
//              ida: {rtol: 1e-6, atol: 1e-9, max_step: 0.01, max_steps: 100000}}
//   output: {file: results.h5, every: 1, quantities: [...], levels: [...], summary_only: false}
//                                                    # what is recorded: output_selection.h
//   cyclic: {amplitude: 200, period: 1, cycles: 2, steps_per_cycle: 400}  # for `isolab cyclic`
//
// Every error is an InputError "file:line:col: key path: what (what was allowed)".
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "isolab/core/units.h"
#include "isolab/hysteresis/cyclic_test.h"
#include "isolab/hysteresis/parallel_assembly.h"
#include "isolab/integrators/ida.h"
#include "isolab/integrators/newmark.h"
#include "isolab/model/output_selection.h"
#include "isolab/structure/shear_building.h"

namespace isolab::model {

struct StructureSection {
  enum class Kind { kSdof, kShearBuilding };
  Kind kind = Kind::kSdof;
  double mass = 0.0;                    // SDOF
  std::optional<double> damping_ratio;  // SDOF, on the initial stiffness
  double damping_coefficient = 0.0;     // SDOF, when no ratio is given
  structure::ShearBuilding building;    // shear building (isolation filled in if present)
};

struct GroundMotionSection {
  std::string file;   // resolved against the model file's folder
  std::string units;  // empty: from the record's header
  double scale = 1.0;
  double dt = 0.0;  // single-column records only
};

struct ForceSection {
  int dof = 0;
  double dt = 0.0;
  std::vector<double> values;
};

struct ExcitationSection {
  std::optional<GroundMotionSection> ground_motion;
  std::vector<ForceSection> forces;
};

// How long the structure vibrates freely after the excitation ends, so that the residual
// displacement is read where the structure comes to rest, not while it still swings.
struct FreeVibration {
  bool automatic = true;  // five times the structure's longest period (analysis_setup.h)
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

struct ModelFile {
  std::string path;
  // The files its isolation section was read from (isolation: {file: ...}, and theirs in turn).
  std::vector<std::string> included_files;
  std::string text;  // the YAML as read, stored with results
  std::string description;
  UnitSystem units{"kN", "mm", "s"};
  hysteresis::ParallelAssembly isolation;  // empty when the file has no isolation section
  std::optional<StructureSection> structure;
  ExcitationSection excitation;
  AnalysisSection analysis;
  std::string output_file;  // empty: not given
  OutputSelection output;
  std::optional<hysteresis::CyclicProtocol> cyclic;
};

// Throws InputError for an unreadable file, bad YAML, unknown or missing keys, wrong types or
// units, and parameters that break a law's or a section's rules.
ModelFile LoadModelFile(const std::string& path);

// The same from a model's text (a model built in memory, e.g. from Python): `path` names it in
// messages, and files it names relative to themselves are found beside `path`.
ModelFile LoadModelText(const std::string& text, const std::string& path);

}  // namespace isolab::model
