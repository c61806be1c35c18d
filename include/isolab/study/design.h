// The design of an isolated building by response-history analysis, as ASCE 7-16 chapter 17 asks
// (Eurocode 8 part 1 section 10 asks the same sequence), in one pipeline:
//
//  1. the nominal, upper-bound and lower-bound models from the bearings' property modification
//     factors (model/bounds.h), written as YAML beside the results;
//  2. the equivalent lateral force procedure on each (design/equivalent_lateral_force.h): D_M,
//     T_M, beta_M, k_M and V_b, and for a building in plan D_TM by Eq. 17.5-3;
//  3. the suite: the design file's records or pairs, or synthetic pairs matched to the target
//     (design/matched_pairs.h), each scaled by its own factor so that the suite's mean spectrum
//     (the pairs' RotD100, a single record's 5 % spectrum) is nowhere below the target from
//     period_range[0] x T_M(upper) to period_range[1] x T_M(lower) (spectra/suite_scaling.h);
//  4. every bound x accidental-eccentricity case (design/accidental_torsion.h: none, and the
//     four shifted cases of a building in plan) x record run through the study scheduler on
//     local worker processes, each as `isolab run` runs it;
//  5. the design values: per bound and record the envelope over the eccentricity cases and the
//     record's orientations (a pair runs H1 along x, then along y: DesignFile::orientations), then
//     the mean over the suite when it has at least kMinimumRecordsForMean records (ASCE
//     7-16 17.6.3.2 allows it), the maximum otherwise; the governing bound per quantity; and the
//     code's design values and checks (design_checks.h: ASCE 7-16's ELF floors, or EN 1998-1's
//     gamma_x; drift, displacement capacities, uplift).
// A Eurocode 8 design scales its suite by EN 1998-1's rule instead of ASCE's, each horizontal
// component a time history of the suite: the mean of the components' 5 % spectra nowhere below
// 90 % of the target over the range (3.2.3.1.2(4)c, its range 0.2 T_1 to 2 T_1 with T_1 the
// isolated period, cut at 4 s where 3.2.2.2's spectrum ends), and the components' mean peak
// ground acceleration not below the target's a_g S (3.2.3.1.2(4)b).
#pragma once

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "isolab/design/accidental_torsion.h"
#include "isolab/design/equivalent_lateral_force.h"
#include "isolab/model/bounds.h"
#include "isolab/model/design_file.h"
#include "isolab/model/study_file.h"
#include "isolab/spectra/suite_scaling.h"
#include "isolab/study/bearing_capacity.h"
#include "isolab/study/design_checks.h"
#include "isolab/study/design_folder.h"
#include "isolab/study/job_result.h"
#include "isolab/study/quantities.h"
#include "isolab/study/scheduler.h"

namespace isolab::study {

inline constexpr std::size_t kMinimumRecordsForMean = 7;
inline constexpr double kElfDisplacementFloor = 0.8;  // of D_TM (ELF)
inline constexpr double kElfShearFloor = 0.9;         // of V_b (ELF)
// EN 1998-1 3.2.3.1.2(4)c: the suite's mean spectrum not below 90 % of the target.
inline constexpr double kEurocode8SuiteFraction = 0.9;

struct DesignBound {
  std::string bound;       // "nominal", "upper", "lower"
  std::string model_file;  // the bound's model, written in the output folder
  // Its bearings as OpenSees elements (model/opensees_export.h), written beside model_file; empty
  // for every bound when one bound's cannot be (DesignOutcome::opensees_refused says why).
  std::string opensees_file;
  std::string opensees_text;
  // Per eccentricity case (DesignOutcome::eccentricities), the model its runs ran, written in the
  // output folder: model_file for "none", the bound with its centres of mass shifted otherwise.
  std::vector<std::string> case_model_files;
  model::ModelFile model;
  design::ElfResult elf;
  double damping_coefficient = 0.0;  // B_M of the ELF result (1 / eta for Eurocode 8)
  // D_TM of ASCE 7-16 Eq. 17.5-3 (not below 1.15 D_M) in plan; 1.15 D_M in one direction, where
  // the model has no plan to twist in.
  double elf_total_displacement = 0.0;
  // Each isolator's effective properties at D_M (ELF), in layout order (bearing_weights names
  // them): what another program's linear link takes.
  std::vector<design::EffectiveProperties> bearings;
};

struct DesignRecord {
  std::string name;
  std::vector<std::string> files;           // H1 (and H2)
  double shape_factor = 1.0, factor = 1.0;  // spectra/suite_scaling.h's s_i and f_i
  double misfit = -1.0;  // a synthetic pair's max |RotD100 / target - 1| as matched; -1: given
  // Unscaled at display_periods (g): a pair's RotD100 (ASCE 7-16), or the mean of its components'
  // 5 % spectra (EN 1998-1); one record's 5 % Sa.
  std::vector<double> spectrum;
};

// Per bound: each design quantity's value over the suite (model units; drift ratio in %).
enum class DesignQuantity {
  kDisplacement,          // D_M: the base's centre of mass, no eccentricity
  kTotalDisplacement,     // D_TM: the worst isolator, envelope over the eccentricity cases
  kBaseShear,             // V_b
  kIsolatorForce,         // the most loaded isolator's peak force
  kStoryDriftRatio,       // %
  kFloorAcceleration,     // g
  kResidualDisplacement,  // the isolator farthest from zero at rest
};
inline constexpr std::size_t kDesignQuantityCount = 7;

// Where a quantity's value is in a bound's array of values.
inline std::size_t IndexOf(DesignQuantity q) { return static_cast<std::size_t>(q); }

struct DesignQuantityInfo {
  DesignQuantity quantity;
  std::string_view key;    // CSV column
  std::string_view label;  // report row
};
std::span<const DesignQuantityInfo> DesignQuantities();
// The study quantity (quantities.h) a design quantity is read from, and so its unit.
Quantity SourceOf(DesignQuantity quantity);

struct DesignStatistic {
  // The envelope over the eccentricity cases and orientations, per record: the largest, or for a
  // least axial load the least.
  std::vector<double> per_record;
  double mean = 0.0;
  double max = 0.0;    // the most unfavourable record's: the largest (a least axial load: least)
  double value = 0.0;  // mean or max, as the suite's size allows
};

// A part's design values (a story's drift ratio and shear, a floor's acceleration, a bearing's
// displacement and axial loads: PartQuantity), per bound, and the bound that governs: the
// largest value (for a least axial load, the least).
struct DesignPartValue {
  PartQuantity quantity = PartQuantity::kStoryDriftRatio;
  std::string part;
  std::vector<DesignStatistic> bounds;
  std::size_t governing = 0;
};

// An isolator's displacement capacity (bearing_capacity.h), nullopt when its laws give none.
struct IsolatorCapacity {
  std::string isolator;
  std::optional<BearingCapacity> capacity;
};

// A warning the runs gave (implausible input: model_summary.h), once per bound with the number of
// its runs that gave it.
struct DesignWarning {
  std::size_t bound = 0;
  std::string text;
  std::size_t runs = 0;
};

struct DesignOutcome {
  std::vector<DesignBound> bounds;                       // nominal, upper, lower
  std::vector<design::EccentricityCase> eccentricities;  // "none" first
  std::vector<model::BoundProperty> modified;  // each modified property, its lambdas and values
  // Why the bounds' bearings were not exported ("the upper bound: ..."); empty if they were.
  std::string opensees_refused;
  std::vector<DesignRecord> records;
  // The angles (degrees from x to H1) each record runs at: model::DesignFile::orientations.
  std::vector<double> orientations = {0.0};
  spectra::SuiteScaling scaling;
  // The scaling periods and more, from 0.05 s to twice the range's top, for the report; the
  // target there (continued past a code's or a table's last period at constant displacement).
  std::vector<double> display_periods, display_target;
  double period_range[2] = {0.0, 0.0};  // s
  // The code's suite rule: the share of the target the scaled mean may not fall below (1: ASCE
  // 7-16 17.3.3; 0.9: EN 1998-1 3.2.3.1.2(4)c); the range's top before EN 1998-1's cut at 4 s (0:
  // not cut); EN 1998-1 3.2.3.1.2(4)b's mean peak ground acceleration of the scaled suite's
  // components and its floor a_g S (g; both 0 for ASCE 7-16), and
  // whether that floor set the common factor.
  double target_fraction = 1.0;
  double uncut_range_top = 0.0;
  double mean_pga = 0.0, pga_floor = 0.0;
  bool pga_governs = false;
  bool mean_of_suite = false;  // values are means (>= 7 records), else maxima
  // What ran: variants bound x case; records the scaled records x orientations (record-major).
  model::StudyFile study;
  std::vector<JobResult> runs;  // job order (variant-major)
  // The run of bound b, eccentricity case c, record r and orientation o.
  const JobResult& RunOf(std::size_t b, std::size_t c, std::size_t r, std::size_t o = 0) const {
    return runs[((b * eccentricities.size() + c) * records.size() + r) * orientations.size() + o];
  }
  std::size_t RunsPerBound() const {
    return eccentricities.size() * records.size() * orientations.size();
  }
  // The weights the pendulum bearings carry, in the ELF step and in the runs alike (the nominal
  // bound's; NaN for a bearing that is not a pendulum), and the building's weight (force).
  std::vector<design::IsolationSystem::BearingWeight> bearing_weights;
  std::vector<IsolatorCapacity> capacities;  // per isolator, the nominal bound's
  double building_weight = 0.0;
  // W_s: the weight above the isolation, the base level's excluded (0 without stories).
  double structure_weight = 0.0;
  std::size_t failed = 0;
  std::vector<DesignWarning> warnings;  // bound by bound, each in the order first given
  DesignChecks checks;                  // the code's design values and checks
  // [bound][quantity]
  std::vector<std::array<DesignStatistic, kDesignQuantityCount>> values;
  std::array<std::size_t, kDesignQuantityCount> governing{};  // the bound with the largest value
  std::vector<DesignPartValue> parts;      // per part and quantity, in the runs' order
  std::size_t figure_record = 0;           // the record of the histories kept for figures
  std::size_t figure_orientation = 0;      // and its orientation
  std::vector<std::string> history_files;  // per bound, relative to the output folder
  // Machine-dependent, for progress only: the suite (matching synthetic pairs, spectra), the
  // runs, and everything.
  double suite_seconds = 0.0, runs_seconds = 0.0, wall_seconds = 0.0;
};

// The rule the pendulum bearings' weights follow, with the numbers (empty without pendulums):
// "bearing weights: 4 pendulum bearings carry ... in the ELF step and the runs alike, ...".
std::string BearingWeightRule(const model::ModelFile& model, const DesignOutcome& outcome);

// The folder a design writes into (design_folder.h), claimed: `requested` when given, else the
// design's output.directory, else the design file's stem. Throws InputError naming `option` (or
// output.directory), or a suite record's entry when the record lies inside an earlier design
// there, which the claim moves aside.
std::unique_ptr<DesignFolder> ClaimDesignFolder(const std::string& requested,
                                                const model::DesignFile& design,
                                                const std::string& option);

// `progress` gets a line per step (and per run); it may be empty. Throws InputError for a design
// the procedure cannot carry out (a period range beyond the target's, a matching that fails),
// naming the design file's key.
DesignOutcome RunDesign(const model::DesignFile& design, const std::string& output_directory,
                        const std::string& version, Scheduler& scheduler,
                        const std::function<void(const std::string&)>& progress);

}  // namespace isolab::study
