// What drives a plan structure (plan_structure.h): the ground acceleration along x and along y
// (two record components already turned to the structure's axes), on every floor's translations;
// a rigid floor's rotation about its centre of mass takes no load from ground translation.
#pragma once

#include <Eigen/Core>

#include "isolab/integrators/excitation.h"

namespace isolab::integrators {

struct PlanExcitation {
  SampledHistory x, y;  // (length/time^2), either may be empty

  double duration() const { return std::max(x.duration(), y.duration()); }
  // -M r_x a_gx(t) - M r_y a_gy(t) on the dofs (u_x, u_y, theta) of each floor.
  void EffectiveLoad(double t, const Eigen::VectorXd& mass, Eigen::VectorXd* load) const;
  // The ground acceleration a dof's relative acceleration adds to give the absolute one.
  void AddGroundAcceleration(double t, Eigen::Ref<Eigen::VectorXd> acceleration) const;
};

}  // namespace isolab::integrators
