// A base-isolated shear building in plan: rigid floors, each with its mass, rotational
// inertia about its centre of mass and the centre of mass's plan position; stories that resist
// along x, along y and in torsion at their centre of stiffness (the description an engineer
// gives for a story: its lateral stiffnesses, where they act, and its torsional stiffness about
// that point; any one-direction laws); isolators at plan positions under the base floor, each
// with its plan laws. Plan coordinates are global; the building is built as a Structure
// (structure.h) whose floor 0 is the base and floor s + 1 the floor above story s, floor f's
// dofs (u_x, u_y, theta about its centre of mass) at 3 f, 3 f + 1, 3 f + 2.
#pragma once

#include <string>
#include <vector>

#include "isolab/hysteresis/parallel_assembly.h"
#include "isolab/hysteresis/plan_assembly.h"
#include "isolab/structure/layout.h"
#include "isolab/structure/structure.h"

namespace isolab::structure {

inline constexpr int kPlanDofsPerFloor = 3;

struct PlanFloor {
  double mass = 0.0;                // (mass)
  double rotational_inertia = 0.0;  // about the centre of mass (mass*length^2)
  hysteresis::Vec2 centre_of_mass;  // plan position (length)
};

struct PlanStory {
  std::string name;
  PlanFloor floor;      // the floor above the story
  double height = 0.0;  // (length), for reporting only
  hysteresis::Vec2 centre_of_stiffness;
  hysteresis::ParallelAssembly x, y;     // story shear against drift at the centre of stiffness
  hysteresis::ParallelAssembly torsion;  // story torque against twist
};

struct PlanIsolatorSite {
  std::string name;
  hysteresis::Vec2 position;
  hysteresis::PlanAssembly assembly;
};

// Classical damping of the fixed-base superstructure, a0 M + a1 K with K the stories' initial
// stiffness, acting on floor motion relative to the base's rigid-body motion; a0 and a1 from the
// ratios at two periods (a plan building's modes mix directions, so periods, not mode numbers).
struct PlanDamping {
  bool rayleigh = false;
  double periods[2] = {0.0, 0.0};
  double ratios[2] = {0.0, 0.0};
};

struct PlanBuilding {
  PlanFloor base;
  std::vector<PlanStory> stories;  // bottom to top
  std::vector<PlanIsolatorSite> isolators;
  PlanDamping damping;
};

// The structure and its layout: levels "base" and "floor 1" to "floor N" (their x, y and rotation
// dofs), story s's members 3 s, 3 s + 1, 3 s + 2, named "<story>.x", ".y", ".torsion", the
// isolators as coupled members under the base. `fixed_base`: the superstructure alone, the base
// held (no isolators, no base dofs). Throws std::invalid_argument naming the field at fault (no
// isolators, a mass or inertia <= 0, Rayleigh periods equal or ratios giving a negative
// coefficient).
LaidOutStructure BuildPlanBuilding(const PlanBuilding& building, bool fixed_base = false);

}  // namespace isolab::structure
