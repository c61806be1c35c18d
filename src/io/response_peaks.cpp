#include "isolab/io/response_peaks.h"

#include <algorithm>
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
  if (setup.layout.isolation >= 0 && r.rows_written > 0) {
    const int dof = connections[setup.layout.isolation].dof_j;
    const int last = r.rows_written - 1;
    double low = r.displacement(last, dof), high = low;
    for (int row = last; row >= 0 && r.time[row] >= r.time[last] - setup.residual_window; --row) {
      low = std::min(low, r.displacement(row, dof));
      high = std::max(high, r.displacement(row, dof));
    }
    peaks.residual_isolator_displacement = 0.5 * (low + high);
    peaks.residual_oscillation = 0.5 * (high - low);
    for (int row = 0; row <= last && r.time[row] <= setup.excitation_end * (1 + 1e-12); ++row) {
      peaks.isolator_displacement_at_excitation_end = r.displacement(row, dof);
    }
  }
  if (peaks.story_drift.index >= 0) {
    const double height = setup.layout.story_heights[peaks.story_drift.index];
    if (height > 0.0) peaks.story_drift_ratio = peaks.story_drift.value / height;
  }
  return peaks;
}

}  // namespace isolab::io
