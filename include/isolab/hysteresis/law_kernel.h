// The closed set of update kernels, stored by value. Every named law (law_parameters.h) compiles
// to one of these, so a parallel assembly is a flat array dispatched by a switch, with no heap
// object or virtual call per component.
#pragma once

#include <cmath>
#include <variant>

#include "isolab/hysteresis/bouc_wen.h"
#include "isolab/hysteresis/dashpot.h"
#include "isolab/hysteresis/degrading_slider.h"
#include "isolab/hysteresis/elastic_spring.h"
#include "isolab/hysteresis/friction_pendulum.h"
#include "isolab/hysteresis/lead_rubber.h"
#include "isolab/hysteresis/parallel_slider.h"
#include "isolab/hysteresis/play_slider.h"
#include "isolab/hysteresis/series_slider.h"

namespace isolab::hysteresis {

using LawKernel = std::variant<SeriesSlider, ParallelSlider, ElasticSpring, Dashpot, BoucWen,
                               DegradingSlider, FrictionPendulum, LeadRubber, PlaySlider>;

inline void UpdateLaw(const LawKernel& kernel, const LawState& committed, const LawInput& in,
                      LawState* trial, LawResponse* response) {
  std::visit([&](const auto& law) { law.Update(committed, in, trial, response); }, kernel);
}

inline double StoredEnergy(const LawKernel& kernel, const LawState& state) {
  return std::visit([&](const auto& law) { return law.StoredEnergy(state); }, kernel);
}

// Whether the law's stiffness and damping are the same at every state (a linear spring, a
// dashpot), so a structure may assemble them once per step size instead of every iteration.
inline bool HasConstantTangent(const LawKernel& kernel) {
  if (const auto* elastic = std::get_if<ElasticSpring>(&kernel)) {
    return elastic->spring.kh1 == elastic->spring.kh2 || !std::isfinite(elastic->spring.uc);
  }
  return std::holds_alternative<Dashpot>(kernel);
}

}  // namespace isolab::hysteresis
