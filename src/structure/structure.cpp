#include "isolab/structure/structure.h"

#include <stdexcept>

namespace isolab::structure {
int SlotOf(const SparseMatrix& matrix, int row, int col) {
  for (int k = matrix.outerIndexPtr()[col]; k < matrix.outerIndexPtr()[col + 1]; ++k) {
    if (matrix.innerIndexPtr()[k] == row) return k;
  }
  throw std::logic_error("sparse pattern lacks an entry it was built with");
}

void ConstantTerms::AppendEntries(int dofs, const SparseMatrix& damping,
                                  std::vector<Eigen::Triplet<double>>* entries) {
  for (int i = 0; i < dofs; ++i) entries->emplace_back(i, i, 0.0);
  for (int col = 0; col < damping.outerSize(); ++col) {
    for (SparseMatrix::InnerIterator it(damping, col); it; ++it) {
      entries->emplace_back(it.row(), it.col(), 0.0);
    }
  }
}

ConstantTerms::ConstantTerms(int dofs, const SparseMatrix& damping, const SparseMatrix& pattern) {
  for (int i = 0; i < dofs; ++i) mass_slots_.push_back(SlotOf(pattern, i, i));
  for (int col = 0; col < damping.outerSize(); ++col) {
    for (SparseMatrix::InnerIterator it(damping, col); it; ++it) {
      damping_slots_.push_back(SlotOf(pattern, static_cast<int>(it.row()), col));
    }
  }
}

void ConstantTerms::Fill(const Eigen::VectorXd& mass, const SparseMatrix& damping,
                         const TangentFactors& factors, SparseMatrix* tangent) const {
  double* values = tangent->valuePtr();
  std::fill(values, values + tangent->nonZeros(), 0.0);
  for (std::size_t i = 0; i < mass_slots_.size(); ++i) {
    values[mass_slots_[i]] += factors.mass * mass[i];
  }
  const double* c = damping.valuePtr();
  for (std::size_t k = 0; k < damping_slots_.size(); ++k) {
    values[damping_slots_[k]] += factors.damping * c[k];
  }
}

Structure::Structure(Eigen::VectorXd mass, std::vector<Connection> connections,
                     SparseMatrix viscous_damping)
    : mass_(std::move(mass)),
      connections_(std::move(connections)),
      viscous_damping_(std::move(viscous_damping)) {
  const int n = dofs();
  for (int i = 0; i < n; ++i) {
    if (!(mass_[i] > 0.0)) {
      throw std::invalid_argument("the mass of dof " + std::to_string(i) + " must be > 0");
    }
  }
  viscous_damping_.makeCompressed();
  law_offsets_.push_back(0);
  for (const Connection& connection : connections_) {
    if (connection.dof_j < 0 || connection.dof_j >= n || connection.dof_i < kGround ||
        connection.dof_i >= n || connection.dof_i == connection.dof_j) {
      throw std::invalid_argument("connection '" + connection.name + "' joins invalid dofs");
    }
    law_offsets_.push_back(law_offsets_.back() + connection.assembly.state_size());
    for (const auto& kernel : connection.assembly.kernels()) {
      law_is_dashpot_.push_back(std::holds_alternative<hysteresis::Dashpot>(kernel));
    }
    law_is_dashpot_.resize(law_offsets_.back(), false);  // the further states of sliders in series
  }

  std::vector<Eigen::Triplet<double>> entries;
  ConstantTerms::AppendEntries(n, viscous_damping_, &entries);
  for (const Connection& connection : connections_) {
    if (connection.dof_i == kGround) continue;
    entries.emplace_back(connection.dof_i, connection.dof_j, 0.0);
    entries.emplace_back(connection.dof_j, connection.dof_i, 0.0);
  }
  pattern_.resize(n, n);
  pattern_.setFromTriplets(entries.begin(), entries.end());
  pattern_.makeCompressed();

  constant_terms_ = ConstantTerms(n, viscous_damping_, pattern_);
  for (const Connection& connection : connections_) {
    ConnectionSlots slots;
    slots.jj = SlotOf(pattern_, connection.dof_j, connection.dof_j);
    if (connection.dof_i != kGround) {
      slots.ii = SlotOf(pattern_, connection.dof_i, connection.dof_i);
      slots.ij = SlotOf(pattern_, connection.dof_i, connection.dof_j);
      slots.ji = SlotOf(pattern_, connection.dof_j, connection.dof_i);
    }
    connection_slots_.push_back(slots);
    constant_responses_.push_back(connection.assembly.ConstantTangent());
  }
}

void Structure::AddConnectionTangent(std::size_t connection, double k_eff, double* values) const {
  const ConnectionSlots& slots = connection_slots_[connection];
  values[slots.jj] += k_eff;
  if (slots.ii < 0) return;  // grounded
  values[slots.ii] += k_eff;
  values[slots.ij] -= k_eff;
  values[slots.ji] -= k_eff;
}

void Structure::ConstantTangent(const TangentFactors& factors, SparseMatrix* tangent) const {
  constant_terms_.Fill(mass_, viscous_damping_, factors, tangent);
  for (std::size_t k = 0; k < connections_.size(); ++k) {
    if (const auto& constant = constant_responses_[k]) {
      AddConnectionTangent(k, constant->stiffness + factors.damping * constant->damping,
                           tangent->valuePtr());
    }
  }
}

void Structure::Evaluate(std::span<const hysteresis::LawState> committed, double t,
                         const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                         std::span<hysteresis::LawState> trial,
                         std::span<hysteresis::LawResponse> responses, Eigen::VectorXd* force,
                         std::span<double> connection_forces, const TangentFactors& factors,
                         SparseMatrix* tangent) const {
  force->noalias() = viscous_damping_ * v;
  double* values = tangent ? tangent->valuePtr() : nullptr;
  for (std::size_t k = 0; k < connections_.size(); ++k) {
    const Connection& connection = connections_[k];
    const bool grounded = connection.dof_i == kGround;
    const hysteresis::LawInput in{u[connection.dof_j] - (grounded ? 0.0 : u[connection.dof_i]),
                                  v[connection.dof_j] - (grounded ? 0.0 : v[connection.dof_i]), t};
    const std::size_t offset = law_offsets_[k];
    const std::size_t count = connection.assembly.state_size();
    const hysteresis::AssemblyResponse total =
        connection.assembly.Update(committed.subspan(offset, count), in,
                                   trial.subspan(offset, count), responses.subspan(offset, count));
    connection_forces[k] = total.force;
    (*force)[connection.dof_j] += total.force;
    if (!grounded) (*force)[connection.dof_i] -= total.force;
    if (values && !constant_responses_[k]) {
      AddConnectionTangent(k, total.stiffness + factors.damping * total.damping, values);
    }
  }
}

double Structure::StoredEnergy(std::span<const hysteresis::LawState> states) const {
  double energy = 0.0;
  for (std::size_t k = 0; k < connections_.size(); ++k) {
    energy += connections_[k].assembly.StoredEnergy(
        states.subspan(law_offsets_[k], connections_[k].assembly.state_size()));
  }
  return energy;
}

double Structure::DashpotEnergy(std::span<const hysteresis::LawState> states) const {
  double energy = 0.0;
  for (std::size_t i = 0; i < states.size(); ++i) {
    if (law_is_dashpot_[i]) energy += states[i].dissipated;
  }
  return energy;
}

double Structure::HystereticEnergy(std::span<const hysteresis::LawState> states) const {
  double energy = 0.0;
  for (std::size_t i = 0; i < states.size(); ++i) {
    if (!law_is_dashpot_[i]) energy += states[i].dissipated;
  }
  return energy;
}

}  // namespace isolab::structure
