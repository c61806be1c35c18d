// What the rate-form system (rate_form_system.h) writes for the structure's
// dofs whatever its laws: the rows u' - v = 0 and M v' + C v + f - p = 0 (M diagonal), their
// constant Jacobian entries (cj I and -I in the u rows, cj M and C in the v rows) at slots of the
// system's fixed pattern, y' consistent with y, and the response row the observer sees. y holds
// u at 0 and v at dofs; the laws' rows and columns follow and are the system's own business.
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "isolab/integrators/response.h"
#include "isolab/structure/structure.h"

namespace isolab::integrators {

// Accumulated energy terms, integrated by the integrator alongside y.
enum EnergyRate { kInputPower, kDampingPower, kHystereticPower, kEnergyRates };

class DofRows {
 public:
  DofRows(int dofs, const structure::SparseMatrix& damping) : dofs_(dofs), damping_(damping) {}

  // The positions of the constant entries, for the system's pattern.
  void AddEntries(std::vector<Eigen::Triplet<double>>* entries) const;
  // Their slots once the pattern is compressed.
  void FindSlots(const structure::SparseMatrix& pattern);
  // Adds the constant entries of dF/dy + cj dF/dy' to `values` (in the pattern's order).
  void AddJacobian(double cj, const Eigen::VectorXd& mass, double* values) const;

  // The dofs' rows of the residual, from the resisting force C v + f and the load p.
  void Residual(const double* y, const double* yp, const Eigen::VectorXd& mass,
                const Eigen::VectorXd& force, const Eigen::VectorXd& load, double* residual) const;
  // The dofs' part of y' consistent with y: u' = v, v' = M^-1 (p - C v - f).
  void Derivative(const double* y, const Eigen::VectorXd& mass, const Eigen::VectorXd& force,
                  const Eigen::VectorXd& load, double* yp) const;

  // The energy rates at a state: input power p . v, and damping (C v . v plus the laws'
  // viscous power) and hysteretic power summed over `responses` (each with viscous_power and
  // hysteretic_power).
  template <typename Responses>
  static void PowerRates(const Eigen::VectorXd& load, const Eigen::VectorXd& velocity,
                         const Eigen::VectorXd& viscous, const Responses& responses,
                         double* rates) {
    rates[kInputPower] = load.dot(velocity);
    double damping = velocity.dot(viscous);
    double hysteretic = 0.0;
    for (const auto& r : responses) {
      damping += r.viscous_power;
      hysteretic += r.hysteretic_power;
    }
    rates[kDampingPower] = damping;
    rates[kHystereticPower] = hysteretic;
  }
  // The energies at the row: the integrals so far, the kinetic energy of `velocity`, and
  // `elastic`.
  static Energies EnergiesAt(const double* energy_integrals, const Eigen::VectorXd& velocity,
                             const Eigen::VectorXd& mass, double elastic);
  // The row viewing y, the accelerations and the forces (valid while they are).
  ResponseRow Row(int step, double t, const double* y, const Eigen::VectorXd& acceleration,
                  const Eigen::VectorXd& absolute_acceleration,
                  std::span<const double> connection_forces, std::span<const double> law_forces,
                  const Energies& energies) const;

 private:
  int dofs_;
  const structure::SparseMatrix& damping_;
  std::vector<int> uu_slots_, uv_slots_, mass_slots_, damping_slots_;
};

}  // namespace isolab::integrators
