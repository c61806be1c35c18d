// Elastic spring in two directions, trilinear or (uc = +inf) linear: f = g(u) with g the radial
// extension of the 1-D spring (radial_spring.h); elastic_spring.h for one direction.
#pragma once

#include "isolab/hysteresis/elastic_spring.h"
#include "isolab/hysteresis/plan_law_state.h"
#include "isolab/hysteresis/radial_spring.h"

namespace isolab::hysteresis {

struct PlanElasticSpring {
  ElasticSpring law;

  void Update(PlanLawStateView committed, const PlanLawInput& in, PlanLawStateSlot trial,
              PlanLawResponse* response) const {
    CoupledState next;
    next.force = RadialForce(law.spring, in.u);
    next.dissipated = committed.x.dissipated;
    response->force = next.force;
    response->stiffness = RadialStiffness(law.spring, in.u);
    response->damping = {};
    Store(in, next, trial);
  }

  double StoredEnergy(PlanLawStateView state) const {
    return RadialEnergy(law.spring, Displacement(state));
  }
};

}  // namespace isolab::hysteresis
