#include "dof_rows.h"

namespace isolab::integrators {

using structure::SlotOf;
using structure::SparseMatrix;

void DofRows::AddEntries(std::vector<Eigen::Triplet<double>>* entries) const {
  const int v0 = dofs_;
  for (int i = 0; i < dofs_; ++i) {
    entries->emplace_back(i, i, 0.0);
    entries->emplace_back(i, v0 + i, 0.0);
    entries->emplace_back(v0 + i, v0 + i, 0.0);
  }
  for (int col = 0; col < damping_.outerSize(); ++col) {
    for (SparseMatrix::InnerIterator it(damping_, col); it; ++it) {
      entries->emplace_back(v0 + static_cast<int>(it.row()), v0 + col, 0.0);
    }
  }
}

void DofRows::FindSlots(const SparseMatrix& pattern) {
  const int v0 = dofs_;
  for (int i = 0; i < dofs_; ++i) {
    uu_slots_.push_back(SlotOf(pattern, i, i));
    uv_slots_.push_back(SlotOf(pattern, i, v0 + i));
    mass_slots_.push_back(SlotOf(pattern, v0 + i, v0 + i));
  }
  for (int col = 0; col < damping_.outerSize(); ++col) {
    for (SparseMatrix::InnerIterator it(damping_, col); it; ++it) {
      damping_slots_.push_back(SlotOf(pattern, v0 + static_cast<int>(it.row()), v0 + col));
    }
  }
}

void DofRows::AddJacobian(double cj, const Eigen::VectorXd& mass, double* values) const {
  for (int i = 0; i < dofs_; ++i) {
    values[uu_slots_[i]] += cj;
    values[uv_slots_[i]] -= 1.0;
    values[mass_slots_[i]] += cj * mass[i];
  }
  const double* c = damping_.valuePtr();
  for (std::size_t k = 0; k < damping_slots_.size(); ++k) values[damping_slots_[k]] += c[k];
}

void DofRows::Residual(const double* y, const double* yp, const Eigen::VectorXd& mass,
                       const Eigen::VectorXd& force, const Eigen::VectorXd& load,
                       double* residual) const {
  for (int i = 0; i < dofs_; ++i) {
    residual[i] = yp[i] - y[dofs_ + i];
    residual[dofs_ + i] = mass[i] * yp[dofs_ + i] + force[i] - load[i];
  }
}

void DofRows::Derivative(const double* y, const Eigen::VectorXd& mass, const Eigen::VectorXd& force,
                         const Eigen::VectorXd& load, double* yp) const {
  for (int i = 0; i < dofs_; ++i) {
    yp[i] = y[dofs_ + i];
    yp[dofs_ + i] = (load[i] - force[i]) / mass[i];
  }
}

Energies DofRows::EnergiesAt(const double* energy_integrals, const Eigen::VectorXd& velocity,
                             const Eigen::VectorXd& mass, double elastic) {
  Energies e;
  e.input = energy_integrals[kInputPower];
  e.damping = energy_integrals[kDampingPower];
  e.hysteretic = energy_integrals[kHystereticPower];
  e.kinetic = 0.5 * velocity.dot(mass.cwiseProduct(velocity));
  e.elastic = elastic;
  return e;
}

ResponseRow DofRows::Row(int step, double t, const double* y, const Eigen::VectorXd& acceleration,
                         const Eigen::VectorXd& absolute_acceleration,
                         std::span<const double> connection_forces,
                         std::span<const double> law_forces, const Energies& energies) const {
  const std::size_t n = static_cast<std::size_t>(dofs_);
  return {step,
          t,
          {y, n},
          {y + dofs_, n},
          {acceleration.data(), n},
          {absolute_acceleration.data(), n},
          connection_forces,
          law_forces,
          energies};
}

}  // namespace isolab::integrators
