#include "isolab/study/quantities.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace isolab::study {
namespace {

constexpr QuantityInfo kQuantities[] = {
    {Quantity::kIsolatorDisplacement, "isolator_displacement", "isolator"},
    {Quantity::kBaseShear, "base_shear", "base shear"},
    {Quantity::kStoryDriftRatio, "story_drift_ratio", "drift"},
    {Quantity::kFloorAcceleration, "floor_acceleration", "floor acc."},
    {Quantity::kResidualIsolatorDisplacement, "residual_isolator_displacement", "residual"},
    {Quantity::kFloorRotation, "floor_rotation", "rotation"},
    {Quantity::kTorsionalAmplification, "torsional_amplification", "torsion amp."},
    {Quantity::kIsolatorForce, "isolator_force", "isolator force"},
    {Quantity::kBaseCentreDisplacement, "base_centre_displacement", "base centre"},
};
static_assert(std::size(kQuantities) == kQuantityCount);

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// From the model's unit of `dimension` to the study's.
double Conversion(const UnitSystem& model_units, const UnitSystem& study_units,
                  Dimension dimension) {
  return model_units.SiFactor(dimension) / study_units.SiFactor(dimension);
}

}  // namespace

std::span<const QuantityInfo> Quantities() { return kQuantities; }

const QuantityInfo& InfoOf(Quantity quantity) {
  return kQuantities[static_cast<std::size_t>(quantity)];
}

std::vector<Quantity> StudyQuantities(bool rotations) {
  std::vector<Quantity> quantities = {Quantity::kIsolatorDisplacement, Quantity::kBaseShear,
                                      Quantity::kStoryDriftRatio, Quantity::kFloorAcceleration,
                                      Quantity::kResidualIsolatorDisplacement};
  if (rotations) {
    quantities.push_back(Quantity::kFloorRotation);
    quantities.push_back(Quantity::kTorsionalAmplification);
  }
  return quantities;
}

std::string QuantityUnit(Quantity quantity, const UnitSystem& units) {
  switch (quantity) {
    case Quantity::kIsolatorDisplacement:
    case Quantity::kResidualIsolatorDisplacement:
    case Quantity::kBaseCentreDisplacement:
      return units.length();
    case Quantity::kBaseShear:
    case Quantity::kIsolatorForce:
      return units.force();
    case Quantity::kFloorRotation:
      return "rad";
    case Quantity::kTorsionalAmplification:
      return "1";
    case Quantity::kStoryDriftRatio:
      return "%";
    case Quantity::kFloorAcceleration:
      return "g";
  }
  return "";
}

QuantityValues NoValues() {
  QuantityValues values;
  values.fill(kNaN);
  return values;
}

QuantityValues MeasureQuantities(const analysis::Problem& problem,
                                 const analysis::ResponsePeaks& peaks,
                                 const UnitSystem& model_units, const UnitSystem& study_units) {
  const double length = Conversion(model_units, study_units, dimension::kLength);
  const double force = Conversion(model_units, study_units, dimension::kForce);
  const double g = model_units.Convert(1.0, "g", dimension::kAcceleration);
  const structure::Layout& layout = problem.layout;
  QuantityValues values = NoValues();
  const auto set = [&](Quantity q, double value) { values[static_cast<std::size_t>(q)] = value; };
  set(Quantity::kBaseShear, peaks.base_shear.value * force);
  if (layout.isolated()) {
    set(Quantity::kIsolatorDisplacement, peaks.isolator_displacement.value * length);
    set(Quantity::kIsolatorForce, peaks.isolator_force.value * force);
    // In one direction every isolator carries the base: its displacement is the base's.
    set(Quantity::kBaseCentreDisplacement,
        (layout.rotations ? peaks.base_centre_displacement : peaks.isolator_displacement).value *
            length);
    if (peaks.rows > 0) {
      set(Quantity::kResidualIsolatorDisplacement,
          std::abs(peaks.residual_isolator_displacement) * length);
    }
  }
  const bool heights = std::any_of(layout.stories.begin(), layout.stories.end(),
                                   [](const structure::StoryLayout& s) { return s.height > 0.0; });
  if (heights) set(Quantity::kStoryDriftRatio, 100.0 * peaks.largest_drift_ratio);
  set(Quantity::kFloorAcceleration, peaks.floor_acceleration.value / g);
  if (layout.rotations) set(Quantity::kFloorRotation, peaks.level_rotation.value);
  if (layout.rotations && layout.isolated()) {
    set(Quantity::kTorsionalAmplification, peaks.torsional_amplification);
  }
  return values;
}

std::string_view PartQuantityName(PartQuantity q) {
  switch (q) {
    case PartQuantity::kStoryDriftRatio:
      return "story_drift_ratio";
    case PartQuantity::kStoryShear:
      return "story_shear";
    case PartQuantity::kFloorAcceleration:
      return "floor_acceleration";
    case PartQuantity::kIsolatorDisplacement:
      return "isolator_displacement";
    case PartQuantity::kLeastAxialLoad:
      return "least_axial_load";
    case PartQuantity::kGreatestAxialLoad:
      return "greatest_axial_load";
  }
  return "";
}

std::string PartQuantityUnit(PartQuantity quantity, const UnitSystem& units) {
  switch (quantity) {
    case PartQuantity::kStoryDriftRatio:
      return "%";
    case PartQuantity::kFloorAcceleration:
      return "g";
    case PartQuantity::kIsolatorDisplacement:
      return units.length();
    case PartQuantity::kStoryShear:
    case PartQuantity::kLeastAxialLoad:
    case PartQuantity::kGreatestAxialLoad:
      return units.force();
  }
  return "";
}

std::vector<PartPeak> MeasurePartPeaks(const analysis::Problem& problem,
                                       const analysis::ResponsePeaks& peaks,
                                       const UnitSystem& model_units,
                                       const UnitSystem& study_units) {
  const double length = Conversion(model_units, study_units, dimension::kLength);
  const double force = Conversion(model_units, study_units, dimension::kForce);
  const double g = model_units.Convert(1.0, "g", dimension::kAcceleration);
  const structure::Layout& layout = problem.layout;
  std::vector<PartPeak> parts;
  for (std::size_t s = 0; s < layout.stories.size(); ++s) {
    const structure::StoryLayout& story = layout.stories[s];
    parts.push_back(
        {PartQuantity::kStoryDriftRatio, story.name,
         story.height > 0.0 ? 100.0 * peaks.story_drifts[s].value / story.height : kNaN});
    parts.push_back({PartQuantity::kStoryShear, story.name, peaks.story_shears[s].value * force});
  }
  for (const analysis::Peak& floor : peaks.floor_accelerations) {
    parts.push_back({PartQuantity::kFloorAcceleration,
                     layout.levels[static_cast<std::size_t>(floor.index)].name, floor.value / g});
  }
  for (std::size_t i = 0; i < peaks.isolator_displacements.size(); ++i) {
    parts.push_back({PartQuantity::kIsolatorDisplacement, layout.isolators[i].name,
                     peaks.isolator_displacements[i].value * length});
  }
  const structure::AxialLoads& axial = problem.structure.axial_loads();
  for (std::size_t j = 0; j < peaks.axial_load_minima.size(); ++j) {
    parts.push_back({PartQuantity::kLeastAxialLoad, axial.bearings[j].name,
                     peaks.axial_load_minima[j].value * force});
    parts.push_back({PartQuantity::kGreatestAxialLoad, axial.bearings[j].name,
                     peaks.axial_load_maxima[j].value * force});
  }
  return parts;
}

}  // namespace isolab::study
