// Plan model files (YAML, issue #15): a base-isolated building in plan under two horizontal
// record components. A model file is a plan model when it has a `plan:` section; every other
// model file is a one-direction model (model_file.h), the default. Units, numbers with their own
// unit, `analysis` and `output` as there. Plan coordinates (x, y) are in the model's length
// unit, from any origin; the footprint is the rectangle every centre and isolator must lie in.
//
//   plan:
//     footprint: [[0, 0], [20, 12]]              # two opposite corners
//     base: {mass: 100 t, centre_of_mass: [10, 6], radius_of_gyration: 6.7}
//     stories:                                    # bottom to top; or {count: 5, ...} for equal
//       - name: s1                                # stories (default: story1, story2, ...)
//         mass: 100 t
//         centre_of_mass: [10.3, 6]               # default: the footprint's centre
//         rotational_inertia: 4000 t*m^2          # or radius_of_gyration; default: a uniform
//                                                 # slab over the footprint, m (a^2 + b^2) / 12
//         height: 3                               # for reporting
//         centre_of_stiffness: [10, 6]            # default: the footprint's centre
//         stiffness: {x: 120 kN/mm, y: 120 kN/mm, torsion: 4.3e9 kN*mm}  # linear, or
//         x: [components], y: [...], torsion: [...]                      # any laws (torque
//                                                 # against twist for torsion, rad)
//     damping: {type: rayleigh, periods: [0.6, 0.1], ratios: [0.05, 0.05]}   # or none (default)
//     isolators:
//       - name: sw
//         position: [0, 0]
//         coupling: coupled                       # or uncoupled: each law along x and along y
//         components: [{type: bhm2, k0: 2, k1: 0.25, uy: 20}]
//   excitation:
//     ground_motion:
//       h1: {file: rsn6_h1.at2, units: g, scale: 1.0, dt: 0.01}   # units and dt as 1-D
//       h2: {file: rsn6_h2.at2}
//       angle: 0              # degrees from the x axis to H1 (H2 at angle + 90); default 0
//
// Every error is an InputError "file:line:col: key path: what (what was allowed)".
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "isolab/core/errors.h"
#include "isolab/model/model_file.h"
#include "isolab/structure/plan_building.h"

namespace isolab::model {

struct PlanGroundMotion {
  GroundMotionSection h1;
  std::optional<GroundMotionSection> h2;  // one component alone is allowed
  double angle = 0.0;                     // degrees
  SourceLocation h2_location;             // where h2 is given, for a pair that does not match
};

struct PlanModelFile {
  std::string path;
  std::string text;
  std::string description;
  UnitSystem units{"kN", "mm", "s"};
  structure::PlanBuilding building;
  // The isolators' laws along x as one-direction assemblies, summed: the isolation layer's
  // push-over along an axis (for the model summary's isolated period).
  hysteresis::ParallelAssembly isolation_along_x;
  std::optional<PlanGroundMotion> ground_motion;
  AnalysisSection analysis;
  std::string output_file;
};

// True when the file is a YAML map with a top-level `plan` key; false for anything else
// (LoadModelFile reports what is wrong with it). Reads a block mapping's keys from the starts of
// its lines without parsing the file.
bool IsPlanModelFile(const std::string& path);

// Throws InputError for an unreadable file, bad YAML, unknown or missing keys, wrong types or
// units, an isolator or centre outside the footprint, a mass or rotational inertia <= 0, laws
// that break their rules or have no coupled form.
PlanModelFile LoadPlanModelFile(const std::string& path);

// The index of the first of `laws` without a coupled bidirectional form; laws.size() if none.
std::size_t FirstWithoutCoupledForm(const hysteresis::ParallelAssembly& laws);
// "degrading_bhm2 has no coupled bidirectional form", of laws[c].
std::string NoCoupledForm(const hysteresis::ParallelAssembly& laws, std::size_t c);

// Every isolator of `model` with `laws` as its coupled law (a study's isolation variant), and
// isolation_along_x to match. Throws std::invalid_argument (NoCoupledForm) for a law without a
// coupled form.
void ReplaceIsolation(PlanModelFile* model, const hysteresis::ParallelAssembly& laws);

}  // namespace isolab::model
