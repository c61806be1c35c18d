// Builders for the structures isolab analyses:
//  * an SDOF oscillator: mass m, viscous damping c, restoring force from any assembly;
//  * an N-story shear building, fixed at the base or on an isolation layer. DOF 0 is the base
//    (isolated only), then floors bottom to top; all displacements relative to the ground.
//
// Superstructure damping is classical, built for the fixed-base superstructure (initial story
// stiffnesses) and acting on floor motion relative to the base, so it does not damp the rigid-body
// motion on the isolators (Kelly 1997; Chopra 2012, Ch. 21). The isolation layer's damping is its
// own components (dashpots, sliders).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "isolab/structure/layout.h"
#include "isolab/structure/structure.h"

namespace isolab::structure {

struct Story {
  std::string name;
  double floor_mass = 0.0;                // mass of the floor above the story (mass)
  double height = 0.0;                    // story height (length), for reporting only
  hysteresis::ParallelAssembly assembly;  // story shear against story drift
};

struct SuperstructureDamping {
  enum class Kind { kNone, kRayleigh, kModal };
  Kind kind = Kind::kNone;
  int rayleigh_modes[2] = {1, 2};          // 1-based modes whose ratios are matched
  double rayleigh_ratios[2] = {0.0, 0.0};  // damping ratios of those modes
  std::vector<double> modal_ratios;        // one ratio for all modes, or one per mode
};

struct ShearBuilding {
  std::vector<Story> stories;  // bottom to top
  bool isolated = false;
  double base_mass = 0.0;                  // isolated only
  hysteresis::ParallelAssembly isolation;  // isolated only: force against base displacement
  // Isolated only: the layer as bearings of `isolation`'s type in parallel, one isolator each,
  // named so; empty: the layer as the one isolator "isolation".
  std::vector<std::string> bearings;
  SuperstructureDamping damping;
};

// Undamped modes of the fixed-base superstructure with initial story stiffnesses, every one, from
// a dense eigensolution (O(stories^3)): set-up calls it only for modal damping, which needs every
// mode; Rayleigh damping takes its two frequencies by bisection (tridiagonal_pencil.h).
struct Modes {
  Eigen::VectorXd periods;  // ascending modes (time)
  Eigen::VectorXd circular_frequencies;
  Eigen::MatrixXd shapes;                 // column n: mode n, mass-normalised
  Eigen::VectorXd effective_mass_ratios;  // effective modal mass / total mass
};

Modes FixedBaseModes(const std::vector<Story>& stories);

// The structure and its layout: levels "base" (isolated) and "floor 1" to "floor N", the stories
// (their members: x only), the isolation layer as the one isolator "isolation" (or one isolator
// per named bearing, each a member of its own); an SDOF is one level "mass" on its spring
// "restoring" (or on its named bearings), which counts as its isolator. An isolated building may
// have no story (a rigid slab on its isolators). Throws std::invalid_argument with the field at
// fault when the description is inconsistent.
LaidOutStructure BuildShearBuilding(const ShearBuilding& building);
LaidOutStructure BuildSdof(double mass, double damping_coefficient,
                           hysteresis::ParallelAssembly restoring,
                           const std::vector<std::string>& bearings = {});

// Initial stiffness of an assembly: its tangent at rest.
double InitialStiffness(const hysteresis::ParallelAssembly& assembly);

}  // namespace isolab::structure
