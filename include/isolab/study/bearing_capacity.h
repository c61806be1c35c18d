// A bearing's displacement capacity, for the design's check of D_TM against it:
//  * a double or triple friction pendulum: its surfaces' actual capacities together, d1 + d2
//    (+ d3 + d4): the total displacement at which every slider is at its restrainer
//    (docs/bearings.md);
//  * a high-damping rubber bearing from design data: its rubber thickness times the allowable
//    shear strain the design gives (`shear_strain_limit`);
//  * any other law: none known (a single pendulum's law has no restrainer, a lead-rubber bearing's
//    no rubber height): the check says so rather than guess.
// An isolator of several components has the least capacity among them.
#pragma once

#include <optional>
#include <string>

#include "isolab/hysteresis/parallel_assembly.h"
#include "isolab/hysteresis/plan_assembly.h"

namespace isolab::study {

struct BearingCapacity {
  double displacement = 0.0;  // length
  std::string basis;          // "d1 + d2 + d3 + d4 of tfp", "tr x 2.5 of hdrb"
};

// nullopt when no component's capacity is known; `shear_strain_limit` 0 when none is given.
std::optional<BearingCapacity> DisplacementCapacity(const hysteresis::ParallelAssembly& laws,
                                                    double shear_strain_limit);
std::optional<BearingCapacity> DisplacementCapacity(const hysteresis::PlanAssembly& laws,
                                                    double shear_strain_limit);

}  // namespace isolab::study
