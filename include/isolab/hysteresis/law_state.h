// The state contract every element law follows (OpenSees' committed/trial split, made structural
// as in MFront): Update(const committed&, input, trial*, response*) is a pure function, so a
// trial can be repeated or dropped; committing is the caller's swap.
#pragma once

namespace isolab::hysteresis {

// What drives a law: the element's total deformation, its rate, and the time they are reached.
struct LawInput {
  double u = 0.0;  // deformation (length)
  double v = 0.0;  // deformation rate (length/time); only rate-dependent laws read it
  double t = 0.0;  // time since the start of the run (time); only the lead core's heat
                   // conduction reads it (lead_rubber.h), with the increment t - committed.t
};

// A law's state after an update. Everything a law needs to continue from here.
struct LawState {
  double u = 0.0;       // deformation at which this state was computed (length)
  double v = 0.0;       // deformation rate at which this state was computed (length/time)
  double force = 0.0;   // force at this state (force)
  double slider = 0.0;  // slider displacement: u_h (series form), u_s (parallel form); else 0
  double accumulated_slip = 0.0;  // total slider travel since rest (length); degrading laws
  double t = 0.0;                 // time of this state (time); written by the laws that read time
  double temperature = 0.0;       // lead-core temperature rise above the start (degC); lead_rubber
  // Direction the slider slipped in to reach this state (+1, -1), or 0 if it stuck or the law has
  // no slider: the phase the next increment starts from (slip_direction.h).
  int slip = 0;
  // Energy dissipated since rest: slider work or dashpot work (force*length).
  double dissipated = 0.0;
};

// Force and its exact derivatives at the trial state.
struct LawResponse {
  double force = 0.0;      // (force)
  double stiffness = 0.0;  // d force / d u at fixed committed state (force/length)
  double damping = 0.0;    // d force / d v (force*time/length)
};

}  // namespace isolab::hysteresis
