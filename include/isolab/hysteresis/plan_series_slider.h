// THM1 kernel in two directions (series form; series_slider.h for one): a spring ke in series
// with [a rigid-plastic slider of circular (isotropic) strength fs, in parallel with the spring g
// driven by the slider displacement x = u_h (radial_spring.h)]:
//   u = u_e + x,   f = ke (u - x) = f_s + g(x),   |f_s| <= fs,
// the slider moving only along its force, dx = lambda f_s / fs with lambda >= 0 (associative
// flow on the circle). BHM1 (kh1 = kh2), the elastoplastic element (kh1 = kh2 = 0) and, with
// fs = 0, a spring ke in series with g are the same kernel, as in 1-D.
//
// Return map (backward Euler, the closest-point projection): from the committed x_n the slider
// sticks while the trial slider force f_s* = ke (u - x_n) - g(x_n) lies in the circle; otherwise
// x = x_n + xi solves
//   R(xi) = ke (x_n + xi) + g(x_n + xi) + fs xi / |xi| - ke u = 0,
// the stationarity of the strictly convex ke |u - x|^2 / 2 + G(|x|) + fs |x - x_n| (G the
// spring's energy; convex because ke + kh1 > 0 and ke + kh2 > 0), so the solution is unique, and
// any x that satisfies it on either segment of g is the solution. It is found in closed form or
// as the root of one scalar equation:
//   * the slip ends inside uc, where g = kh1 x: the radial return, n along
//     w = ke u - (ke + kh1) x_n (the trial slider force f_s* when x_n is inside too) and
//     x = (ke u - fs n) / (ke + kh1), the 1-D kernel's formula at |w|; accepted when |x| <= uc;
//   * it ends beyond uc, where g = kh2 x + (kh1 - kh2) uc x / |x|: given n, x lies along
//     ke u - fs n with a known length, and n solves (x(n) - x_n) x n = 0, by Newton on the angle
//     of n from the direction of f_s* (about four turns in the Table 9 runs);
//   * a slip of round-off size (f_s* within 1e-6 of fs; x - x_n would lose it) and any case the
//     scalar iteration cannot settle go to Newton on xi in 2-D, started from the better of two
//     closed forms (the radial return at the secant of x_n, and x = (ke + g)^-1 (ke u - fs
//     f_s*/|f_s*|)), with backtracking on |R|, stopped at the residual's round-off.
// Along a line through the origin (motion along one axis, in any direction) each is the 1-D
// kernel's solution, so the 1-D law is reproduced to round-off. The Jacobian of R is ke I + B
// with B = Dg(x) + (fs / |xi|) (I - n n^T), n = xi / |xi|, positive definite, and the consistent
// tangent is
//   d f / d u = ke B (ke I + B)^-1,
// the exact derivative of the computed update (symmetric; 1-D: ke kh / (ke + kh)); inside uc its
// axes are n, with ke kh1 / (ke + kh1), and the normal to n. The force is written fs n + g(x), as
// in 1-D free of the cancellation in ke (u - x) when ke >> kh; the dissipation is fs |xi|, the
// slider's work. If Newton fails (it has not been seen to), the force is NaN and the integrator
// cuts the step. With fs = 0 (no slider) x solves ke x + g(x) = ke u along u, and the tangent has
// the axes of x: ke in series with g's slope along x and with its secant across.
//
// A continuing slip (plan_slip_decision.h) whose trial force lies on the circle or a round-off
// inside it (du = 0, or one of round-off size) has zero travel: the slider stays at x_n with force
// fs n + g(x_n), n the trial force's direction, and the tangent is the consistent one's limit as
// |xi| -> 0 (c -> infinity): ke (Dg (A^-1 - w w^T / t.w) + t w^T / t.w), the slip side's
// derivative (slip_direction.h explains why it is exact there). Along n it is the post-yield
// slope ke kh / (ke + kh) of a linear g, across n ke.
#pragma once

#include "isolab/hysteresis/plan_law_state.h"
#include "isolab/hysteresis/plan_slip_decision.h"
#include "isolab/hysteresis/radial_spring.h"
#include "isolab/hysteresis/series_slider.h"

namespace isolab::hysteresis {

struct PlanSeriesSlider {
  SeriesSlider law;  // ke, fs and g, as the 1-D kernel of the same law has them

  // The one stick test of the family (plan_slip_decision.h): the slider force if it stuck is
  // f_s* = ke (u - x_n) - g(x_n) = f_s,n + ke du, f_s,n = f_n - g(x_n) the committed one
  // (committed_spring_force = g(x_n)).
  bool Sticks(PlanLawStateView committed, Vec2 committed_spring_force, Vec2 u,
              Vec2 trial_slider_force) const {
    if (!(law.fs > 0.0)) return false;
    return !PlanSlips(Slipping(committed), Force(committed) - committed_spring_force,
                      u - Displacement(committed), Norm(trial_slider_force) / law.fs);
  }

  void Update(PlanLawStateView committed, const PlanLawInput& in, PlanLawStateSlot trial,
              PlanLawResponse* response) const;

  // Recoverable energy: the spring ke (|f|^2 / 2 ke) plus g.
  double StoredEnergy(PlanLawStateView state) const;
};

}  // namespace isolab::hysteresis
