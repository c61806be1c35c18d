// The closed set of bidirectional (plan) kernels, stored by value (law_kernel.h for one
// direction). Each coupled kernel carries its 1-D law's kernel as its parameters, so a plan law is
// built from the same validated LawParameters, the same keys and rules, as the 1-D law; an
// uncoupled pair carries two 1-D kernels.
#pragma once

#include <variant>

#include "isolab/hysteresis/law_parameters.h"
#include "isolab/hysteresis/plan_bouc_wen.h"
#include "isolab/hysteresis/plan_dashpot.h"
#include "isolab/hysteresis/plan_elastic_spring.h"
#include "isolab/hysteresis/plan_friction_pendulum.h"
#include "isolab/hysteresis/plan_lead_rubber.h"
#include "isolab/hysteresis/plan_parallel_slider.h"
#include "isolab/hysteresis/plan_series_slider.h"
#include "isolab/hysteresis/uncoupled_pair.h"

namespace isolab::hysteresis {

using PlanLawKernel =
    std::variant<PlanSeriesSlider, PlanParallelSlider, PlanElasticSpring, PlanDashpot, PlanBoucWen,
                 PlanFrictionPendulum, PlanLeadRubber, UncoupledPair>;

// Whether a law has a coupled bidirectional form: every law but degrading_bhm2 (whose damage
// has no 2-D energy bookkeeping yet); it can still act as an uncoupled pair.
bool HasCoupledForm(LawType type);

// The coupled form of a validated law (hdr_bearing is BHM2, so it comes as PlanParallelSlider).
// Throws std::invalid_argument naming the law when HasCoupledForm is false: a model reader checks
// HasCoupledForm first and reports its own located error.
PlanLawKernel CoupledKernel(const LawParameters& law);

// Two independent 1-D laws along x and y.
PlanLawKernel UncoupledKernel(const LawParameters& along_x, const LawParameters& along_y);

inline void UpdatePlanLaw(const PlanLawKernel& kernel, PlanLawStateView committed,
                          const PlanLawInput& in, PlanLawStateSlot trial,
                          PlanLawResponse* response) {
  std::visit([&](const auto& law) { law.Update(committed, in, trial, response); }, kernel);
}

inline double PlanStoredEnergy(const PlanLawKernel& kernel, PlanLawStateView state) {
  return std::visit([&](const auto& law) { return law.StoredEnergy(state); }, kernel);
}

// Whether the law's stiffness and damping are the same at every state (law_kernel.h): a linear
// spring, a dashpot, or an uncoupled pair of such.
bool HasConstantTangent(const PlanLawKernel& kernel);

// The part of Dissipated(state) that dashpots took (the rest is hysteretic), for the energy
// balance's split.
double PlanViscousEnergy(const PlanLawKernel& kernel, PlanLawStateView state);

}  // namespace isolab::hysteresis
