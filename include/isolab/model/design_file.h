// Design files (YAML) for `isolab design`: a building whose bearing types carry their property
// modification factors, the code's target spectrum, the suite of records scaled to it, and the
// checks the code asks. Paths are relative to the design file.
//
//   description: free text
//   model: five_story_lrb_plan.yaml      # the building (one direction or in plan) with its
//                                        # bearings' modification factors (docs/design.md)
//   target:                              # one of:
//     asce7: {sms: 1.5 g, sm1: 0.9 g, tl: 8 s}            # ASCE 7-16 MCE_R (11.4.6 shape)
//     eurocode8: {agr: 0.3 g, ground: B, type: 1, importance: 1.0}   # EN 1998-1 3.2.2.2
//     file: target.csv                   # period_s,sa_g (linear between rows)
//   suite:
//     records: [...]                     # pairs (plan) or records (one direction), as a
//                                        # study's records (study_file.h); or
//     synthetic: {count: 11, seed: 1, duration: 30 s, dt: 0.01 s, tolerance: 0.1}
//                                        # pairs matched to the target (design/matched_pairs.h)
//     period_range: [0.75, 1.25]         # x T_M of the upper bound, x T_M of the lower bound:
//                                        # where the suite's mean spectrum must reach the target
//                                        # (ASCE 7-16 17.3.3; [0.2, 2] for Eurocode 8: EN 1998-1
//                                        # 3.2.3.1.2(4)c with T_1 = T_M, at most 4 s)
//     orientations: [0, 90]              # in plan: each pair runs at each angle (degrees from
//                                        # x to H1, added to the pair's own angle): H1 along x,
//                                        # then along y, by default; [0] in one direction
//   r_i: 2.0                             # ASCE 7-16 only: R_I of 17.5.4.2 (3/8 R, in [1, 2]),
//                                        # for the superstructure's shear V_s
//   gamma_x: 1.2                         # Eurocode 8 only: the reliability factor on the
//                                        # isolators' displacements (EN 1998-1 10.3(2))
//   eccentricity: 0.05                   # accidental, of the footprint (plan models; 0: none)
//   drift_limit: 0.015                   # story drift ratio (ASCE 7-16 17.6.4.4)
//   output: {directory: design}          # relative to the working directory
//
// Every error is an InputError "file:line:col: key path: what (allowed)".
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "isolab/model/model_file.h"
#include "isolab/model/study_file.h"
#include "isolab/spectra/design_spectrum.h"

namespace isolab::model {

// The fewest records (pairs in plan) a response-history design takes: EN 1998-1 4.3.3.4.3's
// three (ASCE 7-16 17.3.2 asks for seven, the number from which both take the suite's mean).
inline constexpr int kMinimumDesignRecords = 3;

// The code whose rules a design follows: its target's. A tabulated target is designed by ASCE
// 7-16's rules (its spectrum is the user's, its procedure chapter 17's).
enum class DesignCode { kAsce7_16, kEn1998_1 };
// "ASCE 7-16", "EN 1998-1:2004"
std::string_view CodeName(DesignCode code);
// gamma_x's recommended value (EN 1998-1 10.3(2); a nationally determined parameter).
inline constexpr double kRecommendedReliabilityFactor = 1.2;

// The most orientations a pair runs at: each multiplies the design's runs.
inline constexpr std::size_t kMaxOrientations = 8;

// Pairs generated and matched to the target, so a design runs without a record database.
struct SyntheticSuite {
  int count = 11;
  std::uint64_t seed = 1;
  double duration = 30.0;  // s
  double dt = 0.01;        // s
  double tolerance = 0.1;  // largest |RotD100 / target - 1| over the matched range
};

struct DesignFile {
  std::string path;
  std::string description;
  std::string model_path;  // as found (relative to the working directory or absolute)
  ModelFile model;
  spectra::TargetSpectrum target;
  DesignCode code = DesignCode::kAsce7_16;
  // The factor on the isolators' displacements in the design values: gamma_x for Eurocode 8, 1
  // for ASCE 7-16 (whose margin is the 0.8 ELF floor instead).
  double gamma_x = 1.0;
  double r_i = 0.0;  // ASCE 7-16 17.5.4.2's R_I; 0: not given (V_s not computed)
  std::vector<StudyRecord> records;  // empty when synthetic
  std::optional<SyntheticSuite> synthetic;
  double period_range[2] = {0.75, 1.25};  // factors on T_M upper, T_M lower (code default)
  std::vector<double> orientations = {0.0};  // degrees; {0, 90} in plan unless given
  double eccentricity = 0.05;             // plan; 0 in one direction
  double drift_limit = 0.015;
  // The allowable shear strain of rubber bearings (a ratio, 2.5 for 250 %): a high-damping rubber
  // bearing's displacement capacity is its rubber thickness times it. 0: not given (not checked).
  double shear_strain_limit = 0.0;
  std::string output_directory;  // empty: not given
  std::string suite_key;         // "design.yaml:7:3: suite", for messages on the suite
  std::string target_key;        // "design.yaml:3:1: target", for messages on the target
};

// Throws InputError for an unreadable file, bad YAML, unknown or missing keys, a model that does
// not load or has no modification factors, a target out of range, a suite that is neither
// records nor synthetic (or both), fewer than kMinimumDesignRecords, a period range not
// 0 < lower <= 1 <= upper, orientations that are not distinct angles in [0, 360) (at most
// kMaxOrientations) or other than [0] in one direction, a record named as another turned by one
// (its name + "_at90": they would share run files), r_i on a Eurocode 8 target or outside
// [1, 2], gamma_x on a target other than Eurocode 8's or outside [1, 2], an
// eccentricity given for a one-direction model, a drift limit not in
// (0, 1), a target given on a suite record (the design scales the suite itself).
DesignFile LoadDesignFile(const std::string& path);

}  // namespace isolab::model
