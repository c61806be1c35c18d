// The axial loads N(t) that friction pendulum bearings carry, from rigid-slab statics of the
// bearing layout. A pendulum's strengths (mu W) and stiffnesses (W / R) are its weight W times
// constants, and its sliders decide by ratios of force to strength, so under an axial load N its
// force, tangent and work are exactly N / W times those the law computes at W
// (hysteresis::PendulumWeight): the structure scales such a bearing's response by s = N / W, and
// by 0 while N <= 0 (uplift: the bearing carries no shear).
//
// Rigid-slab statics (the floors and the base a rigid body above the bearing plane, on bearings
// equally stiff vertically): with levels i of mass m_i at plan centre of mass (x_i, y_i) and
// height z_i above the bearing plane, absolute horizontal accelerations (a_xi, a_yi) and the
// ground's vertical acceleration a_v (upwards), the bearings' loads satisfy
//   sum_j N_j = P = sum_i m_i (g + a_v),
//   sum_j x_j N_j = S_x = sum_i m_i [x_i (g + a_v) - z_i a_xi],
//   sum_j y_j N_j = S_y = sum_i m_i [y_i (g + a_v) - z_i a_yi]
// (vertical equilibrium and moment equilibrium about horizontal axes; the story inertial forces
// -m_i a_i act at their heights), and a rigid slab on equal springs shares them linearly,
//   N_j = P / n + (x_j - c_x, y_j - c_y) . I^-1 (S_x - c_x P, S_y - c_y P),
// c the bearings' centroid and I = sum_j (x_j - c)(x_j - c)^T. So N_j is linear:
//   N_j(t) = N_j,0 (1 + a_v / g) + sum_d c_jd a_d(t),
// N_j,0 the static share of the weight and c_jd the overturning coefficients on the levels'
// horizontal dofs. A one-direction model has no layout of bearings: its isolation layer carries
// the whole weight, N = sum_i m_i (g + a_v), and overturning is refused.
//
// The overturning is taken from the inertial forces of the step's start (the committed absolute
// accelerations), so the step's equations, and their tangent, stay those of the laws: an explicit
// coupling, first order in the step (the integrator's documentation says so where it applies).
#pragma once

#include <span>
#include <string>
#include <utility>
#include <vector>

namespace isolab::structure {

struct Layout;
class Structure;

struct AxialBearing {
  std::string name;          // the isolator's
  std::size_t slot = 0;      // its member in Structure's order: members, then coupled members
  double weight = 0.0;       // W its laws take (force), > 0: its response scales by N / W
  double static_load = 0.0;  // N_0, its share of the weight at rest (force)
  // (dof, c): N's change per unit absolute acceleration of the dof (mass*length/length: force
  // per acceleration); empty without overturning.
  std::vector<std::pair<int, double>> overturning;
};

struct AxialLoads {
  double gravity = 0.0;  // g (length/time^2), > 0 when there are bearings
  std::vector<AxialBearing> bearings;

  bool empty() const { return bearings.empty(); }
  // N_j at the vertical ground acceleration a_v (upwards) and the dofs' absolute accelerations.
  double Load(std::size_t bearing, double vertical_acceleration,
              std::span<const double> absolute_acceleration) const {
    const AxialBearing& b = bearings[bearing];
    double load = b.static_load * (1.0 + vertical_acceleration / gravity);
    for (const auto& [dof, c] : b.overturning) load += c * absolute_acceleration[dof];
    return load;
  }
  // The scale of a bearing's response at load N: N / W, 0 while N <= 0.
  double Scale(std::size_t bearing, double load) const {
    return load > 0.0 ? load / bearings[bearing].weight : 0.0;
  }
};

struct AxialLoadOptions {
  double gravity = 0.0;      // g in the model's units (length/time^2), > 0
  bool overturning = false;  // the story inertial forces' moments (a building in plan only)
  double base_height = 0.0;  // height of the base level's mass above the bearing plane (length)
};

// The axial loads of a laid-out structure's isolators: `weights` has one entry per isolator (the
// layout's order), its pendulum laws' W, or 0 for an isolator whose laws keep their own load (an
// elastomeric bearing); every isolator shares the statics. Throws std::invalid_argument for
// overturning on a structure that is not in plan, for isolators on a line (a plan moment about
// that line has no rigid-slab share), or for a story without a height when overturning is asked.
AxialLoads RigidSlabAxialLoads(const Structure& structure, const Layout& layout,
                               std::span<const double> weights, const AxialLoadOptions& options);

}  // namespace isolab::structure
