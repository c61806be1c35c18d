// Double and triple friction pendulum bearings as sliders in series (series_arrangement.h), in the
// engineer's terms: the supported weight W, each sliding surface's effective radius R_i, friction
// coefficient mu_i and actual displacement capacity d_i, and the pre-slide displacement u_y.
//
// Effective radius and capacity as OpenSees' TripleFrictionPendulum takes them (its L_i, "L_i =
// R_i - h_i", and its displacement limits): from a surface's geometric radius R_i, the height h_i
// of the slider's pivot above it and the nominal capacity d_i (the slider's travel along the dish),
// R_eff,i = R_i - h_i and d_i* = d_i R_eff,i / R_i (Fenz & Constantinou 2008). A surface slides
// when the force reaches mu_i W and stiffens it by W / R_eff,i.
//
// Double pendulum (Fenz & Constantinou 2006): two surfaces in series, each a single pendulum:
//   element i: f = mu_i W, k = W / R_i, stop d_i      (i = 1, 2).
//
// Triple pendulum (Fenz & Constantinou 2008, Earthquake Spectra 24(4), the series model with
// modified parameters): surfaces 1 and 4 the outer dishes, 2 and 3 the inner slider's. The bearing
// is not a plain series of its four surfaces (sliding on surface 1 stops the motion on surface 2
// in regime II), but it is a series of four elements whose parameters are modified:
//   element 1: f = mu1 W, k = W / (R1 - R2), stop d1 (R1 - R2) / R1
//   element 2: f = mu2 W, k = W / R2,        stop d2 + d1 R2 / R1
//   element 3: f = mu3 W, k = W / R3,        stop d3 + d4 R3 / R4
//   element 4: f = mu4 W, k = W / (R4 - R3), stop d4 (R4 - R3) / R4
// The surfaces' own displacements follow from the elements' z_1..z_4:
//   u1 = z1 R1 / (R1 - R2),  u2 = z2 - z1 R2 / (R1 - R2),  and 4, 3 alike,
// so that W u1 / R1 is element 1's spring force, u1 + u2 = z1 + z2, and the surfaces move as
// Fenz & Constantinou describe ("Spherical sliding isolation bearings with adaptive behavior:
// Theory"): in regime II u2 stays still while z2 moves, and surface 1 is at its restrainer exactly
// when u1 = d1 (surface 2 when u2 = d2 once surface 1 is at its own).
// The inner elements' stops are where the inner slider reaches its restrainers once the outer
// surface on its side has reached its own (as in regime V): OpenSees places the combined inner
// element's stop at 2 (d2 + R2 d4 / R4), the same for a symmetric bearing.
//
// In both, ke = min_i(mu_i) W / u_y in series: the bearing deforms by u_y before its first surface
// slides (friction_pendulum.h's u_y), and it is the stiffness once every restrainer is engaged.
//
// The five regimes (Fenz & Constantinou 2008, for mu2 = mu3 < mu1 < mu4 and R1 = R4 >> R2 = R3;
// element k sliding means z_k moving):
//   I    sliding on surfaces 2 and 3      elements 2, 3                 F from mu2 W
//   II   sliding on 1 and 3               elements 1, 2, 3              F from mu1 W
//   III  sliding on 1 and 4               all four                      F from mu4 W
//   IV   1 at its restrainer; 2 and 4     1 at its stop; 2, 3, 4        F from W (mu1 + d1/R1)
//   V    1 and 4 at theirs; 2 and 3       1, 4 at their stops; 2, 3     F from W (mu4 + d4/R4)
// and, once the inner slider reaches its restrainers too, the bearing is stiff (ke): its
// capacity is used up.
#pragma once

#include <array>
#include <span>
#include <string_view>

#include "isolab/hysteresis/law_state.h"
#include "isolab/hysteresis/plan_law_state.h"
#include "isolab/hysteresis/series_arrangement.h"

namespace isolab::hysteresis {

struct DoublePendulum {
  double weight = 0.0;               // W (force), > 0
  std::array<double, 2> radius{};    // effective radii R_1, R_2 (length), > 0
  std::array<double, 2> friction{};  // mu_1, mu_2, > 0
  std::array<double, 2> capacity{};  // actual displacement capacities d_1, d_2 (length), > 0
  double uy = 0.0;                   // pre-slide displacement (length), > 0

  SeriesArrangement Series() const;
};

struct TriplePendulum {
  double weight = 0.0;               // W (force), > 0
  std::array<double, 4> radius{};    // effective radii R_1..R_4 (length); R_1 > R_2, R_4 > R_3
  std::array<double, 4> friction{};  // mu_1..mu_4, > 0; mu_2 <= mu_1, mu_3 <= mu_4
  std::array<double, 4> capacity{};  // actual displacement capacities d_1..d_4 (length), > 0
  double uy = 0.0;                   // pre-slide displacement (length), > 0

  SeriesArrangement Series() const;
};

// Regimes of a triple pendulum (above). kSticking: no surface slid over the state's last
// increment (inside the loop, or below the first friction). kBeyondV: the inner slider is against
// a restrainer too.
enum class PendulumRegime { kSticking, kI, kII, kIII, kIV, kV, kBeyondV };

// The regime as docs/bearings.md names it: "sticking", "I" to "V", "beyond V".
std::string_view PendulumRegimeName(PendulumRegime regime);

// The regime a triple pendulum's state reached over its last increment (at a displacement peak:
// the regime of the peak), from its series model (TriplePendulum::Series) and its element states
// (series_arrangement.h). A bearing whose outer surfaces reach their restrainers in the other
// order, or that slides on 4 before 1 (mu4 < mu1), is reported by the same counts: IV is one
// outer surface at its restrainer, II one outer surface sliding. These functions throw
// std::invalid_argument for a series model that is not a triple pendulum's (four elements).
PendulumRegime TriplePendulumRegime(const SeriesArrangement& series,
                                    std::span<const LawState> elements);

// Displacements u_1..u_4 of a triple pendulum's surfaces (above), and u_i / d_i, the fraction of
// each surface's capacity used (1 at its restrainer).
std::array<double, 4> TriplePendulumSurfaceDisplacements(const SeriesArrangement& series,
                                                         std::span<const LawState> elements);
std::array<double, 4> TriplePendulumCapacityUsed(const SeriesArrangement& series,
                                                 std::span<const LawState> elements);

// The same in plan, from plan_series_arrangement.h's element states: a surface's displacement is
// a vector, its capacity used |u_i| / d_i (1 to round-off at its restrainer ring).
PendulumRegime TriplePendulumRegime(const SeriesArrangement& series,
                                    std::span<const PlanLawState> elements);
std::array<Vec2, 4> TriplePendulumSurfaceDisplacements(const SeriesArrangement& series,
                                                       std::span<const PlanLawState> elements);
std::array<double, 4> TriplePendulumCapacityUsed(const SeriesArrangement& series,
                                                 std::span<const PlanLawState> elements);

// Whether element k of a series law is against its stop (exactly: the update puts it there).
bool StopEngaged(const SeriesArrangement& series, std::span<const LawState> elements, int k);

}  // namespace isolab::hysteresis
