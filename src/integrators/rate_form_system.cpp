#include "rate_form_system.h"

#include <algorithm>

namespace isolab::integrators {

using structure::SlotOf;

void RateFormSystem::AddLaw(LawBlock law, const hysteresis::LawKernel& kernel) {
  law.plan = false;
  law.kernel = static_cast<int>(member_kernels_.size());
  member_kernels_.push_back(&kernel);
  member_phases_.push_back(hysteresis::RestPhase(kernel));
  AddBlock(law, hysteresis::InternalVariableCount(kernel), hysteresis::PhaseRootCount(kernel));
}

void RateFormSystem::AddLaw(LawBlock law, const hysteresis::PlanLawKernel& kernel) {
  law.plan = true;
  law.kernel = static_cast<int>(plan_kernels_.size());
  plan_kernels_.push_back(&kernel);
  plan_phases_.push_back(hysteresis::PlanRestPhase(kernel));
  AddBlock(law, hysteresis::PlanInternalVariableCount(kernel),
           hysteresis::PlanPhaseRootCount(kernel));
}

void RateFormSystem::AddBlock(LawBlock law, int q_count, int roots) {
  law.q0 = internal_count_;
  law.q_count = q_count;
  law.root0 = root_count_;
  law.roots = roots;
  internal_count_ += q_count;
  root_count_ += roots;
  laws_.push_back(law);
}

RateFormSystem::RateFormSystem(const structure::Structure& structure, const Excitation& excitation)
    : structure_(structure),
      excitation_(excitation),
      mass_influence_(excitation.MassInfluence(structure.mass())),
      dofs_(structure.dofs()),
      dof_rows_(dofs_, structure.viscous_damping()) {
  for (std::size_t slot = 0; slot < structure.slots(); ++slot) {
    // The slot's map G (r x m) from its influence: the same operator Newmark's Evaluate applies.
    const structure::Structure::Influence influence = structure.SlotInfluence(slot);
    LawBlock law;
    law.rows = structure.slot_width(slot);
    law.terms = influence.count;
    for (int a = 0; a < influence.count; ++a) {
      law.dofs[a] = influence.dofs[a];
      law.map[0][a] = influence.columns[a].x;
      law.map[1][a] = influence.columns[a].y;
    }
    law.force_column = static_cast<int>(structure.slot_force_column(slot));
    structure.VisitSlotAssembly(slot, [&](const auto& assembly) {
      for (std::size_t c = 0; c < assembly.kernels().size(); ++c) {
        law.law_column = static_cast<int>(structure.slot_law_offset(slot) + law.rows * c);
        AddLaw(law, assembly.kernels()[c]);
      }
    });
  }
  responses_.resize(laws_.size());
  connection_forces_.resize(structure.force_columns());
  law_forces_.resize(structure.law_count());
  for (Eigen::VectorXd* x :
       {&load_, &force_, &viscous_, &velocity_, &acceleration_, &absolute_acceleration_}) {
    x->setZero(dofs_);
  }

  // Column blocks: u at 0, v at n, q at 2n. Each law's block: rows (its dofs' v rows, its q
  // rows) x columns (its dofs' u and v columns, its q columns).
  const int n = dofs_, v0 = n, q0 = 2 * n;
  const auto rows_of = [&](const LawBlock& law, int a) {
    return a < law.terms ? v0 + law.dofs[a] : q0 + law.q0 + (a - law.terms);
  };
  const auto columns_of = [&](const LawBlock& law, int b) {
    if (b < law.terms) return law.dofs[b];
    if (b < 2 * law.terms) return v0 + law.dofs[b - law.terms];
    return q0 + law.q0 + (b - 2 * law.terms);
  };
  std::vector<Eigen::Triplet<double>> entries;
  dof_rows_.AddEntries(&entries);
  for (const LawBlock& law : laws_) {
    for (int a = 0; a < law.terms + law.q_count; ++a) {
      for (int b = 0; b < 2 * law.terms + law.q_count; ++b) {
        entries.emplace_back(rows_of(law, a), columns_of(law, b), 0.0);
      }
    }
  }
  pattern_.resize(size(), size());
  pattern_.setFromTriplets(entries.begin(), entries.end());
  pattern_.makeCompressed();

  dof_rows_.FindSlots(pattern_);
  for (LawBlock& law : laws_) {
    law.slot0 = static_cast<int>(law_slots_.size());
    for (int a = 0; a < law.terms + law.q_count; ++a) {
      for (int b = 0; b < 2 * law.terms + law.q_count; ++b) {
        law_slots_.push_back(SlotOf(pattern_, rows_of(law, a), columns_of(law, b)));
      }
    }
  }
}

void RateFormSystem::Deformation(const LawBlock& law, const double* y,
                                 std::array<double, kMaxRows>* u,
                                 std::array<double, kMaxRows>* v) const {
  for (int i = 0; i < law.rows; ++i) {
    double d = 0.0, rate = 0.0;
    for (int a = 0; a < law.terms; ++a) {
      d += law.map[i][a] * y[law.dofs[a]];
      rate += law.map[i][a] * y[dofs_ + law.dofs[a]];
    }
    (*u)[i] = d;
    (*v)[i] = rate;
  }
}

RateFormSystem::BlockResponse RateFormSystem::EvaluateLaw(const LawBlock& law, double t,
                                                          const double* y) const {
  std::array<double, kMaxRows> u{}, v{};
  Deformation(law, y, &u, &v);
  const double* q = y + 2 * dofs_ + law.q0;
  BlockResponse b;
  if (law.plan) {
    const hysteresis::PlanRateResponse r = hysteresis::EvaluatePlanRate(
        *plan_kernels_[law.kernel], plan_phases_[law.kernel], {u[0], u[1]}, {v[0], v[1]}, q, t);
    b.force = {r.force.x, r.force.y};
    b.force_u = {{{r.force_u.xx, r.force_u.xy}, {r.force_u.yx, r.force_u.yy}}};
    b.force_v = {{{r.force_v.xx, r.force_v.xy}, {r.force_v.yx, r.force_v.yy}}};
    b.force_q = r.force_q;
    b.rate = r.rate;
    b.rate_u = r.rate_u;
    b.rate_v = r.rate_v;
    b.rate_q = r.rate_q;
    b.hysteretic_power = r.hysteretic_power;
    b.viscous_power = r.viscous_power;
    return b;
  }
  // A one-direction law: z then w as its q (rate_form.h).
  const double z = law.q_count > 0 ? q[0] : 0.0, w = law.q_count > 1 ? q[1] : 0.0;
  const hysteresis::RateResponse r = hysteresis::EvaluateRate(
      *member_kernels_[law.kernel], member_phases_[law.kernel], u[0], v[0], z, w, t);
  b.force[0] = r.force;
  b.force_u[0][0] = r.force_u;
  b.force_v[0][0] = r.force_v;
  b.force_q[0] = {r.force_z, r.force_w};
  b.rate = {r.rate, r.w_rate};
  b.rate_u[0][0] = r.rate_u;
  b.rate_u[1][0] = r.w_rate_u;
  b.rate_v[0][0] = r.rate_v;
  b.rate_v[1][0] = r.w_rate_v;
  b.rate_q[0] = {r.rate_z, r.rate_w};
  b.rate_q[1] = {r.w_rate_z, r.w_rate_w};
  b.hysteretic_power = r.hysteretic_power;
  b.viscous_power = r.viscous_power;
  return b;
}

void RateFormSystem::EvaluateLaws(double t, const double* y) {
  velocity_ = Eigen::Map<const Eigen::VectorXd>(y + dofs_, dofs_);
  structure_.DampingForce(velocity_, &viscous_);
  force_ = viscous_;
  std::fill(connection_forces_.begin(), connection_forces_.end(), 0.0);
  for (std::size_t l = 0; l < laws_.size(); ++l) {
    const LawBlock& law = laws_[l];
    responses_[l] = EvaluateLaw(law, t, y);
    for (int i = 0; i < law.rows; ++i) {
      const double f = responses_[l].force[i];
      connection_forces_[law.force_column + i] += f;
      law_forces_[law.law_column + i] = f;
      for (int a = 0; a < law.terms; ++a) force_[law.dofs[a]] += law.map[i][a] * f;
    }
  }
}

void RateFormSystem::Residual(double t, const double* y, const double* yp, double* residual) {
  EvaluateLaws(t, y);
  excitation_.EffectiveLoad(t, mass_influence_, &load_);
  dof_rows_.Residual(y, yp, structure_.mass(), force_, load_, residual);
  for (std::size_t l = 0; l < laws_.size(); ++l) {
    const int q0 = 2 * dofs_ + laws_[l].q0;
    for (int k = 0; k < laws_[l].q_count; ++k) {
      residual[q0 + k] = yp[q0 + k] - responses_[l].rate[k];
    }
  }
}

void RateFormSystem::Jacobian(double t, double cj, const double* y, double* values) {
  EvaluateLaws(t, y);
  std::fill(values, values + pattern_.nonZeros(), 0.0);
  dof_rows_.AddJacobian(cj, structure_.mass(), values);

  for (std::size_t l = 0; l < laws_.size(); ++l) {
    const LawBlock& law = laws_[l];
    const BlockResponse& r = responses_[l];
    const int m_terms = law.terms, width = 2 * m_terms + law.q_count;
    const int* slots = &law_slots_[law.slot0];
    // f_u G and f_v G (r x m), then the force rows: G^T (f_u G), G^T (f_v G), G^T f_q.
    std::array<std::array<double, kMaxTerms>, kMaxRows> ku{}, kv{};
    for (int i = 0; i < law.rows; ++i) {
      for (int b = 0; b < m_terms; ++b) {
        for (int j = 0; j < law.rows; ++j) {
          ku[i][b] += r.force_u[i][j] * law.map[j][b];
          kv[i][b] += r.force_v[i][j] * law.map[j][b];
        }
      }
    }
    for (int a = 0; a < m_terms; ++a) {
      const int* s = slots + a * width;
      for (int b = 0; b < m_terms; ++b) {
        double stiffness = 0.0, damping = 0.0;
        for (int i = 0; i < law.rows; ++i) {
          stiffness += law.map[i][a] * ku[i][b];
          damping += law.map[i][a] * kv[i][b];
        }
        values[s[b]] += stiffness;
        values[s[m_terms + b]] += damping;
      }
      for (int k = 0; k < law.q_count; ++k) {
        double coupling = 0.0;
        for (int i = 0; i < law.rows; ++i) coupling += law.map[i][a] * r.force_q[i][k];
        values[s[2 * m_terms + k]] += coupling;
      }
    }
    // The q rows: -r_u G, -r_v G, cj I - r_q.
    for (int k = 0; k < law.q_count; ++k) {
      const int* s = slots + (m_terms + k) * width;
      for (int b = 0; b < m_terms; ++b) {
        double rate_u = 0.0, rate_v = 0.0;
        for (int j = 0; j < law.rows; ++j) {
          rate_u += r.rate_u[k][j] * law.map[j][b];
          rate_v += r.rate_v[k][j] * law.map[j][b];
        }
        values[s[b]] -= rate_u;
        values[s[m_terms + b]] -= rate_v;
      }
      for (int l2 = 0; l2 < law.q_count; ++l2) {
        values[s[2 * m_terms + l2]] += (k == l2 ? cj : 0.0) - r.rate_q[k][l2];
      }
    }
  }
}

void RateFormSystem::LawRoots(const LawBlock& law, const double* y, double* roots) const {
  std::array<double, kMaxRows> u{}, v{};
  Deformation(law, y, &u, &v);
  const double* q = y + 2 * dofs_ + law.q0;
  if (law.plan) {
    hysteresis::PlanPhaseRoots(*plan_kernels_[law.kernel], plan_phases_[law.kernel], {u[0], u[1]},
                               {v[0], v[1]}, q, roots);
  } else {
    hysteresis::PhaseRoots(*member_kernels_[law.kernel], member_phases_[law.kernel], u[0], v[0],
                           law.q_count > 0 ? q[0] : 0.0, roots);
  }
}

void RateFormSystem::Roots(const double* y, double* roots) const {
  for (const LawBlock& law : laws_) {
    if (law.roots > 0) LawRoots(law, y, roots + law.root0);
  }
}

bool RateFormSystem::SwitchLaw(const LawBlock& law, int root, double* y) {
  std::array<double, kMaxRows> u{}, v{};
  Deformation(law, y, &u, &v);
  double* q = y + 2 * dofs_ + law.q0;
  if (law.plan) {
    const hysteresis::PlanPhaseSwitch next = hysteresis::SwitchPlanPhase(
        *plan_kernels_[law.kernel], plan_phases_[law.kernel], root, {u[0], u[1]}, {v[0], v[1]}, q);
    const bool changed = !(next.phase == plan_phases_[law.kernel]);
    plan_phases_[law.kernel] = next.phase;
    std::copy(next.q.begin(), next.q.begin() + law.q_count, q);
    return changed;
  }
  const hysteresis::PhaseSwitch next =
      hysteresis::SwitchPhase(*member_kernels_[law.kernel], member_phases_[law.kernel], root, u[0],
                              v[0], law.q_count > 0 ? q[0] : 0.0);
  const bool changed = !(next.phase == member_phases_[law.kernel]);
  member_phases_[law.kernel] = next.phase;
  if (law.q_count > 0) q[0] = next.z;
  return changed;
}

int RateFormSystem::SwitchPhases(const int* roots_found, double* y) {
  int switched = 0;
  for (const LawBlock& law : laws_) {
    bool any = false;
    for (int root = 0; root < law.roots; ++root) {
      if (roots_found[law.root0 + root] == 0) continue;
      const bool changed = SwitchLaw(law, root, y);
      switched += changed;
      any |= changed;
    }
    // A switch can leave another of the law's roots already below zero, which IDA would never
    // see fall: switched here too, a bounded number of times.
    for (int pass = 0; any && pass < 2 * hysteresis::kMaxPlanPhaseRoots; ++pass) {
      double roots[hysteresis::kMaxPlanPhaseRoots];
      LawRoots(law, y, roots);
      any = false;
      for (int root = 0; root < law.roots && !any; ++root) {
        if (roots[root] < 0.0) {
          any = SwitchLaw(law, root, y);
          switched += any;
        }
      }
    }
  }
  return switched;
}

void RateFormSystem::ConsistentDerivative(double t, const double* y, double* yp) {
  EvaluateLaws(t, y);
  excitation_.EffectiveLoad(t, mass_influence_, &load_);
  dof_rows_.Derivative(y, structure_.mass(), force_, load_, yp);
  for (std::size_t l = 0; l < laws_.size(); ++l) {
    const int q0 = 2 * dofs_ + laws_[l].q0;
    for (int k = 0; k < laws_[l].q_count; ++k) yp[q0 + k] = responses_[l].rate[k];
  }
}

void RateFormSystem::EnergyRates(double t, const double* y, double* rates) {
  EvaluateLaws(t, y);
  excitation_.EffectiveLoad(t, mass_influence_, &load_);
  DofRows::PowerRates(load_, velocity_, viscous_, responses_, rates);
}

double RateFormSystem::LawStoredEnergy(const LawBlock& law, double t, const double* y) const {
  std::array<double, kMaxRows> u{}, v{};
  Deformation(law, y, &u, &v);
  const double* q = y + 2 * dofs_ + law.q0;
  if (law.plan) {
    const auto& kernel = *plan_kernels_[law.kernel];
    return hysteresis::PlanStoredEnergy(
        kernel, hysteresis::PlanRateFormState(kernel, plan_phases_[law.kernel], {u[0], u[1]},
                                              {v[0], v[1]}, q, t));
  }
  const auto& kernel = *member_kernels_[law.kernel];
  return hysteresis::StoredEnergy(
      kernel,
      hysteresis::RateFormState(kernel, member_phases_[law.kernel], u[0], v[0],
                                law.q_count > 0 ? q[0] : 0.0, law.q_count > 1 ? q[1] : 0.0, t));
}

ResponseRow RateFormSystem::Record(int step, double t, const double* y,
                                   const double* energy_integrals) {
  const Eigen::VectorXd& m = structure_.mass();
  EvaluateLaws(t, y);
  excitation_.EffectiveLoad(t, mass_influence_, &load_);
  acceleration_ = (load_ - force_).cwiseQuotient(m);
  absolute_acceleration_ = acceleration_;
  excitation_.AddGroundAcceleration(t, absolute_acceleration_);
  double elastic = 0.0;
  for (const LawBlock& law : laws_) elastic += LawStoredEnergy(law, t, y);
  return dof_rows_.Row(step, t, y, acceleration_, absolute_acceleration_, connection_forces_,
                       law_forces_, DofRows::EnergiesAt(energy_integrals, velocity_, m, elastic));
}

}  // namespace isolab::integrators
