// Telling a run that blew up from one that completed, by its energies alone: both integrators
// check every committed output with the same rule, so `run` and `compare` never call a divergent
// response "completed" nor let it into a study's means.
#pragma once

#include <cmath>
#include <string>

#include "isolab/integrators/response.h"

namespace isolab::integrators {

// A passive structure (positive stiffnesses, dampers and sliders that dissipate) cannot hold more
// kinetic energy than the work it has been supplied (Energies::Supplied: the input's, and the
// varying axial loads' on pendulum bearings): kinetic <= input + axial - elastic - damping -
// hysteretic. A response whose kinetic energy exceeds this many times the largest supplied work
// so far is creating energy (a law with negative stiffnesses, an unstable step): a blow-up. Over
// the bundled models the ratio peaks at 1.00 (it cannot exceed 1 plus the balance error); a
// negative-stiffness layer reaches 24 within 4 s. Ten leaves a margin on both sides.
constexpr double kBlowUpKineticToInput = 10.0;

inline bool EnergiesFinite(const Energies& e) {
  return std::isfinite(e.input) && std::isfinite(e.kinetic) && std::isfinite(e.damping) &&
         std::isfinite(e.elastic) && std::isfinite(e.hysteretic);
}

// Whether the energies show a blow-up: a non-finite term, or kinetic energy out of reach of the
// supplied work. `max_input` is the largest Energies::Supplied() so far. Inline: it is asked at
// every step.
inline bool ShowsBlowUp(const Energies& e, double max_input) {
  return !EnergiesFinite(e) || e.kinetic > kBlowUpKineticToInput * max_input;
}

// What the blow-up ShowsBlowUp found is, for the run's message.
std::string DescribeBlowUp(const Energies& energies, double max_input);

}  // namespace isolab::integrators
