#include "isolab/analysis/summary_peaks.h"

namespace isolab::analysis {
namespace {

// Which structures have a peak.
enum class Applies { kAlways, kIsolated, kStories, kRotations, kIsolatedRotations };

struct Row {
  const char* name;
  const char* label;
  Peak ResponsePeaks::*peak;
  Dimension dimension;
  Applies applies;
  NamedPeak::Note note;
};

using Note = NamedPeak::Note;
constexpr Row kRows[] = {
    {"isolator_displacement", "peak isolator displacement", &ResponsePeaks::isolator_displacement,
     dimension::kLength, Applies::kIsolated, Note::kIsolator},
    {"isolator_force", "peak isolator force", &ResponsePeaks::isolator_force, dimension::kForce,
     Applies::kIsolated, Note::kIsolator},
    {"base_shear", "peak base shear", &ResponsePeaks::base_shear, dimension::kForce,
     Applies::kAlways, Note::kNone},
    {"first_story_shear", "peak first-story shear", &ResponsePeaks::first_story_shear,
     dimension::kForce, Applies::kStories, Note::kNone},
    {"story_drift", "peak story drift", &ResponsePeaks::story_drift, dimension::kLength,
     Applies::kStories, Note::kStoryAndRatio},
    {"roof_absolute_acceleration", "peak roof absolute acceleration",
     &ResponsePeaks::roof_absolute_acceleration, dimension::kAcceleration, Applies::kAlways,
     Note::kG},
    {"floor_acceleration", "peak floor acceleration", &ResponsePeaks::floor_acceleration,
     dimension::kAcceleration, Applies::kStories, Note::kLevelAndG},
    {"floor_rotation", "peak floor rotation", &ResponsePeaks::level_rotation, dimension::kNone,
     Applies::kRotations, Note::kLevel},
    {"base_centre_displacement", "peak base centre displacement",
     &ResponsePeaks::base_centre_displacement, dimension::kLength, Applies::kIsolatedRotations,
     Note::kNone},
};

bool AppliesTo(Applies applies, const structure::Layout& layout) {
  switch (applies) {
    case Applies::kAlways:
      return true;
    case Applies::kIsolated:
      return layout.isolated();
    case Applies::kStories:
      return !layout.stories.empty();
    case Applies::kRotations:
      return layout.rotations;
    case Applies::kIsolatedRotations:
      return layout.rotations && layout.isolated();
  }
  return false;
}

}  // namespace

std::vector<NamedPeak> SummaryPeaks(const structure::Layout& layout, const ResponsePeaks& peaks) {
  std::vector<NamedPeak> named;
  for (const Row& row : kRows) {
    if (!AppliesTo(row.applies, layout)) continue;
    named.push_back({row.name, row.label, &(peaks.*row.peak), row.dimension, row.note});
  }
  return named;
}

std::optional<SecantIsolation> IsolationAtPeak(const Problem& problem, const ResponsePeaks& peaks) {
  if (!problem.layout.isolated() || !(peaks.isolator_displacement.value > 0.0)) return std::nullopt;
  return IsolationAt(problem.structure, problem.layout, peaks.isolator_displacement.value);
}

std::string PeakUnit(const UnitSystem& units, Dimension dimension) {
  return dimension == dimension::kNone ? "rad" : DescribeUnits(units, dimension);
}

}  // namespace isolab::analysis
