// Study files (YAML) for `isolab compare`: one building, several isolator variants, a suite of
// records at several scale factors. Paths are relative to the study file.
//
//   description: free text
//   building: ../buildings/five_story_table9.yaml   # a model file with a structure section;
//                                                   # its units are the study's
//   variants:                                       # at least one; names are unique
//     - {name: thm1, isolation: {file: ../paper/table9_thm1_system.yaml}}
//     - name: bilinear                              # components in the building's units
//       isolation: {components: [{name: b, type: bhm2, ke: 8, kh: 0.8, fs: 18}]}
//     - {name: as_built}                            # the building's own isolation
//     - {name: other, model: other_building.yaml}   # a whole model file instead of the building
//     - {name: fixed, fixed_base: true}             # the building without isolation
//   reference: thm1                                 # ratios are to this variant; default: first
//   records:                                        # files or globs (* ? [..] in the file
//     - ../../ground_motions/*.at2                  # name), each glob sorted by name; units
//     - {file: extra/rec.txt, units: gal, dt: 0.01, scale: 1.2}   # and step from each file's
//                                                   # header, else from its entry (never the
//                                                   # building's ground_motion); an entry's
//                                                   # scale multiplies every study scale;
//     - {file: r.at2, scale: {pga: 0.4 g}}          # or a target (model_file.h), whose factor
//                                                   # each study scale multiplies
//   scales: [0.5, 1.0, 1.5]                         # replace the building's ground_motion.scale
//   output: {directory: results}                    # per-run HDF5 and summary; relative to the
//                                                   # working directory, like a model's output
//   free_vibration: auto                            # after each record (or a time, 0 for none);
//                                                   # default: each model's analysis section
//
// The building's analysis section (dt, duration, integrator) applies to every run; a `model`
// variant brings its own. The building may be any model with a structure (one direction or in
// plan); every variant's structure moves in the building's directions (a study's records and
// quantities are the same for all). An `isolation` variant of a building in plan puts every
// isolator on those laws, as coupled laws. A record entry may also be a pair, for buildings in
// plan, written as a model's excitation.ground_motion is:
//   records:
//     - {h1: {file: a_h1.at2, scale: 1.0}, h2: {file: a_h2.at2}, angle: 30, name: a_at30}
// (units, dt and scale per component as there, a target on h1 only; angle in degrees from x to
// H1, default 0; name default: h1's file stem). Both files are read when the study loads: a pair
// whose steps or lengths differ is refused then, as is a pair in a study of a building in one
// direction. Each run is what `isolab run` does on the variant's model with the record in its
// excitation, each component's scale times the study's.
//
// Every error is an InputError "file:line:col: key path: what (allowed)".
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "isolab/core/units.h"
#include "isolab/model/model_file.h"

namespace isolab::model {

struct StudyVariant {
  std::string name;
  ModelFile model;  // what runs: the building with this variant's isolation, or its own model
  bool fixed_base = false;
};

struct StudyRecord {
  std::string name;   // the file's stem (a pair's name), unique within a study
  std::string entry;  // "study.yaml:12:5: records[2]", for messages about what it gives
  // H1 (and H2): files as found (relative to the working directory or absolute), units given by
  // the entry (empty: from the file's header), dt in the building's time unit (0: from the file),
  // scale multiplying the study's scales.
  std::vector<GroundMotionSection> components;
  double angle = 0.0;  // degrees from x to H1
};

// What a study writes per run beside its summary: nothing, each run's summary (peaks, final
// energies, attributes: `isolab run --summary-only`'s file) or every history as well.
enum class RunFiles { kNone, kSummary, kFull };

// "none", "summary" or "full"; InputError({key}, ...) naming the three otherwise.
RunFiles ParseRunFiles(const std::string& text, const std::string& key);
const char* RunFilesName(RunFiles runs);

struct StudyFile {
  std::string path;
  std::string description;
  std::string building_path;
  UnitSystem units{"kN", "mm", "s"};  // the building's: summary quantities are in these
  int directions = 1;      // horizontal directions of the building's structure: 1, or 2 in plan
  bool rotations = false;  // its levels rotate (a building in plan)
  std::vector<StudyVariant> variants;
  std::size_t reference = 0;  // index into variants
  std::vector<StudyRecord> records;
  std::vector<double> scales;
  std::string output_directory;                 // empty: not given
  RunFiles runs = RunFiles::kFull;              // output.runs
  std::optional<FreeVibration> free_vibration;  // (the building's time unit); empty: the models'
  // Where free_vibration was given, for messages: "study.yaml:9:17: free_vibration", an option.
  std::string free_vibration_given_by = "free_vibration";
};

// Gives every run of `study` the free vibration `free` after its record; `given_by` names where
// it was given (the study's key at its line, an option, an argument). A variant whose model fixes
// the run's duration (analysis.duration) cannot take one: InputError({given_by}, ...) before any
// run, rather than the same failure in each.
void SetStudyFreeVibration(StudyFile& study, const FreeVibration& free,
                           const std::string& given_by);

// Throws InputError for an unreadable file, bad YAML, unknown or missing keys, wrong types, a
// variant or building model that does not load, a glob that matches nothing, a missing record
// file, two records with the same name, or an unknown reference. Records are only opened when
// a run reads them, so a record that exists but cannot be read fails its runs, not the study.
StudyFile LoadStudyFile(const std::string& path);

}  // namespace isolab::model
