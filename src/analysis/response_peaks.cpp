#include "isolab/analysis/response_peaks.h"

#include <algorithm>
#include <cmath>

namespace isolab::analysis {
namespace {

void Consider(Peak* peak, double value, double time, int index = -1) {
  if (std::abs(value) > peak->value) *peak = {std::abs(value), time, index};
}

}  // namespace

void PeakTracker::Observe(const integrators::ResponseRow& row) {
  const auto& connections = setup_.structure.connections();
  const int roof = setup_.structure.dofs() - 1;
  const double t = row.time;
  ResponsePeaks& peaks = peaks_;
  if (setup_.layout.isolation >= 0) {
    const double u = row.displacement[connections[setup_.layout.isolation].dof_j];
    Consider(&peaks.isolator_displacement, u, t);
    Consider(&peaks.isolator_force, row.connection_force[setup_.layout.isolation], t);
    // The residual is read over the last residual_window of the run, wherever the run ends.
    window_.emplace_back(t, u);
    while (window_.front().first < t - setup_.residual_window) window_.pop_front();
    if (t <= setup_.excitation_end * (1 + 1e-12)) peaks.isolator_displacement_at_excitation_end = u;
  }
  double base_shear = 0.0;
  for (std::size_t k = 0; k < connections.size(); ++k) {
    if (connections[k].dof_i == structure::kGround) base_shear += row.connection_force[k];
  }
  Consider(&peaks.base_shear, base_shear, t);
  Consider(&peaks.roof_absolute_acceleration, row.absolute_acceleration[roof], t, roof);
  for (std::size_t s = 0; s < setup_.layout.stories.size(); ++s) {
    if (s == 0) {
      Consider(&peaks.first_story_shear, row.connection_force[setup_.layout.stories[s]], t);
    }
    Consider(&peaks.story_drift, StoryDrift(setup_, row.displacement, s), t, static_cast<int>(s));
  }
  peaks.energies = row.energies;
  ++peaks.rows;
}

ResponsePeaks PeakTracker::Peaks() const {
  ResponsePeaks peaks = peaks_;
  if (!window_.empty()) {
    double low = window_.back().second, high = low;
    for (const auto& [t, u] : window_) {
      low = std::min(low, u);
      high = std::max(high, u);
    }
    peaks.residual_isolator_displacement = 0.5 * (low + high);
    peaks.residual_oscillation = 0.5 * (high - low);
  }
  if (peaks.story_drift.index >= 0) {
    const double height = setup_.layout.story_heights[peaks.story_drift.index];
    if (height > 0.0) peaks.story_drift_ratio = peaks.story_drift.value / height;
  }
  return peaks;
}

ResponsePeaks ComputePeaks(const AnalysisSetup& setup, const integrators::ResponseHistory& r) {
  PeakTracker tracker(setup);
  for (int row = 0; row < r.rows_written; ++row) tracker.Observe(r.Row(row));
  return tracker.Peaks();
}

}  // namespace isolab::analysis
