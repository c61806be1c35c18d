// What an engineer checks before trusting a run, computed from the model alone and printed and
// stored before the analysis: the total weight, the fixed-base periods of the superstructure and
// the isolated period at a trial displacement. Values no real structure or record has are
// warned about, because they are almost always a slip of units (a unitless `mass: 25` in a kN-mm
// model is 25,000 t; a record in gal read as m/s^2 is a hundred times too strong):
//   * a peak ground acceleration above kMaxPlausiblePga (3 g);
//   * a fixed-base or isolated period above kMaxPlausiblePeriod (10 s);
//   * after the run, a peak isolator displacement above kMaxBearingDisplacement (1.5 m, beyond
//     the capacity of any bearing built).
// Warnings never stop a run: the engineer decides.
#pragma once

#include <string>
#include <vector>

#include "isolab/hysteresis/parallel_assembly.h"
#include "isolab/model/model_file.h"

namespace isolab::analysis {

inline constexpr double kMaxPlausiblePga = 3.0;           // g
inline constexpr double kMaxPlausiblePeriod = 10.0;       // s
inline constexpr double kMaxBearingDisplacement = 1.5;    // m
inline constexpr double kDefaultTrialDisplacement = 0.1;  // m

// Every quantity in the model's units.
struct ModelSummary {
  double total_mass = 0.0;    // (mass) of every degree of freedom
  double total_weight = 0.0;  // (force) total mass x standard gravity
  // (time) modes of the superstructure on a fixed base with its initial story stiffnesses,
  // longest first; empty for an SDOF.
  std::vector<double> fixed_base_periods;
  bool isolated = false;            // an isolation layer (or an SDOF's restoring force) carries it
  double trial_displacement = 0.0;  // (length)
  // (force/length) F(D)/D of the isolation pushed from rest to the trial displacement D.
  double secant_stiffness = 0.0;
  // (time) 2 pi sqrt(total mass / secant stiffness): the whole structure as a rigid block on
  // the isolation at D (an SDOF: its own period at D). 0 when not isolated.
  double isolated_period = 0.0;
  double pga = 0.0;  // (acceleration) of the scaled record; 0 without one
  std::vector<std::string> warnings;

  // The longest of the periods above (time).
  double LongestPeriod() const;
};

// `fixed_base`: the building analysed without its isolation. `pga`: of the scaled record in
// model units (0 without one). `trial_displacement` in model length units.
ModelSummary SummariseModel(const model::ModelFile& model, bool fixed_base, double pga,
                            double trial_displacement);

// F(D)/D of an assembly pushed monotonically from rest to D (force/length).
double SecantStiffness(const hysteresis::ParallelAssembly& assembly, double displacement);

// The warning for a peak isolator displacement beyond any bearing, or empty (lengths in the
// model's units).
std::string IsolatorDisplacementWarning(double peak, const UnitSystem& units);

}  // namespace isolab::analysis
