// Telling a run that blew up from one that completed, by its energies alone: both integrators
// check every committed output with the same rule, so `run` and `compare` never call a divergent
// response "completed" nor let it into a study's means.
#pragma once

#include <string>

#include "isolab/integrators/response.h"

namespace isolab::integrators {

// A passive structure (positive stiffnesses, dampers and sliders that dissipate) cannot hold more
// kinetic energy than the input energy it has received: kinetic <= input - elastic - damping -
// hysteretic <= input. A response whose kinetic energy exceeds this many times the largest input
// so far is creating energy (a law with negative stiffnesses, an unstable step): a blow-up. Over
// the bundled models the ratio peaks at 1.00 (it cannot exceed 1 plus the balance error); a
// negative-stiffness layer reaches 24 within 4 s. Ten leaves a margin on both sides.
constexpr double kBlowUpKineticToInput = 10.0;

// Why the energies show a blow-up (a non-finite term, or kinetic energy out of reach of the
// input), or empty when they do not. `max_input` is the largest |input energy| so far.
std::string DescribeBlowUp(const Energies& energies, double max_input);

}  // namespace isolab::integrators
