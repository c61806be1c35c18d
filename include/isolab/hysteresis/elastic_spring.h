// Elastic spring, trilinear or (uc = +inf) linear: f = g(u). The paper's Fig. 5a, the THM1
// limit u_y = 0, k0 >> k1, k2, taken exactly.
#pragma once

#include "isolab/hysteresis/law_state.h"
#include "isolab/hysteresis/trilinear_spring.h"

namespace isolab::hysteresis {

struct ElasticSpring {
  TrilinearSpring spring;

  // The force at `in` alone: it depends on the deformation only, never on the state.
  double Force(const LawInput& in) const { return spring.Force(in.u); }

  void Update(const LawState& committed, const LawInput& in, LawState* trial,
              LawResponse* response) const {
    *trial = committed;
    trial->u = in.u;
    trial->v = in.v;
    trial->force = response->force = Force(in);
    response->stiffness = spring.Stiffness(in.u);
    response->damping = 0.0;
  }

  double StoredEnergy(const LawState& state) const { return spring.Energy(state.u); }
};

}  // namespace isolab::hysteresis
