// What an engineer checks before trusting a run, computed from the model alone and printed and
// stored before the analysis: the total weight, the periods of the superstructure on a fixed base,
// and the periods of the isolated structure with its isolators at their secant stiffness at a
// trial displacement, each mode with the direction it moves in. Values no real structure or
// record has are warned about, because they are almost always a slip of units (a unitless
// `mass: 25` in a kN-mm model is 25,000 t; a record in gal read as m/s^2 is a hundred times too
// strong):
//   * a peak ground acceleration above kMaxPlausiblePga (3 g);
//   * a fixed-base or isolated period above kMaxPlausiblePeriod (10 s);
//   * a story height outside kPlausibleStoryHeight (1 to 20 m: `height: 3.5` in a mm model is
//     3.5 mm) and a level's mass outside kPlausibleLevelMass (1 to 10^5 t);
//   * a friction pendulum carrying more than the structure weighs, or of a radius outside
//     kPlausiblePendulumRadius (0.1 to 50 m);
//   * after the run, a peak isolator displacement above kMaxBearingDisplacement (1.5 m, beyond
//     the capacity of any bearing built).
// Warnings never stop a run: the engineer decides.
#pragma once

#include <string>
#include <vector>

#include "isolab/core/units.h"
#include "isolab/hysteresis/parallel_assembly.h"
#include "isolab/hysteresis/plan_assembly.h"
#include "isolab/identification/cyclic_data.h"
#include "isolab/structure/layout.h"

namespace isolab::analysis {

inline constexpr double kMaxPlausiblePga = 3.0;                    // g
inline constexpr double kMaxPlausiblePeriod = 10.0;                // s
inline constexpr double kMaxBearingDisplacement = 1.5;             // m
inline constexpr double kPlausibleStoryHeight[] = {1.0, 20.0};     // m
inline constexpr double kPlausibleLevelMass[] = {1.0, 1e5};        // t
inline constexpr double kPlausiblePendulumRadius[] = {0.1, 50.0};  // m
inline constexpr double kDefaultTrialDisplacement = 0.1;           // m
// Structures of more dofs than this get no modes of the whole structure (a dense eigensolution's
// cost grows with the cube of its size); a chain of springs in one direction always does.
inline constexpr int kMaxDenseModalDofs = 1500;

struct Mode {
  double period = 0.0;    // (time); infinite for a mechanism
  std::string direction;  // where most of its kinetic energy is: "x", "y" or "torsion"
};

// Every quantity in the model's units.
struct ModelSummary {
  double total_mass = 0.0;    // (mass) of every level
  double total_weight = 0.0;  // (force) total mass x standard gravity
  // The superstructure on a fixed base with its initial story stiffnesses, longest first; empty
  // for an SDOF or a slab on isolators.
  std::vector<Mode> fixed_base_modes;
  bool isolated = false;            // isolators (or an SDOF's restoring force) carry it
  double trial_displacement = 0.0;  // (length) D
  // (force/length) F(D)/D of every isolator pushed along x from rest to D, summed.
  double secant_stiffness = 0.0;
  // The superstructure as a rigid body on the isolators at their secant stiffness at D: one mode
  // (along x) in one direction, three (x, y, torsion) in plan; an SDOF's own period at D.
  std::vector<Mode> rigid_modes;
  // The whole structure with the isolators at their secant stiffness at D, longest first (empty
  // beyond kMaxDenseModalDofs).
  std::vector<Mode> isolated_modes;
  // (time) the longest rigid mode's period: the isolated period engineers quote. 0 when not
  // isolated, infinite when the isolators have no stiffness at D.
  double isolated_period = 0.0;
  double pga = 0.0;  // (acceleration) of the scaled record; 0 without one
  std::vector<std::string> warnings;

  // The longest of the fixed-base and isolated periods (time).
  double LongestPeriod() const;
  std::vector<double> FixedBasePeriods() const;
};

// `structure` as it runs (on its isolators, or on a fixed base); `fixed_base` the superstructure
// on a fixed base, when the run's structure is isolated and has one. `pga` of the scaled record in
// model units (0 without one); `trial_displacement` in model length units.
ModelSummary SummariseModel(const structure::Structure& structure, const structure::Layout& layout,
                            const structure::LaidOutStructure* fixed_base, const UnitSystem& units,
                            double pga, double trial_displacement);

// The isolators' secant stiffness at D, summed (along x in plan), and the longest rigid mode's
// period there: the isolated period engineers quote at D (infinite for no stiffness at D).
struct SecantIsolation {
  double stiffness = 0.0;  // force/length
  double period = 0.0;     // time
};
SecantIsolation IsolationAt(const structure::Structure& structure, const structure::Layout& layout,
                            double displacement);

// The rigid modes at displacement D (ModelSummary::rigid_modes), e.g. at a run's peak.
std::vector<Mode> RigidModes(const structure::Structure& structure, const structure::Layout& layout,
                             double displacement);

// F(D)/D of an assembly pushed monotonically from rest to D (force/length), and of a plan
// assembly pushed along x and along y.
double SecantStiffness(const hysteresis::ParallelAssembly& assembly, double displacement);
hysteresis::Vec2 SecantStiffness(const hysteresis::PlanAssembly& assembly, double displacement);

// The warning for a peak isolator displacement beyond any bearing, or empty (lengths in the
// model's units).
std::string IsolatorDisplacementWarning(double peak, const UnitSystem& units);

// How far past the identified range a run may go unwarned: the data's own peak is one sample of
// a continuous motion, and a run at 1.03 times it (the motions the model was fitted to, rerun)
// is within what the fit saw.
inline constexpr double kIdentifiedRangeMargin = 1.1;
// Past this factor the warning says "far beyond": the response rests on the law's form alone.
inline constexpr double kFarBeyondIdentifiedRange = 2.0;

// How far a run goes past the range its isolation was identified on: the larger of its peak
// isolator displacement and velocity over the identified ones (> 0).
double IdentifiedRangeFactor(const identification::IdentifiedRange& range, double displacement,
                             double velocity);

// The warning for a run whose peak isolator displacement or velocity (|u|, |du/dt|: the resultant
// in plan) goes more than kIdentifiedRangeMargin times beyond the range its isolation was
// identified on, with how far and graded (beyond; far beyond past kFarBeyondIdentifiedRange), or
// empty (in the model's units). Beyond that range the fitted laws extrapolate.
std::string IdentifiedRangeWarning(const identification::IdentifiedRange& range,
                                   double displacement, double velocity, const UnitSystem& units);

}  // namespace isolab::analysis
