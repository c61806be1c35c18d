// A structure and its excitation as the implicit system IDA integrates, in residual form
// F(t, y, y') = 0 with y = [u; v; z] (relative displacements, velocities, and the internal
// variables of every law that has them, hysteresis/rate_form.h: z, and w for a heated lead core):
//   u' - v = 0
//   M v' + C v + f(u, v, z, w, t) - p_eff(t) = 0
//   z' - r(u, v, z, w) = 0,   w' - q(u, v, z, w, t) = 0
// Each law's phase (its active smooth branch) is held here and changed only by SwitchPhases at
// an event the integrator has located; in between the system is smooth. The Jacobian
// dF/dy + cj dF/dy' is assembled into a fixed sparse pattern through precomputed slots, from the
// laws' exact partial derivatives. Nothing here allocates after construction.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dof_rows.h"
#include "isolab/hysteresis/rate_form.h"
#include "isolab/integrators/excitation.h"
#include "isolab/integrators/response.h"
#include "isolab/structure/structure.h"

namespace isolab::integrators {

class RateFormSystem {
 public:
  RateFormSystem(const structure::Structure& structure, const Excitation& excitation);

  int size() const { return 2 * dofs_ + internal_count_; }
  int root_count() const { return root_offsets_.back(); }
  const structure::SparseMatrix& jacobian_pattern() const { return pattern_; }

  void Residual(double t, const double* y, const double* yp, double* residual);
  // Values of dF/dy + cj dF/dy' in jacobian_pattern()'s order.
  void Jacobian(double t, double cj, const double* y, double* values);
  void Roots(const double* y, double* roots) const;
  // Switches the phase of every law whose root is flagged (IDAGetRootInfo's -1/0/+1) and puts its
  // z on the new phase's surface, in y. Returns the number of phase changes.
  int SwitchPhases(const int* roots_found, double* y);
  // y' consistent with y at t under the current phases (M is diagonal, so v' is explicit).
  void ConsistentDerivative(double t, const double* y, double* yp);
  void EnergyRates(double t, const double* y, double* rates);
  // The response at grid step `step` (time t) from the state y and the energies integrated so
  // far, viewing y and this system's buffers (valid until the next call).
  ResponseRow Record(int step, double t, const double* y, const double* energy_integrals);

 private:
  struct LawInput {
    double u, v, z, w;
  };
  // Laws' deformation, rate and internal variables read from y.
  LawInput InputOf(std::size_t connection, std::size_t law, const double* y) const;
  // Evaluates every law at t into responses_ and the resisting force C v + f into force_.
  void EvaluateLaws(double t, const double* y);

  struct ConnectionSlots {
    int vu_jj = -1, vu_ii = -1, vu_ij = -1, vu_ji = -1;  // stiffness, v rows x u columns
    int vv_jj = -1, vv_ii = -1, vv_ij = -1, vv_ji = -1;  // damping, v rows x v columns
  };
  struct InternalSlots {
    int vz_j = -1, vz_i = -1;                                 // force_z, v rows x z column
    int zu_j = -1, zu_i = -1, zv_j = -1, zv_i = -1, zz = -1;  // z row
    // With a second variable w: force_w (v rows), rate_w (z row), and the w row.
    int vw_j = -1, vw_i = -1, zw = -1;
    int wu_j = -1, wu_i = -1, wv_j = -1, wv_i = -1, wz = -1, ww = -1;
  };

  const structure::Structure& structure_;
  const Excitation& excitation_;
  int dofs_ = 0;
  DofRows dof_rows_;
  int internal_count_ = 0;
  std::vector<int> internal_index_;  // per law: position of z in the z block, or -1
  std::vector<int> second_index_;    // per law: position of w in the z block, or -1
  std::vector<int> root_offsets_;    // per law, and one past the last
  std::vector<hysteresis::LawPhase> phases_;
  std::vector<hysteresis::RateResponse> responses_;
  std::vector<double> connection_forces_, law_forces_;
  Eigen::VectorXd load_, force_, viscous_, velocity_, acceleration_, absolute_acceleration_;

  structure::SparseMatrix pattern_;
  std::vector<ConnectionSlots> connection_slots_;
  std::vector<InternalSlots> internal_slots_;  // per law with z
};

}  // namespace isolab::integrators
