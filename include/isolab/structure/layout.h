// What a structure's dofs and members mean to an engineer: levels (the base on its isolators,
// then the floors), the stories between them, the isolators, and how the ground moves the dofs.
// A builder (shear_building.h, plan_building.h) lays its structure out once; everything that
// reads a response (peaks, results files, summaries, studies) reads it through this, so it works
// the same on a one-direction building (one translation per level) as on a building in plan (two
// translations and a rotation per level).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "isolab/structure/structure.h"

namespace isolab::structure {

// The directions a level moves in: index into Level::dofs and a story's members.
enum Direction { kX = 0, kY = 1, kRotation = 2 };

struct Level {
  std::string name;  // "base", "floor 1", ...; an SDOF's "mass"
  // Its dofs along x, along y and in rotation about its centre of mass; kGround where it has none.
  std::array<int, 3> dofs{kGround, kGround, kGround};
  Vec2 centre_of_mass;  // plan position (length); zero in one direction
};

struct StoryLayout {
  std::string name;
  int level = 0;        // the level above the story
  double height = 0.0;  // (length), 0 where not given
  // Its members resisting along x, along y and in torsion (index into Structure::members()); -1
  // where it has none. The torsion member's deformation is a twist (rad), its force a torque.
  std::array<int, 3> members{-1, -1, -1};
};

// An isolator (a bearing position): a slot of the structure (a one-direction member acting along
// x, or a coupled member).
struct IsolatorLayout {
  std::string name;
  int slot = -1;  // index into the structure's slots
  int level = 0;  // the level it carries
  Vec2 position;  // plan position (length); zero in one direction
};

// A force into the ground: a slot's force, along `direction` for a slot of width 1 (its vector
// for one of width 2).
struct GroundForce {
  int slot = -1;
  int direction = kX;
};

struct Layout {
  int directions = 1;         // horizontal directions every level moves in: 1 (x) or 2 (x, y)
  bool rotations = false;     // levels also rotate (a building in plan)
  std::vector<Level> levels;  // bottom to top: the base (when isolated), then the floors
  std::vector<StoryLayout> stories;  // bottom to top
  std::vector<IsolatorLayout> isolators;
  std::vector<GroundForce> base_shear;  // the forces that make the base shear
  // Per direction (x, then y): the dofs a unit ground displacement along it moves (the influence
  // vector r), so a record component along x loads the structure with -M r a(t). Empty: every
  // dof (a one-direction structure).
  std::array<Eigen::VectorXd, 2> ground_influence;

  bool isolated() const { return !isolators.empty(); }
  // The highest level, whose absolute acceleration is the roof's.
  const Level& roof() const { return levels.back(); }
};

// A structure and its layout, as a builder makes them.
struct LaidOutStructure {
  Structure structure;
  Layout layout;
};

}  // namespace isolab::structure
