#include "isolab/io/response_peaks.h"

#include <cmath>

namespace isolab::io {
namespace {

void Consider(Peak* peak, double value, double time, int index = -1) {
  if (std::abs(value) > peak->value) *peak = {std::abs(value), time, index};
}

}  // namespace

ResponsePeaks ComputePeaks(const AnalysisSetup& setup, const integrators::ResponseHistory& r) {
  ResponsePeaks peaks;
  const auto& connections = setup.structure.connections();
  const int roof = setup.structure.dofs() - 1;
  for (int row = 0; row < r.rows_written; ++row) {
    const double t = r.time[row];
    if (setup.layout.isolation >= 0) {
      const auto& isolation = connections[setup.layout.isolation];
      Consider(&peaks.isolator_displacement, r.displacement(row, isolation.dof_j), t);
      Consider(&peaks.isolator_force, r.connection_force(row, setup.layout.isolation), t);
    }
    double base_shear = 0.0;
    for (std::size_t k = 0; k < connections.size(); ++k) {
      if (connections[k].dof_i == structure::kGround) base_shear += r.connection_force(row, k);
    }
    Consider(&peaks.base_shear, base_shear, t);
    Consider(&peaks.roof_absolute_acceleration, r.absolute_acceleration(row, roof), t, roof);
    for (std::size_t s = 0; s < setup.layout.stories.size(); ++s) {
      if (s == 0)
        Consider(&peaks.first_story_shear, r.connection_force(row, setup.layout.stories[s]), t);
      const double drift = StoryDrift(setup, r.displacement, row, s);
      Consider(&peaks.story_drift, drift, t, static_cast<int>(s));
    }
  }
  if (peaks.story_drift.index >= 0) {
    const double height = setup.layout.story_heights[peaks.story_drift.index];
    if (height > 0.0) peaks.story_drift_ratio = peaks.story_drift.value / height;
  }
  return peaks;
}

}  // namespace isolab::io
