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
    {Quantity::kResultantIsolatorDisplacement, "resultant_isolator_displacement", "isolator |u|"},
    {Quantity::kResultantBaseShear, "resultant_base_shear", "base shear |V|"},
    {Quantity::kFloorRotation, "floor_rotation", "rotation"},
    {Quantity::kTorsionalAmplification, "torsional_amplification", "torsion amp."},
};
static_assert(std::size(kQuantities) == kQuantityCount);

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The DOFs whose absolute acceleration is a floor's: the top of each story, or every DOF of a
// model without stories (an SDOF's mass).
std::vector<int> FloorDofs(const analysis::AnalysisSetup& setup) {
  std::vector<int> dofs;
  const auto& connections = setup.structure.connections();
  for (const int story : setup.layout.stories) dofs.push_back(connections[story].dof_j);
  if (dofs.empty()) {
    for (int dof = 0; dof < setup.structure.dofs(); ++dof) dofs.push_back(dof);
  }
  return dofs;
}

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

std::vector<Quantity> StudyQuantities(bool plan) {
  if (plan) {
    return {Quantity::kResultantIsolatorDisplacement, Quantity::kResultantBaseShear,
            Quantity::kFloorRotation, Quantity::kTorsionalAmplification};
  }
  return {Quantity::kIsolatorDisplacement, Quantity::kBaseShear, Quantity::kStoryDriftRatio,
          Quantity::kFloorAcceleration, Quantity::kResidualIsolatorDisplacement};
}

std::string QuantityUnit(Quantity quantity, const UnitSystem& units) {
  switch (quantity) {
    case Quantity::kIsolatorDisplacement:
    case Quantity::kResidualIsolatorDisplacement:
    case Quantity::kResultantIsolatorDisplacement:
      return units.length();
    case Quantity::kBaseShear:
    case Quantity::kResultantBaseShear:
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

QuantityValues MeasureQuantities(const analysis::AnalysisSetup& setup,
                                 const integrators::ResponseHistory& response,
                                 const analysis::ResponsePeaks& peaks,
                                 const UnitSystem& model_units, const UnitSystem& study_units) {
  const double length = Conversion(model_units, study_units, dimension::kLength);
  const double force = Conversion(model_units, study_units, dimension::kForce);
  const double g = model_units.Convert(1.0, "g", dimension::kAcceleration);
  const int rows = response.rows_written;

  QuantityValues values = NoValues();
  const auto set = [&](Quantity q, double value) { values[static_cast<std::size_t>(q)] = value; };
  set(Quantity::kBaseShear, peaks.base_shear.value * force);
  if (setup.layout.isolation >= 0) {
    set(Quantity::kIsolatorDisplacement, peaks.isolator_displacement.value * length);
    if (rows > 0) {
      set(Quantity::kResidualIsolatorDisplacement,
          std::abs(peaks.residual_isolator_displacement) * length);
    }
  }
  // The largest ratio, which need not be the largest drift's when heights differ.
  double drift_ratio = kNaN;
  for (std::size_t s = 0; s < setup.layout.stories.size(); ++s) {
    const double height = setup.layout.story_heights[s];
    if (!(height > 0.0)) continue;
    if (std::isnan(drift_ratio)) drift_ratio = 0.0;
    for (int row = 0; row < rows; ++row) {
      drift_ratio =
          std::max(drift_ratio,
                   std::abs(analysis::StoryDrift(setup, response.displacement, row, s)) / height);
    }
  }
  set(Quantity::kStoryDriftRatio, 100.0 * drift_ratio);
  double acceleration = 0.0;
  for (const int dof : FloorDofs(setup)) {
    for (int row = 0; row < rows; ++row) {
      acceleration = std::max(acceleration, std::abs(response.absolute_acceleration(row, dof)));
    }
  }
  set(Quantity::kFloorAcceleration, acceleration / g);
  return values;
}

QuantityValues MeasurePlanQuantities(const analysis::PlanPeaks& peaks,
                                     const UnitSystem& model_units, const UnitSystem& study_units) {
  const double length = Conversion(model_units, study_units, dimension::kLength);
  const double force = Conversion(model_units, study_units, dimension::kForce);
  QuantityValues values = NoValues();
  const auto set = [&](Quantity q, double value) { values[static_cast<std::size_t>(q)] = value; };
  set(Quantity::kResultantIsolatorDisplacement, peaks.largest_resultant.value * length);
  set(Quantity::kResultantBaseShear, peaks.base_shear.value * force);
  set(Quantity::kFloorRotation, peaks.largest_floor_rotation.value);
  set(Quantity::kTorsionalAmplification, peaks.torsional_amplification);
  return values;
}

}  // namespace isolab::study
