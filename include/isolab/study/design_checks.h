// The design values a code takes from a design's response histories and the checks it asks,
// computed once (RunDesign stores them in the outcome) for the report, the terminal, the CSV files
// and Python alike. The code is the target's (model::DesignCode):
//
//   ASCE 7-16      D_TM not below 0.8 D_TM of the ELF procedure, V_b not below 0.9 of its V_b
//                  (17.6.3); no factor on displacements.
//   EN 1998-1      the isolators' displacements times gamma_x (10.3(2)); no floor from the
//                  simplified analysis; V_b as the response history gives it.
//
// and, for both, the checks, each with its clause, met or EXCEEDED (or not checked, saying why):
//   * the story drift ratio against the design's drift_limit;
//   * D_TM, the design value, against the displacement capacity of each group of isolators that
//     share one (bearing_capacity.h);
//   * where the model has axial loads (structure/axial_load.h), each bearing's least axial load
//     over every run against zero: at or below it the bearing lifts off (ASCE 7-16 17.2.4.7
//     permits local uplift only where the isolator is shown to take it, so it is reported as
//     exceeded, with the count of runs that lifted it). Without overturning in the model the
//     loads are static shares: a bearing they lift is exceeded, otherwise the check is not
//     checked (the overturning that lifts bearings is not modelled).
#pragma once

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "isolab/model/design_file.h"
#include "isolab/study/bearing_capacity.h"

namespace isolab::study {

struct DesignOutcome;

enum class Verdict { kMet, kExceeded, kNotChecked };
// "met", "EXCEEDED", "not checked"
std::string_view VerdictName(Verdict verdict);

// A design value after the code's rule: max(factor x response_history, floor x elf).
struct DesignValue {
  double response_history = 0.0;  // the governing bound's (suite mean or maximum)
  std::size_t bound = 0;          // the governing bound (index in DesignOutcome::bounds)
  double factor = 1.0;            // gamma_x on displacements (EN 1998-1), else 1
  double floor = 0.0;             // the fraction of the ELF value it may not fall below; 0: none
  double elf = 0.0;               // the ELF value (largest over the bounds)
  double value = 0.0;
  std::string rule;  // "not below 0.8 D_TM (ELF), ASCE 7-16 17.6.3"
};

struct DesignCheck {
  std::string check;   // "D_TM <= displacement capacity of tfp_1, tfp_2"
  std::string clause;  // "ASCE 7-16 17.2.4.7"
  std::string unit;
  double demand = std::numeric_limits<double>::quiet_NaN();
  double limit = std::numeric_limits<double>::quiet_NaN();  // NaN: none known
  std::string basis;  // where the limit or demand comes from, or why it is not checked
  Verdict verdict = Verdict::kNotChecked;
  std::vector<std::string> isolators;  // the isolators (bearings) the check is of; empty: all
};

// ASCE 7-16's shear on the structure above the isolation, where the design gives R_I:
//   V_st = V_b (W_s / W)^(1 - 2.5 beta_M)    (Eq. 17.5-7, per bound, from its ELF V_b and beta_M)
//   V_s  = V_st / R_I                        (Eq. 17.5-8)
// and from the response history, the first story's shear / R_I, not below 0.8 V_s (17.6.3 as
// read here; a lower floor the edition may allow a regular structure is not taken). 17.5.4.3's
// further limits (the fixed-base force of 12.8, wind, the force that activates the isolation) need
// inputs a design file does not give: not checked, said so.
struct SuperstructureShear {
  double r_i = 0.0;
  double structure_weight = 0.0, weight = 0.0;  // W_s, W
  std::vector<double> v_st;                     // per bound
  double elf = 0.0;                             // V_s (ELF): the largest V_st / R_I
  DesignValue v_s;  // response history: first story's shear / R_I, floor 0.8 x elf
};

struct DesignChecks {
  model::DesignCode code = model::DesignCode::kAsce7_16;
  DesignValue total_displacement;                     // D_TM
  DesignValue base_shear;                             // V_b
  std::optional<SuperstructureShear> superstructure;  // ASCE 7-16 with r_i and stories
  std::vector<DesignCheck> checks;
};

// The code's design values and checks of a design whose runs all completed.
DesignChecks CheckDesign(const model::DesignFile& design, const DesignOutcome& outcome);

}  // namespace isolab::study
