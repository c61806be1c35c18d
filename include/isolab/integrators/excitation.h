// What drives a structure: ground acceleration components, each moving the dofs its influence
// vector names (the displacements being relative to the ground), and applied force histories on
// chosen dofs. Every history is sampled at a fixed step, linear between samples and zero after the
// last.
//
// A one-direction structure has one component on every dof; a plan structure two, along x on each
// floor's u_x and along y on each floor's u_y (a rigid floor's rotation about its centre of mass
// takes no load from ground translation).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "isolab/structure/layout.h"

namespace isolab::integrators {

struct SampledHistory {
  double dt = 0.0;             // sampling step (time), > 0
  std::vector<double> values;  // value at k dt, k = 0, 1, ...

  // Linear between samples; zero before 0 and after the last sample. Inline: every step reads
  // it once per ground component, and out of line it costs a call the step need not pay.
  double At(double t) const {
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
  double duration() const { return values.empty() ? 0.0 : dt * (values.size() - 1); }
};

struct AppliedForce {
  int dof = 0;
  SampledHistory force;  // (force)
};

// A ground acceleration and the dofs it moves.
struct GroundMotion {
  SampledHistory acceleration;  // (length/time^2)
  // r: per dof, the dof's displacement for a unit ground displacement of this component (1 for a
  // translation along it, 0 otherwise); empty: 1 on every dof.
  Eigen::VectorXd influence;
};

struct Excitation {
  std::vector<GroundMotion> ground;
  std::vector<AppliedForce> forces;
  // The ground's vertical acceleration (length/time^2, upwards; empty for none). The structure has
  // no vertical dofs: it loads nothing directly, and acts only through the axial loads of the
  // bearings that take them (structure/axial_load.h), as N_0 (1 + a_v / g).
  SampledHistory vertical;

  // One component moving every dof: a one-direction structure's record.
  static Excitation Uniform(SampledHistory acceleration);
  // The ground's acceleration along x and along y (empty for none; y only where the layout moves
  // in two directions), moving the dofs the layout's influence vectors name.
  static Excitation Horizontal(const structure::Layout& layout, SampledHistory x,
                               SampledHistory y = {});

  double duration() const;
  // M r_c for every component c, given a lumped mass vector: what EffectiveLoad takes.
  std::vector<Eigen::VectorXd> MassInfluence(const Eigen::VectorXd& mass) const;
  // Effective load p(t) - sum_c (M r_c) a_c(t); writes into `load` (sized already).
  void EffectiveLoad(double t, const std::vector<Eigen::VectorXd>& mass_influence,
                     Eigen::VectorXd* load) const;
  // Adds the ground's acceleration at t to the dofs' relative accelerations: the absolute ones.
  void AddGroundAcceleration(double t, Eigen::Ref<Eigen::VectorXd> acceleration) const;
  // The first sample time of any history after t and before `horizon` (or `horizon`): where a
  // history's linear interpolation has a kink, which an adaptive integrator steps onto.
  double NextSample(double t, double horizon) const;
};

}  // namespace isolab::integrators
