#include "rate_form_system.h"

namespace isolab::integrators {

using hysteresis::RateResponse;
using structure::kGround;
using structure::SlotOf;

RateFormSystem::RateFormSystem(const structure::Structure& structure, const Excitation& excitation)
    : structure_(structure),
      excitation_(excitation),
      dofs_(structure.dofs()),
      dof_rows_(dofs_, structure.viscous_damping()) {
  const auto& connections = structure.connections();
  root_offsets_.push_back(0);
  for (const auto& connection : connections) {
    for (const auto& kernel : connection.assembly.kernels()) {
      const int count = hysteresis::InternalVariableCount(kernel);
      internal_index_.push_back(count > 0 ? internal_count_++ : -1);
      second_index_.push_back(count > 1 ? internal_count_++ : -1);
      root_offsets_.push_back(root_offsets_.back() + hysteresis::PhaseRootCount(kernel));
      phases_.push_back(hysteresis::RestPhase(kernel));
    }
  }
  responses_.resize(phases_.size());
  connection_forces_.resize(connections.size());
  law_forces_.resize(phases_.size());
  acceleration_.setZero(dofs_);
  absolute_acceleration_.setZero(dofs_);
  load_.setZero(dofs_);
  force_.setZero(dofs_);
  viscous_.setZero(dofs_);
  velocity_.setZero(dofs_);

  // Column blocks: u at 0, v at n, z at 2n.
  const int n = dofs_, v0 = n, z0 = 2 * n;
  std::vector<Eigen::Triplet<double>> entries;
  const auto add = [&](int row, int col) { entries.emplace_back(row, col, 0.0); };
  dof_rows_.AddEntries(&entries);
  const auto scatter_pairs = [&](int row0, int col0, int i, int j) {
    add(row0 + j, col0 + j);
    if (i == kGround) return;
    add(row0 + i, col0 + i);
    add(row0 + i, col0 + j);
    add(row0 + j, col0 + i);
  };
  for (std::size_t k = 0; k < connections.size(); ++k) {
    const int i = connections[k].dof_i, j = connections[k].dof_j;
    scatter_pairs(v0, 0, i, j);
    scatter_pairs(v0, v0, i, j);
    for (std::size_t l = 0; l < connections[k].assembly.size(); ++l) {
      const int z = internal_index_[structure.law_offset(k) + l];
      if (z < 0) continue;
      for (const int row : {v0 + j, z0 + z}) add(row, z0 + z);
      add(z0 + z, j);
      add(z0 + z, v0 + j);
      if (i != kGround) {
        add(v0 + i, z0 + z);
        add(z0 + z, i);
        add(z0 + z, v0 + i);
      }
      const int w = second_index_[structure.law_offset(k) + l];
      if (w < 0) continue;
      for (const int row : {v0 + j, z0 + z, z0 + w}) add(row, z0 + w);
      for (const int col : {j, v0 + j, z0 + z}) add(z0 + w, col);
      if (i != kGround) {
        add(v0 + i, z0 + w);
        add(z0 + w, i);
        add(z0 + w, v0 + i);
      }
    }
  }
  pattern_.resize(size(), size());
  pattern_.setFromTriplets(entries.begin(), entries.end());
  pattern_.makeCompressed();

  dof_rows_.FindSlots(pattern_);
  internal_slots_.resize(phases_.size());
  for (std::size_t k = 0; k < connections.size(); ++k) {
    const int i = connections[k].dof_i, j = connections[k].dof_j;
    ConnectionSlots s;
    s.vu_jj = SlotOf(pattern_, v0 + j, j);
    s.vv_jj = SlotOf(pattern_, v0 + j, v0 + j);
    if (i != kGround) {
      s.vu_ii = SlotOf(pattern_, v0 + i, i);
      s.vu_ij = SlotOf(pattern_, v0 + i, j);
      s.vu_ji = SlotOf(pattern_, v0 + j, i);
      s.vv_ii = SlotOf(pattern_, v0 + i, v0 + i);
      s.vv_ij = SlotOf(pattern_, v0 + i, v0 + j);
      s.vv_ji = SlotOf(pattern_, v0 + j, v0 + i);
    }
    connection_slots_.push_back(s);
    for (std::size_t l = 0; l < connections[k].assembly.size(); ++l) {
      const std::size_t law = structure.law_offset(k) + l;
      const int z = internal_index_[law];
      if (z < 0) continue;
      InternalSlots& t = internal_slots_[law];
      t.vz_j = SlotOf(pattern_, v0 + j, z0 + z);
      t.zu_j = SlotOf(pattern_, z0 + z, j);
      t.zv_j = SlotOf(pattern_, z0 + z, v0 + j);
      t.zz = SlotOf(pattern_, z0 + z, z0 + z);
      if (i != kGround) {
        t.vz_i = SlotOf(pattern_, v0 + i, z0 + z);
        t.zu_i = SlotOf(pattern_, z0 + z, i);
        t.zv_i = SlotOf(pattern_, z0 + z, v0 + i);
      }
      const int w = second_index_[law];
      if (w < 0) continue;
      t.vw_j = SlotOf(pattern_, v0 + j, z0 + w);
      t.zw = SlotOf(pattern_, z0 + z, z0 + w);
      t.wu_j = SlotOf(pattern_, z0 + w, j);
      t.wv_j = SlotOf(pattern_, z0 + w, v0 + j);
      t.wz = SlotOf(pattern_, z0 + w, z0 + z);
      t.ww = SlotOf(pattern_, z0 + w, z0 + w);
      if (i != kGround) {
        t.vw_i = SlotOf(pattern_, v0 + i, z0 + w);
        t.wu_i = SlotOf(pattern_, z0 + w, i);
        t.wv_i = SlotOf(pattern_, z0 + w, v0 + i);
      }
    }
  }
}

RateFormSystem::LawInput RateFormSystem::InputOf(std::size_t connection, std::size_t law,
                                                 const double* y) const {
  const auto& c = structure_.connections()[connection];
  const double* u = y;
  const double* v = y + dofs_;
  const bool grounded = c.dof_i == kGround;
  const int z = internal_index_[law], w = second_index_[law];
  return {u[c.dof_j] - (grounded ? 0.0 : u[c.dof_i]), v[c.dof_j] - (grounded ? 0.0 : v[c.dof_i]),
          z >= 0 ? y[2 * dofs_ + z] : 0.0, w >= 0 ? y[2 * dofs_ + w] : 0.0};
}

void RateFormSystem::EvaluateLaws(double t, const double* y) {
  velocity_ = Eigen::Map<const Eigen::VectorXd>(y + dofs_, dofs_);
  viscous_.noalias() = structure_.viscous_damping() * velocity_;
  force_ = viscous_;
  const auto& connections = structure_.connections();
  for (std::size_t k = 0; k < connections.size(); ++k) {
    const auto& kernels = connections[k].assembly.kernels();
    double total = 0.0;
    for (std::size_t l = 0; l < kernels.size(); ++l) {
      const std::size_t law = structure_.law_offset(k) + l;
      const LawInput in = InputOf(k, law, y);
      responses_[law] =
          hysteresis::EvaluateRate(kernels[l], phases_[law], in.u, in.v, in.z, in.w, t);
      total += responses_[law].force;
    }
    connection_forces_[k] = total;
    force_[connections[k].dof_j] += total;
    if (connections[k].dof_i != kGround) force_[connections[k].dof_i] -= total;
  }
}

void RateFormSystem::Residual(double t, const double* y, const double* yp, double* residual) {
  EvaluateLaws(t, y);
  excitation_.EffectiveLoad(t, structure_.mass(), &load_);
  dof_rows_.Residual(y, yp, structure_.mass(), force_, load_, residual);
  for (std::size_t law = 0; law < internal_index_.size(); ++law) {
    const int z = internal_index_[law], w = second_index_[law];
    if (z >= 0) residual[2 * dofs_ + z] = yp[2 * dofs_ + z] - responses_[law].rate;
    if (w >= 0) residual[2 * dofs_ + w] = yp[2 * dofs_ + w] - responses_[law].w_rate;
  }
}

void RateFormSystem::Jacobian(double t, double cj, const double* y, double* values) {
  EvaluateLaws(t, y);
  std::fill(values, values + pattern_.nonZeros(), 0.0);
  dof_rows_.AddJacobian(cj, structure_.mass(), values);

  const auto& connections = structure_.connections();
  for (std::size_t k = 0; k < connections.size(); ++k) {
    const bool grounded = connections[k].dof_i == kGround;
    const ConnectionSlots& s = connection_slots_[k];
    double stiffness = 0.0, damping = 0.0;
    for (std::size_t l = 0; l < connections[k].assembly.size(); ++l) {
      const std::size_t law = structure_.law_offset(k) + l;
      const RateResponse& r = responses_[law];
      stiffness += r.force_u;
      damping += r.force_v;
      if (internal_index_[law] < 0) continue;
      const InternalSlots& slots = internal_slots_[law];
      values[slots.vz_j] += r.force_z;
      values[slots.zu_j] -= r.rate_u;
      values[slots.zv_j] -= r.rate_v;
      values[slots.zz] += cj - r.rate_z;
      if (!grounded) {
        values[slots.vz_i] -= r.force_z;
        values[slots.zu_i] += r.rate_u;
        values[slots.zv_i] += r.rate_v;
      }
      if (second_index_[law] < 0) continue;
      values[slots.vw_j] += r.force_w;
      values[slots.zw] -= r.rate_w;
      values[slots.wu_j] -= r.w_rate_u;
      values[slots.wv_j] -= r.w_rate_v;
      values[slots.wz] -= r.w_rate_z;
      values[slots.ww] += cj - r.w_rate_w;
      if (!grounded) {
        values[slots.vw_i] -= r.force_w;
        values[slots.wu_i] += r.w_rate_u;
        values[slots.wv_i] += r.w_rate_v;
      }
    }
    values[s.vu_jj] += stiffness;
    values[s.vv_jj] += damping;
    if (!grounded) {
      values[s.vu_ii] += stiffness;
      values[s.vu_ij] -= stiffness;
      values[s.vu_ji] -= stiffness;
      values[s.vv_ii] += damping;
      values[s.vv_ij] -= damping;
      values[s.vv_ji] -= damping;
    }
  }
}

void RateFormSystem::Roots(const double* y, double* roots) const {
  const auto& connections = structure_.connections();
  for (std::size_t k = 0; k < connections.size(); ++k) {
    const auto& kernels = connections[k].assembly.kernels();
    for (std::size_t l = 0; l < kernels.size(); ++l) {
      const std::size_t law = structure_.law_offset(k) + l;
      if (root_offsets_[law] == root_offsets_[law + 1]) continue;
      const LawInput in = InputOf(k, law, y);
      hysteresis::PhaseRoots(kernels[l], phases_[law], in.u, in.v, in.z,
                             roots + root_offsets_[law]);
    }
  }
}

int RateFormSystem::SwitchPhases(const int* roots_found, double* y) {
  int switched = 0;
  const auto& connections = structure_.connections();
  for (std::size_t k = 0; k < connections.size(); ++k) {
    const auto& kernels = connections[k].assembly.kernels();
    for (std::size_t l = 0; l < kernels.size(); ++l) {
      const std::size_t law = structure_.law_offset(k) + l;
      const int count = root_offsets_[law + 1] - root_offsets_[law];
      const auto apply = [&](int root) {
        const LawInput in = InputOf(k, law, y);
        const hysteresis::PhaseSwitch next =
            hysteresis::SwitchPhase(kernels[l], phases_[law], root, in.u, in.v, in.z);
        const bool changed = !(next.phase == phases_[law]);
        phases_[law] = next.phase;
        if (internal_index_[law] >= 0) y[2 * dofs_ + internal_index_[law]] = next.z;
        switched += changed;
        return changed;
      };
      bool any = false;
      for (int root = 0; root < count; ++root) {
        if (roots_found[root_offsets_[law] + root] != 0) any |= apply(root);
      }
      // A switch can leave another of the law's roots already below zero (two boundaries met
      // at once, e.g. slip ending exactly at +-uc): IDA would never see it fall, so it is
      // applied here, a bounded number of times.
      for (int pass = 0; any && pass < 2 * hysteresis::kMaxPhaseRoots; ++pass) {
        double roots[hysteresis::kMaxPhaseRoots];
        const LawInput in = InputOf(k, law, y);
        hysteresis::PhaseRoots(kernels[l], phases_[law], in.u, in.v, in.z, roots);
        any = false;
        for (int root = 0; root < count && !any; ++root) {
          if (roots[root] < 0.0) any = apply(root);
        }
      }
    }
  }
  return switched;
}

void RateFormSystem::ConsistentDerivative(double t, const double* y, double* yp) {
  EvaluateLaws(t, y);
  excitation_.EffectiveLoad(t, structure_.mass(), &load_);
  dof_rows_.Derivative(y, structure_.mass(), force_, load_, yp);
  for (std::size_t law = 0; law < internal_index_.size(); ++law) {
    const int z = internal_index_[law], w = second_index_[law];
    if (z >= 0) yp[2 * dofs_ + z] = responses_[law].rate;
    if (w >= 0) yp[2 * dofs_ + w] = responses_[law].w_rate;
  }
}

void RateFormSystem::EnergyRates(double t, const double* y, double* rates) {
  EvaluateLaws(t, y);
  excitation_.EffectiveLoad(t, structure_.mass(), &load_);
  DofRows::PowerRates(load_, velocity_, viscous_, responses_, rates);
}

ResponseRow RateFormSystem::Record(int step, double t, const double* y,
                                   const double* energy_integrals) {
  const Eigen::VectorXd& m = structure_.mass();
  EvaluateLaws(t, y);
  excitation_.EffectiveLoad(t, m, &load_);
  const double ground = excitation_.ground_acceleration.At(t);
  acceleration_ = (load_ - force_).cwiseQuotient(m);
  absolute_acceleration_ = acceleration_.array() + ground;
  double elastic = 0.0;
  const auto& connections = structure_.connections();
  for (std::size_t k = 0; k < connections.size(); ++k) {
    const auto& kernels = connections[k].assembly.kernels();
    for (std::size_t l = 0; l < kernels.size(); ++l) {
      const std::size_t law = structure_.law_offset(k) + l;
      const LawInput in = InputOf(k, law, y);
      law_forces_[law] = responses_[law].force;
      elastic += hysteresis::StoredEnergy(
          kernels[l],
          hysteresis::RateFormState(kernels[l], phases_[law], in.u, in.v, in.z, in.w, t));
    }
  }
  return dof_rows_.Row(step, t, y, acceleration_, absolute_acceleration_, connection_forces_,
                       law_forces_, DofRows::EnergiesAt(energy_integrals, velocity_, m, elastic));
}

}  // namespace isolab::integrators
