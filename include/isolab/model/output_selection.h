// What a run records in its results file (the model file's `output:` section, or `isolab run
// --every/--quantities/--levels/--summary-only`, which override it):
//
//   output:
//     file: results.h5
//     every: 10                 # every 10th analysis step (default 1: every step)
//     quantities: [displacement, isolator, story, energy]   # default: all of kQuantityNames
//     levels: [0, 5, roof]      # default: all; 0 = the base (an SDOF's mass), k = floor k
//     summary_only: false       # true: peaks and final energies only, no histories
//
// Peaks, the residual displacement and the energy balance always see every step: the selection
// thins only what is written. Levels choose the columns of the per-DOF quantities, and of the
// per-connection ones (connection_force, story drift and shear) by the level above the
// connection; time and the ground acceleration are always written with any history.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace isolab::model {

// The history groups a selection names; each is one or more series of results_file.h.
//   displacement, velocity, acceleration, absolute_acceleration: per DOF
//   connection_force: per connection
//   isolator: isolator/displacement, force and component_force (its hysteresis)
//   story: story/drift, drift_ratio and shear
//   energy: energy/input, kinetic, damping, elastic, hysteretic
inline constexpr std::array<std::string_view, 8> kQuantityNames = {
    "displacement",     "velocity", "acceleration", "absolute_acceleration",
    "connection_force", "isolator", "story",        "energy"};

// The level "roof": the top DOF, whatever the building's height.
inline constexpr int kRoofLevel = -1;

struct OutputSelection {
  int every = 1;                        // >= 1
  bool summary_only = false;            // no histories at all
  std::vector<std::string> quantities;  // empty: every one of kQuantityNames
  std::vector<int> levels;              // empty: every level; kRoofLevel for "roof"

  bool Records(std::string_view quantity) const;
};

// "roof" or a level number (>= 0); nullopt for anything else. The callers say where it was.
std::optional<int> ParseLevel(const std::string& text);
// Why `name` is none of kQuantityNames (naming the nearest), or empty when it is one.
std::string UnknownQuantity(const std::string& name);

}  // namespace isolab::model
