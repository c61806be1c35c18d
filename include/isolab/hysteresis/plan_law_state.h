// The state contract of the bidirectional (plan) laws, the 2-D counterpart of law_state.h: a
// trial Update(committed, input, trial*, response*) is a pure function of the committed state
// and the input, so it can be repeated or dropped, and committing is the caller's swap.
//
// A plan state is the pair of one-direction states along x and y. An uncoupled pair of 1-D laws
// (uncoupled_pair.h) keeps each direction's LawState whole. A coupled law keeps its vectors as
// the pair's components (u, v, force, slider: x.u = u_x, y.u = u_y, ...), its scalars in x
// (dissipated energy, accumulated slip, lead-core temperature, and x.slip = 1 while its slider
// slips, 0 while it sticks; y's stay 0) and the time in both.
// So a coupled law moving along x has exactly the state its 1-D law would have in x.
#pragma once

#include "isolab/hysteresis/law_state.h"
#include "isolab/hysteresis/plan_vector.h"

namespace isolab::hysteresis {

// What drives a plan law: the horizontal deformation, its rate and the time they are reached.
struct PlanLawInput {
  Vec2 u;          // deformation (length)
  Vec2 v;          // deformation rate (length/time); rate-dependent laws read it
  double t = 0.0;  // time since the start of the run (time); the lead core's conduction reads it
};

struct PlanLawState {
  LawState x, y;
};

// A plan state where it lives, for the laws to read (committed) or write (trial) in place: a
// PlanLawState, or two adjacent LawStates of a structure's state array (structure/structure.h,
// which would otherwise copy 144 bytes in and out of every component at every evaluation). They are
// for parameters: a view outliving the state it refers to dangles, and an update's committed and
// trial never share storage.
struct PlanLawStateView {
  const LawState& x;
  const LawState& y;
  PlanLawStateView(const LawState& along_x, const LawState& along_y) : x(along_x), y(along_y) {}
  PlanLawStateView(const PlanLawState& s) : x(s.x), y(s.y) {}  // NOLINT: implicit by design
};
struct PlanLawStateSlot {
  LawState& x;
  LawState& y;
  PlanLawStateSlot(LawState& along_x, LawState& along_y) : x(along_x), y(along_y) {}
  PlanLawStateSlot(PlanLawState* s) : x(s->x), y(s->y) {}  // NOLINT: implicit by design
};

// Force and its exact derivatives at the trial state.
struct PlanLawResponse {
  Vec2 force;      // (force)
  Mat2 stiffness;  // d force / d u at fixed committed state (force/length)
  Mat2 damping;    // d force / d v (force*time/length)
};

inline Vec2 Displacement(PlanLawStateView s) { return {s.x.u, s.y.u}; }
inline Vec2 Velocity(PlanLawStateView s) { return {s.x.v, s.y.v}; }
inline Vec2 Force(PlanLawStateView s) { return {s.x.force, s.y.force}; }
inline Vec2 Slider(PlanLawStateView s) { return {s.x.slider, s.y.slider}; }
// Energy dissipated since rest, both directions.
inline double Dissipated(PlanLawStateView s) { return s.x.dissipated + s.y.dissipated; }
// A coupled law's committed phase: its slider slipped to reach this state.
inline bool Slipping(PlanLawStateView s) { return s.x.slip != 0; }

// What a coupled law writes after an update; Store puts it in the layout above, every field
// written, so a trial never carries anything over from the array it was swapped from.
struct CoupledState {
  Vec2 force;
  Vec2 slider;
  double dissipated = 0.0;
  double accumulated_slip = 0.0;
  double temperature = 0.0;
  bool slipping = false;  // the slider slipped over the increment (plan_slip_decision.h)
};

// A coupled law's state before its update changes anything: the committed slider and energies.
inline CoupledState Carried(PlanLawStateView committed) {
  CoupledState c;
  c.slider = Slider(committed);
  c.dissipated = committed.x.dissipated;
  c.accumulated_slip = committed.x.accumulated_slip;
  c.temperature = committed.x.temperature;
  return c;
}

inline void Store(const PlanLawInput& in, const CoupledState& c, PlanLawStateSlot s) {
  s.x = {.u = in.u.x,
         .v = in.v.x,
         .force = c.force.x,
         .slider = c.slider.x,
         .accumulated_slip = c.accumulated_slip,
         .t = in.t,
         .temperature = c.temperature,
         .slip = c.slipping ? 1 : 0,
         .dissipated = c.dissipated};
  s.y = {.u = in.u.y,
         .v = in.v.y,
         .force = c.force.y,
         .slider = c.slider.y,
         .accumulated_slip = 0.0,
         .t = in.t,
         .temperature = 0.0,
         .slip = 0,
         .dissipated = 0.0};
}

}  // namespace isolab::hysteresis
