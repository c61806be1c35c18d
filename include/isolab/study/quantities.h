// The response quantities a study compares, measured from one run's peaks (response_peaks.h), the
// same for every structure (a quantity with two horizontal components, in plan, as its
// resultant):
//   isolator_displacement           peak |u| of the worst isolator (length)
//   base_shear                      peak |force into the ground| (force)
//   story_drift_ratio               peak |drift| / height over every story with a height (%)
//   floor_acceleration              peak |absolute acceleration| over the floors above the
//                                   isolation (every level of a model without stories) (g)
//   residual_isolator_displacement  |u| of the isolator that comes to rest farthest from zero
//                                   after the free vibration that follows the record (length)
// Buildings in plan also:
//   floor_rotation                  peak |rotation| of the level that twists most (rad)
//   torsional_amplification         the worst isolator's peak displacement over that of the
//                                   base's centre of mass (1)
// Measured for every run and used by a design (study/design.h), not shown in a study's summary:
//   isolator_force                  peak |force| of the most loaded isolator (force)
//   base_centre_displacement        peak |u| of the base's centre of mass (length): the design
//                                   displacement D_M of a building in plan
// Lengths and forces are in the study's units (its building's), whatever the variant's model
// uses. A quantity a variant does not have (a fixed base has no isolator) is NaN; a study shows
// the quantities of its building (StudyQuantities).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "isolab/analysis/problem.h"
#include "isolab/analysis/response_peaks.h"
#include "isolab/core/units.h"
#include "isolab/integrators/response.h"

namespace isolab::study {

enum class Quantity {
  kIsolatorDisplacement,
  kBaseShear,
  kStoryDriftRatio,
  kFloorAcceleration,
  kResidualIsolatorDisplacement,
  kFloorRotation,
  kTorsionalAmplification,
  kIsolatorForce,
  kBaseCentreDisplacement,
};
inline constexpr std::size_t kQuantityCount = 9;

using QuantityValues = std::array<double, kQuantityCount>;

struct QuantityInfo {
  Quantity quantity;
  std::string_view key;    // column and dataset name
  std::string_view label;  // short heading for the terminal
};

// Every quantity, in the order of QuantityValues.
std::span<const QuantityInfo> Quantities();
const QuantityInfo& InfoOf(Quantity quantity);

// The quantities a study's summary shows: five, and the two of rotating levels when its building
// is in plan.
std::vector<Quantity> StudyQuantities(bool rotations);

// "mm", "kN", "%", "g": the unit quantity values are in, for a study in `units`.
std::string QuantityUnit(Quantity quantity, const UnitSystem& units);

// The peaks of a run's parts, for a design's per-story and per-bearing values (study units): each
// story's drift ratio (%; NaN without a height) and shear, each floor's absolute acceleration (g)
// above the isolation, each isolator's displacement, and each axially loaded bearing's least and
// greatest axial load N (structure/axial_load.h).
enum class PartQuantity : std::uint8_t {
  kStoryDriftRatio,
  kStoryShear,
  kFloorAcceleration,
  kIsolatorDisplacement,
  kLeastAxialLoad,
  kGreatestAxialLoad,
};
inline constexpr std::size_t kPartQuantityCount = 6;

struct PartPeak {
  PartQuantity quantity = PartQuantity::kStoryDriftRatio;
  std::string part;  // the story's, floor's, isolator's or bearing's name
  double value = 0.0;
};

// "story_drift_ratio", "story_shear", "floor_acceleration", "isolator_displacement",
// "least_axial_load", "greatest_axial_load": a part quantity's key in files and Python.
std::string_view PartQuantityName(PartQuantity quantity);
// "%", "kN", "g", "mm": the unit of a part's quantity in `units`.
std::string PartQuantityUnit(PartQuantity quantity, const UnitSystem& units);

// All NaN: nothing measured.
QuantityValues NoValues();

// `model_units` are the run's model's, `study_units` the study's.
QuantityValues MeasureQuantities(const analysis::Problem& problem,
                                 const analysis::ResponsePeaks& peaks,
                                 const UnitSystem& model_units, const UnitSystem& study_units);
std::vector<PartPeak> MeasurePartPeaks(const analysis::Problem& problem,
                                       const analysis::ResponsePeaks& peaks,
                                       const UnitSystem& model_units,
                                       const UnitSystem& study_units);

}  // namespace isolab::study
