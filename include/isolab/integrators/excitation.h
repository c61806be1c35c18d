// What drives a structure: a ground acceleration record (on every degree of freedom, the
// displacements being relative to the ground) and applied force histories on chosen degrees of
// freedom. Both are sampled at a fixed step, linear between samples and zero after the last.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace isolab::integrators {

struct SampledHistory {
  double dt = 0.0;             // sampling step (time), > 0
  std::vector<double> values;  // value at k dt, k = 0, 1, ...

  double At(double t) const;
  double duration() const { return values.empty() ? 0.0 : dt * (values.size() - 1); }
};

struct AppliedForce {
  int dof = 0;
  SampledHistory force;  // (force)
};

struct Excitation {
  SampledHistory ground_acceleration;  // (length/time^2); empty for none
  std::vector<AppliedForce> forces;

  double duration() const;
  // Effective load p(t) - M 1 a_g(t) for a lumped mass vector; writes into `load`.
  void EffectiveLoad(double t, const Eigen::VectorXd& mass, Eigen::VectorXd* load) const;
};

}  // namespace isolab::integrators
