// The response quantities a study compares, measured from one run:
//   isolator_displacement           peak |u| of the isolation layer (length)
//   base_shear                      peak |force into the ground| (force)
//   story_drift_ratio               peak |drift| / height over every story with a height (%)
//   floor_acceleration              peak |absolute acceleration| over the floors above the
//                                   isolation (every DOF of a model without stories) (g)
//   residual_isolator_displacement  |u| of the isolation layer where it comes to rest after the
//                                   free vibration that follows the record (response_peaks.h)
//                                   (length)
// A plan study's runs (plan_analysis.h, as `isolab run` reports them on a plan model):
//   resultant_isolator_displacement  peak resultant |(u_x, u_y)| of the worst isolator (length)
//   resultant_base_shear             peak resultant of the isolators' summed force (force)
//   floor_rotation                   peak |rotation| of the floor that twists most (rad)
//   torsional_amplification          the worst isolator's peak resultant over that of the base's
//                                    centre of mass (1)
// Lengths and forces are in the study's units (its building's), whatever the variant's model
// uses. A quantity a variant does not have (a fixed base has no isolator) is NaN; a study shows
// the quantities of its kind (StudyQuantities).
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "isolab/analysis/analysis_setup.h"
#include "isolab/analysis/plan_analysis.h"
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
  kResultantIsolatorDisplacement,
  kResultantBaseShear,
  kFloorRotation,
  kTorsionalAmplification,
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

// The quantities a study's summary shows: a one-direction study's five, or a plan study's four.
std::vector<Quantity> StudyQuantities(bool plan);

// "mm", "kN", "%", "g": the unit quantity values are in, for a study in `units`.
std::string QuantityUnit(Quantity quantity, const UnitSystem& units);

// All NaN: nothing measured.
QuantityValues NoValues();

// `model_units` are the run's model's, `study_units` the study's; `peaks` are the run's
// (analysis::ComputePeaks).
QuantityValues MeasureQuantities(const analysis::AnalysisSetup& setup,
                                 const integrators::ResponseHistory& response,
                                 const analysis::ResponsePeaks& peaks,
                                 const UnitSystem& model_units, const UnitSystem& study_units);

// A plan run's quantities from its peaks (analysis::ComputePlanPeaks), the others NaN.
QuantityValues MeasurePlanQuantities(const analysis::PlanPeaks& peaks,
                                     const UnitSystem& model_units, const UnitSystem& study_units);

}  // namespace isolab::study
