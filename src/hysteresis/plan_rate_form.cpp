#include "isolab/hysteresis/plan_rate_form.h"

#include <stdexcept>
#include <type_traits>

#include "plan_rate_form_laws.h"

namespace isolab::hysteresis {

void SetForceQ(PlanRateResponse* r, int column, const Mat2& m) {
  r->force_q[0][column] = m.xx;
  r->force_q[0][column + 1] = m.xy;
  r->force_q[1][column] = m.yx;
  r->force_q[1][column + 1] = m.yy;
}
void SetRateU(PlanRateResponse* r, int row, const Mat2& m) {
  r->rate_u[row] = {m.xx, m.xy};
  r->rate_u[row + 1] = {m.yx, m.yy};
}
void SetRateV(PlanRateResponse* r, int row, const Mat2& m) {
  r->rate_v[row] = {m.xx, m.xy};
  r->rate_v[row + 1] = {m.yx, m.yy};
}
void SetRateQ(PlanRateResponse* r, int row, int column, const Mat2& m) {
  r->rate_q[row][column] = m.xx;
  r->rate_q[row][column + 1] = m.xy;
  r->rate_q[row + 1][column] = m.yx;
  r->rate_q[row + 1][column + 1] = m.yy;
}
void SetRate(PlanRateResponse* r, int row, Vec2 rate) {
  r->rate[row] = rate.x;
  r->rate[row + 1] = rate.y;
}

namespace {

// Sliders in series have their rate form in plan_series_rate_form.h, a variable pair per
// element; HasRateForm keeps them away from this contract, so these are never reached.
[[noreturn]] void SeriesTakeTheirOwnRateForm() {
  throw std::logic_error("sliders in series take plan_series_rate_form.h (HasRateForm is false)");
}
PlanRateResponse Evaluate(const PlanSeriesArrangement&, const PlanLawPhase&, Vec2, Vec2,
                          const double*, double) {
  SeriesTakeTheirOwnRateForm();
}
void Roots(const PlanSeriesArrangement&, const PlanLawPhase&, Vec2, Vec2, const double*, double*) {
  SeriesTakeTheirOwnRateForm();
}
void Switch(const PlanSeriesArrangement&, int, Vec2, Vec2, PlanPhaseSwitch*) {
  SeriesTakeTheirOwnRateForm();
}

// Laws without roots, and the pair (handled below).
void Roots(const PlanDashpot&, const PlanLawPhase&, Vec2, Vec2, const double*, double*) {}
void Roots(const PlanBoucWen&, const PlanLawPhase&, Vec2, Vec2, const double*, double*) {}
void Switch(const PlanDashpot&, int, Vec2, Vec2, PlanPhaseSwitch*) {}
void Switch(const PlanBoucWen&, int, Vec2, Vec2, PlanPhaseSwitch*) {}

// ---- Uncoupled pair: the 1-D rate forms along x and y, their q and roots one after the other.

// The pair's 1-D law along `axis` (0: x, 1: y) with its phase, its first q and first root.
struct Side {
  const LawKernel& kernel;
  int q0, root0, count;
};
Side SideOf(const UncoupledPair& pair, int axis) {
  const int nx = InternalVariableCount(pair.x);
  return axis == 0 ? Side{pair.x, 0, 0, nx}
                   : Side{pair.y, nx, PhaseRootCount(pair.x), InternalVariableCount(pair.y)};
}
double At(Vec2 a, int axis) { return axis == 0 ? a.x : a.y; }

PlanRateResponse Evaluate(const UncoupledPair& pair, const PlanLawPhase& phase, Vec2 u, Vec2 v,
                          const double* q, double t) {
  PlanRateResponse r;
  for (const int axis : {0, 1}) {
    const Side side = SideOf(pair, axis);
    const int i = side.q0;
    const double z = side.count > 0 ? q[i] : 0.0, w = side.count > 1 ? q[i + 1] : 0.0;
    const RateResponse one = EvaluateRate(side.kernel, axis == 0 ? phase.along_x : phase.along_y,
                                          At(u, axis), At(v, axis), z, w, t);
    (axis == 0 ? r.force.x : r.force.y) = one.force;
    (axis == 0 ? r.force_u.xx : r.force_u.yy) = one.force_u;
    (axis == 0 ? r.force_v.xx : r.force_v.yy) = one.force_v;
    r.hysteretic_power += one.hysteretic_power;
    r.viscous_power += one.viscous_power;
    if (side.count > 0) {
      r.force_q[axis][i] = one.force_z;
      r.rate[i] = one.rate;
      r.rate_u[i][axis] = one.rate_u;
      r.rate_v[i][axis] = one.rate_v;
      r.rate_q[i][i] = one.rate_z;
    }
    if (side.count > 1) {
      r.force_q[axis][i + 1] = one.force_w;
      r.rate_q[i][i + 1] = one.rate_w;
      r.rate[i + 1] = one.w_rate;
      r.rate_u[i + 1][axis] = one.w_rate_u;
      r.rate_v[i + 1][axis] = one.w_rate_v;
      r.rate_q[i + 1][i] = one.w_rate_z;
      r.rate_q[i + 1][i + 1] = one.w_rate_w;
    }
  }
  return r;
}

void Roots(const UncoupledPair& pair, const PlanLawPhase& phase, Vec2 u, Vec2 v, const double* q,
           double* roots) {
  for (const int axis : {0, 1}) {
    const Side side = SideOf(pair, axis);
    PhaseRoots(side.kernel, axis == 0 ? phase.along_x : phase.along_y, At(u, axis), At(v, axis),
               side.count > 0 ? q[side.q0] : 0.0, roots + side.root0);
  }
}

void Switch(const UncoupledPair& pair, int root, Vec2 u, Vec2 v, PlanPhaseSwitch* next) {
  const int axis = root < PhaseRootCount(pair.x) ? 0 : 1;
  const Side side = SideOf(pair, axis);
  LawPhase& phase = axis == 0 ? next->phase.along_x : next->phase.along_y;
  const PhaseSwitch one = SwitchPhase(side.kernel, phase, root - side.root0, At(u, axis),
                                      At(v, axis), side.count > 0 ? next->q[side.q0] : 0.0);
  phase = one.phase;
  if (side.count > 0) next->q[side.q0] = one.z;
}

}  // namespace

bool HasRateForm(const PlanLawKernel& kernel) {
  if (std::holds_alternative<PlanSeriesArrangement>(kernel)) return false;
  const auto* pair = std::get_if<UncoupledPair>(&kernel);
  return pair == nullptr || (HasRateForm(pair->x) && HasRateForm(pair->y));
}

int PlanInternalVariableCount(const PlanLawKernel& kernel) {
  if (std::holds_alternative<PlanElasticSpring>(kernel) ||
      std::holds_alternative<PlanDashpot>(kernel) ||
      std::holds_alternative<PlanSeriesArrangement>(kernel)) {
    return 0;
  }
  if (const auto* law = std::get_if<PlanLeadRubber>(&kernel)) {
    return law->law.heating.heats() ? 3 : 2;
  }
  if (const auto* pair = std::get_if<UncoupledPair>(&kernel)) {
    return InternalVariableCount(pair->x) + InternalVariableCount(pair->y);
  }
  return 2;
}

int PlanPhaseRootCount(const PlanLawKernel& kernel) {
  if (const auto* pair = std::get_if<UncoupledPair>(&kernel)) {
    return PhaseRootCount(pair->x) + PhaseRootCount(pair->y);
  }
  if (std::holds_alternative<PlanSeriesSlider>(kernel) ||
      std::holds_alternative<PlanParallelSlider>(kernel) ||
      std::holds_alternative<PlanFrictionPendulum>(kernel)) {
    return 2;
  }
  return std::holds_alternative<PlanElasticSpring>(kernel) ||
                 std::holds_alternative<PlanLeadRubber>(kernel)
             ? 1
             : 0;
}

PlanLawPhase PlanRestPhase(const PlanLawKernel& kernel) {
  PlanLawPhase phase;
  if (const auto* law = std::get_if<PlanSeriesSlider>(&kernel))
    phase.slip = law->law.fs > 0 ? 0 : 1;
  if (const auto* law = std::get_if<PlanParallelSlider>(&kernel)) {
    phase.slip = law->law.fs > 0 ? 0 : 1;
  }
  if (const auto* pair = std::get_if<UncoupledPair>(&kernel)) {
    phase.along_x = RestPhase(pair->x);
    phase.along_y = RestPhase(pair->y);
  }
  return phase;
}

PlanRateResponse EvaluatePlanRate(const PlanLawKernel& kernel, const PlanLawPhase& phase, Vec2 u,
                                  Vec2 v, const double* q, double t) {
  return std::visit([&](const auto& law) { return Evaluate(law, phase, u, v, q, t); }, kernel);
}

void PlanPhaseRoots(const PlanLawKernel& kernel, const PlanLawPhase& phase, Vec2 u, Vec2 v,
                    const double* q, double* roots) {
  std::visit([&](const auto& law) { Roots(law, phase, u, v, q, roots); }, kernel);
}

PlanPhaseSwitch SwitchPlanPhase(const PlanLawKernel& kernel, const PlanLawPhase& phase, int root,
                                Vec2 u, Vec2 v, const double* q) {
  PlanPhaseSwitch next{phase, {}};
  for (int i = 0; i < PlanInternalVariableCount(kernel); ++i) next.q[i] = q[i];
  std::visit([&](const auto& law) { Switch(law, root, u, v, &next); }, kernel);
  return next;
}

PlanLawState PlanRateFormState(const PlanLawKernel& kernel, const PlanLawPhase& phase, Vec2 u,
                               Vec2 v, const double* q, double t) {
  PlanLawState state;
  if (const auto* pair = std::get_if<UncoupledPair>(&kernel)) {
    for (const int axis : {0, 1}) {
      const Side side = SideOf(*pair, axis);
      (axis == 0 ? state.x : state.y) = RateFormState(
          side.kernel, axis == 0 ? phase.along_x : phase.along_y, At(u, axis), At(v, axis),
          side.count > 0 ? q[side.q0] : 0.0, side.count > 1 ? q[side.q0 + 1] : 0.0, t);
    }
    return state;
  }
  CoupledState c;
  c.force = EvaluatePlanRate(kernel, phase, u, v, q, t).force;
  if (std::holds_alternative<PlanSeriesSlider>(kernel) ||
      std::holds_alternative<PlanParallelSlider>(kernel) ||
      std::holds_alternative<PlanFrictionPendulum>(kernel) ||
      std::holds_alternative<PlanLeadRubber>(kernel)) {
    c.slider = VectorAt(q);
  }
  if (PlanInternalVariableCount(kernel) == 3) c.temperature = q[2];
  Store({u, v, t}, c, &state);
  return state;
}

}  // namespace isolab::hysteresis
