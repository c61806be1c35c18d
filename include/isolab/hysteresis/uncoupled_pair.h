// An uncoupled isolator: two independent 1-D laws, one along x and one along y (any laws of the
// library, the same or not), as engineers often model a bearing: f_x = f_x(u_x), f_y = f_y(u_y),
// each with its own state (PlanLawState's x and y), the tangent and damping diagonal. Unlike the
// coupled laws its strength is a square, not a circle, so under motion off the axes it carries up
// to sqrt(2) times the force of its coupled counterpart.
#pragma once

#include "isolab/hysteresis/law_kernel.h"
#include "isolab/hysteresis/plan_law_state.h"

namespace isolab::hysteresis {

struct UncoupledPair {
  LawKernel x, y;

  void Update(PlanLawStateView committed, const PlanLawInput& in, PlanLawStateSlot trial,
              PlanLawResponse* response) const {
    LawResponse rx, ry;
    UpdateLaw(x, committed.x, {in.u.x, in.v.x, in.t}, &trial.x, &rx);
    UpdateLaw(y, committed.y, {in.u.y, in.v.y, in.t}, &trial.y, &ry);
    response->force = {rx.force, ry.force};
    response->stiffness = {rx.stiffness, 0.0, 0.0, ry.stiffness};
    response->damping = {rx.damping, 0.0, 0.0, ry.damping};
  }

  double StoredEnergy(PlanLawStateView state) const {
    return hysteresis::StoredEnergy(x, state.x) + hysteresis::StoredEnergy(y, state.y);
  }
};

}  // namespace isolab::hysteresis
