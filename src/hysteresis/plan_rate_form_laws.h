// Rate forms of the coupled plan laws, dispatched from plan_rate_form.cpp, with the pieces they
// share. Private to the hysteresis library.
#pragma once

#include "isolab/hysteresis/plan_rate_form.h"

namespace isolab::hysteresis {

// Writers of 2x2 blocks of a PlanRateResponse: force_q columns (column, column + 1); rate_u,
// rate_v rows (row, row + 1); rate_q rows (row, row + 1) x columns (column, column + 1).
void SetForceQ(PlanRateResponse* r, int column, const Mat2& m);
void SetRateU(PlanRateResponse* r, int row, const Mat2& m);
void SetRateV(PlanRateResponse* r, int row, const Mat2& m);
void SetRateQ(PlanRateResponse* r, int row, int column, const Mat2& m);
void SetRate(PlanRateResponse* r, int row, Vec2 rate);

// The elastoplastic link of the parallel form and of the bearings: u - s with |u - s| <= reach
// (fs / kp, or u_y), the slider s following it along n = (u - s) / |u - s| at the loading rate
// n . v while it slips: ds/dt = n (n . v).
struct LinkSlip {
  Vec2 n;
  Mat2 dn_du;  // (I - n n^T) / |u - s|; d n / d s = -dn_du
  Vec2 rate;
  Mat2 rate_u, rate_v;  // d rate / d s = -rate_u
};
LinkSlip SlipOfLink(Vec2 u, Vec2 v, Vec2 slider);
// Stick: reach - |u - s| (the link reaches its circle); slip: n . v (loading stops).
double LinkRoot(double reach, const PlanLawPhase& phase, Vec2 u, Vec2 v, Vec2 slider);
// Stick to slip (unless n . v <= 0) or slip to stick, the slider put at u - reach n; `direction`
// follows the velocity as for the 1-D friction pendulum (n when slip starts, -n when it ends).
void LinkSwitch(double reach, Vec2 u, Vec2 v, PlanPhaseSwitch* next);

inline Vec2 VectorAt(const double* q, int i = 0) { return {q[i], q[i + 1]}; }
inline void SetVectorAt(Vec2 a, double* q, int i = 0) {
  q[i] = a.x;
  q[i + 1] = a.y;
}

// Each law's Switch gets `next` holding the current phase and internal variables, and changes
// what root `root` switches.

PlanRateResponse Evaluate(const PlanSeriesSlider& law, const PlanLawPhase& phase, Vec2 u, Vec2 v,
                          const double* q, double t);
void Roots(const PlanSeriesSlider& law, const PlanLawPhase& phase, Vec2 u, Vec2 v, const double* q,
           double* roots);
void Switch(const PlanSeriesSlider& law, int root, Vec2 u, Vec2 v, PlanPhaseSwitch* next);

PlanRateResponse Evaluate(const PlanParallelSlider& law, const PlanLawPhase& phase, Vec2 u, Vec2 v,
                          const double* q, double t);
void Roots(const PlanParallelSlider& law, const PlanLawPhase& phase, Vec2 u, Vec2 v,
           const double* q, double* roots);
void Switch(const PlanParallelSlider& law, int root, Vec2 u, Vec2 v, PlanPhaseSwitch* next);

PlanRateResponse Evaluate(const PlanElasticSpring& law, const PlanLawPhase& phase, Vec2 u, Vec2 v,
                          const double* q, double t);
void Roots(const PlanElasticSpring& law, const PlanLawPhase& phase, Vec2 u, Vec2 v, const double* q,
           double* roots);
void Switch(const PlanElasticSpring& law, int root, Vec2 u, Vec2 v, PlanPhaseSwitch* next);

PlanRateResponse Evaluate(const PlanDashpot& law, const PlanLawPhase& phase, Vec2 u, Vec2 v,
                          const double* q, double t);
PlanRateResponse Evaluate(const PlanBoucWen& law, const PlanLawPhase& phase, Vec2 u, Vec2 v,
                          const double* q, double t);

PlanRateResponse Evaluate(const PlanFrictionPendulum& law, const PlanLawPhase& phase, Vec2 u,
                          Vec2 v, const double* q, double t);
void Roots(const PlanFrictionPendulum& law, const PlanLawPhase& phase, Vec2 u, Vec2 v,
           const double* q, double* roots);
void Switch(const PlanFrictionPendulum& law, int root, Vec2 u, Vec2 v, PlanPhaseSwitch* next);

PlanRateResponse Evaluate(const PlanLeadRubber& law, const PlanLawPhase& phase, Vec2 u, Vec2 v,
                          const double* q, double t);
void Roots(const PlanLeadRubber& law, const PlanLawPhase& phase, Vec2 u, Vec2 v, const double* q,
           double* roots);
void Switch(const PlanLeadRubber& law, int root, Vec2 u, Vec2 v, PlanPhaseSwitch* next);

}  // namespace isolab::hysteresis
