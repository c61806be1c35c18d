#include "isolab/integrators/excitation.h"

#include <algorithm>
#include <cmath>

namespace isolab::integrators {
namespace {

// The time of the next sample of `history` after t, if before `next`.
double NextSampleOf(const SampledHistory& history, double t, double next) {
  if (history.values.empty() || !(history.dt > 0.0)) return next;
  double k = std::floor(t / history.dt) + 1.0;
  if (k * history.dt <= t * (1.0 + 1e-12) + 1e-12 * history.dt) k += 1.0;
  if (k <= static_cast<double>(history.values.size() - 1)) next = std::min(next, k * history.dt);
  return next;
}

}  // namespace

Excitation Excitation::Uniform(SampledHistory acceleration) {
  Excitation excitation;
  excitation.ground.push_back({std::move(acceleration), {}});
  return excitation;
}

Excitation Excitation::Horizontal(const structure::Layout& layout, SampledHistory x,
                                  SampledHistory y) {
  Excitation excitation;
  if (!x.values.empty()) {
    excitation.ground.push_back({std::move(x), layout.ground_influence[structure::kX]});
  }
  if (!y.values.empty()) {
    excitation.ground.push_back({std::move(y), layout.ground_influence[structure::kY]});
  }
  return excitation;
}

double Excitation::duration() const {
  double duration = 0.0;
  for (const GroundMotion& motion : ground) {
    duration = std::max(duration, motion.acceleration.duration());
  }
  for (const AppliedForce& force : forces) duration = std::max(duration, force.force.duration());
  return std::max(duration, vertical.duration());
}

std::vector<Eigen::VectorXd> Excitation::MassInfluence(const Eigen::VectorXd& mass) const {
  std::vector<Eigen::VectorXd> mass_influence;
  for (const GroundMotion& motion : ground) {
    mass_influence.push_back(motion.influence.size() == 0 ? mass
                                                          : mass.cwiseProduct(motion.influence));
  }
  return mass_influence;
}

void Excitation::EffectiveLoad(double t, const std::vector<Eigen::VectorXd>& mass_influence,
                               Eigen::VectorXd* load) const {
  // The first component assigns: a one-direction record costs one pass over the dofs.
  if (ground.empty()) load->setZero();
  for (std::size_t c = 0; c < ground.size(); ++c) {
    const double a = ground[c].acceleration.At(t);
    if (c == 0) {
      load->noalias() = -a * mass_influence[c];
    } else {
      load->noalias() -= a * mass_influence[c];
    }
  }
  for (const AppliedForce& force : forces) (*load)[force.dof] += force.force.At(t);
}

void Excitation::AddGroundAcceleration(double t, Eigen::Ref<Eigen::VectorXd> acceleration) const {
  for (const GroundMotion& motion : ground) {
    const double a = motion.acceleration.At(t);
    if (motion.influence.size() == 0) {
      acceleration.array() += a;
    } else {
      acceleration += a * motion.influence;
    }
  }
}

double Excitation::NextSample(double t, double horizon) const {
  double next = horizon;
  for (const GroundMotion& motion : ground) next = NextSampleOf(motion.acceleration, t, next);
  for (const AppliedForce& force : forces) next = NextSampleOf(force.force, t, next);
  return next;
}

}  // namespace isolab::integrators
