#include "isolab/structure/axial_load.h"

#include <cmath>
#include <stdexcept>

#include "isolab/structure/layout.h"
#include "isolab/structure/structure.h"

namespace isolab::structure {
namespace {

// Each level's height above the bearing plane: the base's as given, then the stories' heights
// added from the bottom.
std::vector<double> LevelHeights(const Layout& layout, const AxialLoadOptions& options) {
  std::vector<double> heights(layout.levels.size(), options.base_height);
  for (const StoryLayout& story : layout.stories) {
    if (options.overturning && !(story.height > 0.0)) {
      throw std::invalid_argument("story " + story.name +
                                  " has no height: overturning needs every story's height");
    }
    for (std::size_t level = static_cast<std::size_t>(story.level); level < heights.size();
         ++level) {
      heights[level] += story.height;
    }
  }
  return heights;
}

}  // namespace

AxialLoads RigidSlabAxialLoads(const Structure& structure, const Layout& layout,
                               std::span<const double> weights, const AxialLoadOptions& options) {
  if (weights.size() != layout.isolators.size()) {
    throw std::invalid_argument("axial loads: one weight per isolator");
  }
  if (!(options.gravity > 0.0)) throw std::invalid_argument("axial loads: gravity must be > 0");
  AxialLoads loads;
  loads.gravity = options.gravity;
  const std::size_t n = layout.isolators.size();
  if (n == 0) return loads;
  const bool plan = layout.rotations;
  if (options.overturning && !plan) {
    throw std::invalid_argument(
        "overturning needs a building in plan: a one-direction model has no layout of bearings "
        "to share a moment");
  }
  const std::vector<double> heights = LevelHeights(layout, options);
  double weight = 0.0, first_x = 0.0, first_y = 0.0;  // P, S_x, S_y under gravity
  for (const Level& level : layout.levels) {
    const double m = structure.mass()[level.dofs[kX]];
    weight += m * options.gravity;
    first_x += m * options.gravity * level.centre_of_mass.x;
    first_y += m * options.gravity * level.centre_of_mass.y;
  }
  // The linear share N_j = P / n + arm_j . I^-1 (S - c P); in one direction, P / n.
  Vec2 centroid;
  for (const IsolatorLayout& isolator : layout.isolators) {
    centroid = centroid + (1.0 / static_cast<double>(n)) * isolator.position;
  }
  double ixx = 0.0, ixy = 0.0, iyy = 0.0;
  for (const IsolatorLayout& isolator : layout.isolators) {
    const Vec2 arm = isolator.position - centroid;
    ixx += arm.x * arm.x;
    ixy += arm.x * arm.y;
    iyy += arm.y * arm.y;
  }
  const double det = ixx * iyy - ixy * ixy;
  if (plan && !(det > 1e-12 * (ixx + iyy) * (ixx + iyy))) {
    throw std::invalid_argument(
        "the isolators lie on a line (or at one point): rigid-slab statics cannot share a "
        "moment about it among them");
  }
  // The share of a moment (S_x, S_y) about the centroid: arm_j . I^-1 S.
  const auto share = [&](Vec2 arm, double sx, double sy) {
    return (arm.x * (iyy * sx - ixy * sy) + arm.y * (ixx * sy - ixy * sx)) / det;
  };
  for (std::size_t j = 0; j < n; ++j) {
    if (weights[j] <= 0.0) continue;
    const IsolatorLayout& isolator = layout.isolators[j];
    AxialBearing bearing;
    bearing.name = isolator.name;
    bearing.slot = static_cast<std::size_t>(isolator.slot);
    bearing.weight = weights[j];
    bearing.static_load = weight / static_cast<double>(n);
    if (plan) {
      const Vec2 arm = isolator.position - centroid;
      bearing.static_load +=
          share(arm, first_x - centroid.x * weight, first_y - centroid.y * weight);
      if (options.overturning) {
        for (std::size_t l = 0; l < layout.levels.size(); ++l) {
          const Level& level = layout.levels[l];
          const double lever = structure.mass()[level.dofs[kX]] * heights[l];
          if (lever == 0.0) continue;
          // S_x gains -m z a_x, S_y gains -m z a_y.
          bearing.overturning.emplace_back(level.dofs[kX], -lever * share(arm, 1.0, 0.0));
          bearing.overturning.emplace_back(level.dofs[kY], -lever * share(arm, 0.0, 1.0));
        }
      }
    }
    loads.bearings.push_back(std::move(bearing));
  }
  return loads;
}

}  // namespace isolab::structure
