// A structure for time-history analysis: lumped masses on degrees of freedom (displacements
// relative to the ground), connections between them or to the ground that each carry a parallel
// assembly of element laws, and a constant viscous damping matrix. SDOF systems and shear
// buildings (shear_building.h) are both built as this.
//
// The integrator sees only Evaluate(): resisting force and its tangent at a trial state (MFEM's
// seam between problem and integrator), with ConstantTangent() for the tangent's terms that never
// change within a step size; the structure never sees the integrator.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "isolab/hysteresis/parallel_assembly.h"

namespace isolab::structure {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

inline constexpr int kGround = -1;

// Position of (row, col) in a compressed column-major matrix's value array, so an assembly can
// write its entries through precomputed slots; throws std::logic_error if the entry is absent.
int SlotOf(const SparseMatrix& matrix, int row, int col);

// A connection's deformation is u[dof_j] - u[dof_i] (u[kGround] = 0); its force acts +on dof_j.
struct Connection {
  std::string name;
  int dof_i = kGround;
  int dof_j = 0;
  hysteresis::ParallelAssembly assembly;
};

// Coefficients of the effective tangent  K_t + damping (C_t + C) + mass M.
struct TangentFactors {
  double mass = 0.0;
  double damping = 0.0;
};

// The mass and viscous damping terms of the effective tangent, written through slots precomputed
// in a fixed tangent pattern: factors.mass M on the diagonal and factors.damping C. Structure and
// PlanStructure (plan_structure.h) share it.
class ConstantTerms {
 public:
  // The pattern entries the terms need: the diagonal and every stored entry of `damping`.
  static void AppendEntries(int dofs, const SparseMatrix& damping,
                            std::vector<Eigen::Triplet<double>>* entries);

  ConstantTerms() = default;
  // `damping` compressed; `pattern` holds AppendEntries' entries.
  ConstantTerms(int dofs, const SparseMatrix& damping, const SparseMatrix& pattern);

  // The tangent's values zeroed, then the mass and damping terms added. Allocates nothing.
  void Fill(const Eigen::VectorXd& mass, const SparseMatrix& damping, const TangentFactors& factors,
            SparseMatrix* tangent) const;

 private:
  std::vector<int> mass_slots_;
  std::vector<int> damping_slots_;  // one per stored entry of the damping matrix
};

class Structure {
 public:
  // `viscous_damping` is dofs x dofs (may be empty of entries).
  Structure(Eigen::VectorXd mass, std::vector<Connection> connections,
            SparseMatrix viscous_damping);

  int dofs() const { return static_cast<int>(mass_.size()); }
  const Eigen::VectorXd& mass() const { return mass_; }
  const std::vector<Connection>& connections() const { return connections_; }
  const SparseMatrix& viscous_damping() const { return viscous_damping_; }

  // Law states are stored connection after connection; component c of connection k sits at
  // law_offset(k) + c.
  std::size_t law_count() const { return law_offsets_.back(); }
  std::size_t law_offset(std::size_t connection) const { return law_offsets_[connection]; }

  // The effective tangent's sparsity: mass diagonal, connections, viscous damping. Fixed for the
  // structure's life, so a solver analyses it once.
  const SparseMatrix& tangent_pattern() const { return pattern_; }

  // The terms of the effective tangent with `factors` that do not depend on the state, into
  // `tangent`'s values (its pattern tangent_pattern()): the mass, the viscous damping and every
  // connection whose laws all have a constant tangent (linear springs, dashpots: a building's
  // elastic stories). An integrator writes them once per step size and starts every Evaluate's
  // tangent from a copy.
  void ConstantTangent(const TangentFactors& factors, SparseMatrix* tangent) const;

  // Updates every law at trial (u, v) at time t from `committed`, writes `trial` states and
  // `responses` (law_count() each), the resisting force (connections plus C v) into `force`, each
  // connection's force into `connection_forces`, and, when `tangent` is not null, adds the terms
  // of the effective tangent with `factors` that depend on the state to its values, which must
  // hold ConstantTangent(factors). Allocates nothing.
  void Evaluate(std::span<const hysteresis::LawState> committed, double t, const Eigen::VectorXd& u,
                const Eigen::VectorXd& v, std::span<hysteresis::LawState> trial,
                std::span<hysteresis::LawResponse> responses, Eigen::VectorXd* force,
                std::span<double> connection_forces, const TangentFactors& factors,
                SparseMatrix* tangent) const;

  // Recoverable energy of all laws, and dissipated energy split into viscous (dashpots) and
  // hysteretic (sliders).
  double StoredEnergy(std::span<const hysteresis::LawState> states) const;
  double DashpotEnergy(std::span<const hysteresis::LawState> states) const;
  double HystereticEnergy(std::span<const hysteresis::LawState> states) const;

 private:
  // Positions in the tangent's value array of the entries a connection touches (-1 if none).
  struct ConnectionSlots {
    int ii = -1, jj = -1, ij = -1, ji = -1;
  };

  void AddConnectionTangent(std::size_t connection, double k_eff, double* values) const;

  Eigen::VectorXd mass_;
  std::vector<Connection> connections_;
  SparseMatrix viscous_damping_;
  std::vector<std::size_t> law_offsets_;
  std::vector<char> law_is_dashpot_;
  SparseMatrix pattern_;
  ConstantTerms constant_terms_;
  std::vector<ConnectionSlots> connection_slots_;
  // Per connection: its laws' stiffness and damping if they do not depend on the state.
  std::vector<std::optional<hysteresis::AssemblyResponse>> constant_responses_;
};

}  // namespace isolab::structure
