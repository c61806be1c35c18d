// The stick-or-slip decision of a circular slider over an increment, shared by every plan kernel
// with a slider (plan_parallel_slider.h, plan_unit_slider.h, plan_series_slider.h): the 2-D form
// of slip_direction.h, and for the same reason.
//
// A slider that slipped to reach its committed state sits on its circle, so an increment of zero
// (a Newton iterate that repeats the committed displacement) recomputes a trial force whose norm
// equals the strength up to round-off, and a bare |trial| <= strength decides stick or slip by
// the sign of that round-off: half such continuing slips would start on the elastic tangent and
// need a second solve. The committed phase is known
// (PlanLawState's x.slip), so:
//   * committed slipping along n and n . du >= 0: the slip goes on, exactly, since then
//     |trial|^2 = strength^2 + 2 strength k n . du + k^2 |du|^2 >= strength^2;
//   * otherwise the kernel's own test |trial| <= strength.
// The tangent at du = 0 is then the slip side's, the phase of the step before (slip_direction.h
// explains why both one-sided derivatives are exact). For the series form (plan_series_slider.h)
// the trial slider force is f_s,n + ke du, so the same inequality holds with k = ke; a continuing
// slip whose trial is a round-off inside the circle has zero travel and the limit tangent.
#pragma once

#include "isolab/hysteresis/plan_vector.h"

namespace isolab::hysteresis {

//   committed_slipping  the committed state's phase (Slipping(state))
//   committed_direction any positive multiple of the committed slider force's direction
//   du                  increment of the driving deformation from the committed state
//   trial_norm          |trial slider force| / strength if it stuck over the increment
inline bool PlanSlips(bool committed_slipping, Vec2 committed_direction, Vec2 du,
                      double trial_norm) {
  if (committed_slipping && Dot(committed_direction, du) >= 0.0) return true;
  return trial_norm > 1.0;
}

}  // namespace isolab::hysteresis
