// Elastic spring, trilinear or (uc = +inf) linear: f = g(u). The paper's Fig. 5a, the THM1
// limit u_y = 0, k0 >> k1, k2, taken exactly.
#pragma once

#include "isolab/hysteresis/law_state.h"
#include "isolab/hysteresis/trilinear_spring.h"

namespace isolab::hysteresis {

struct ElasticSpring {
  TrilinearSpring spring;

  void Update(const LawState& committed, const LawInput& in, LawState* trial,
              LawResponse* response) const {
    *trial = committed;
    trial->u = in.u;
    trial->v = in.v;
    trial->force = response->force = spring.Force(in.u);
    response->stiffness = spring.Stiffness(in.u);
    response->damping = 0.0;
  }

  double StoredEnergy(const LawState& state) const { return spring.Energy(state.u); }
};

}  // namespace isolab::hysteresis
