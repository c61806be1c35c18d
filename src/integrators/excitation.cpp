#include "isolab/integrators/excitation.h"

#include <algorithm>
#include <cmath>

namespace isolab::integrators {

double SampledHistory::At(double t) const {
  if (values.empty() || t < 0.0) return 0.0;
  const double position = t / dt;
  const auto k = static_cast<std::size_t>(position);
  if (k + 1 >= values.size()) {
    // The last sample holds only at its own time (to round-off); after it the history is zero.
    return k + 1 == values.size() && position - k < 1e-9 ? values.back() : 0.0;
  }
  const double fraction = position - k;
  return values[k] + fraction * (values[k + 1] - values[k]);
}

double Excitation::duration() const {
  double duration = ground_acceleration.duration();
  for (const AppliedForce& force : forces) duration = std::max(duration, force.force.duration());
  return duration;
}

void Excitation::EffectiveLoad(double t, const Eigen::VectorXd& mass, Eigen::VectorXd* load) const {
  const double ag = ground_acceleration.At(t);
  *load = -ag * mass;
  for (const AppliedForce& force : forces) (*load)[force.dof] += force.force.At(t);
}

}  // namespace isolab::integrators
