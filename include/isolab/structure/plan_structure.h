// A structure in plan for time-history analysis: rigid floors with three degrees of freedom each,
// (u_x, u_y, theta) about the floor's centre of mass, floor f at dofs 3f, 3f + 1, 3f + 2 (all
// relative to the ground); one-direction laws on linear combinations of those dofs (a story's
// resistance along x, along y and in torsion), and isolators with plan laws (coupled or
// uncoupled, plan_assembly.h) between the ground and a floor at a point of its plan. The
// counterpart of structure.h for plan models, with the same Evaluate contract, so one Newmark
// loop drives both (newmark.h).
//
// Law states live in one LawState array like structure.h's: a member's components one each, an
// isolator's components two each (x then y, PlanLawState's halves), so the integrator's state,
// response and energy bookkeeping is the one-direction one.
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "isolab/hysteresis/parallel_assembly.h"
#include "isolab/hysteresis/plan_assembly.h"
#include "isolab/structure/structure.h"

namespace isolab::structure {

inline constexpr int kPlanDofsPerFloor = 3;

// A one-direction law on the deformation d = sum_k coefficient_k u[dof_k] (terms with dof kGround
// are absent); its force f acts as coefficient_k f on dof_k. A story's x resistance at plan point
// (x_s, y_s) between floors a (below) and b (above) has d = u_xb - (y_s - y_b) theta_b - u_xa +
// (y_s - y_a) theta_a, with (x_f, y_f) the floors' centres of mass.
struct PlanMember {
  static constexpr int kMaxTerms = 6;
  std::string name;
  std::array<int, kMaxTerms> dofs{kGround, kGround, kGround, kGround, kGround, kGround};
  std::array<double, kMaxTerms> coefficients{};
  hysteresis::ParallelAssembly assembly;
};

// An isolator between the ground and floor `floor` at `arm` from the floor's centre of mass: its
// deformation is u = T q, T = [1 0 -arm.y; 0 1 arm.x], q the floor's three dofs.
struct PlanIsolator {
  std::string name;
  int floor = 0;
  hysteresis::Vec2 arm;
  hysteresis::PlanAssembly assembly;
};

class PlanStructure {
 public:
  // `mass`: 3 entries per floor (m, m, rotational inertia about the centre of mass);
  // `viscous_damping` is dofs x dofs. Throws std::invalid_argument for a mass or inertia <= 0
  // and for members or isolators on dofs that do not exist.
  PlanStructure(Eigen::VectorXd mass, std::vector<PlanMember> members,
                std::vector<PlanIsolator> isolators, SparseMatrix viscous_damping);

  int dofs() const { return static_cast<int>(mass_.size()); }
  int floors() const { return dofs() / kPlanDofsPerFloor; }
  const Eigen::VectorXd& mass() const { return mass_; }
  const std::vector<PlanMember>& members() const { return members_; }
  const std::vector<PlanIsolator>& isolators() const { return isolators_; }
  const SparseMatrix& viscous_damping() const { return viscous_damping_; }

  // Law states: members' components, then isolators' (two each). law_offset(k) for member k,
  // isolator_law_offset(i) for isolator i (its component c at offset + 2 c and + 2 c + 1).
  std::size_t law_count() const { return law_offsets_.back(); }
  std::size_t law_offset(std::size_t member) const { return law_offsets_[member]; }
  std::size_t isolator_law_offset(std::size_t isolator) const {
    return law_offsets_[members_.size() + isolator];
  }

  // Force columns Evaluate writes: one per member, then two per isolator (x, y).
  std::size_t force_columns() const { return members_.size() + 2 * isolators_.size(); }
  std::size_t isolator_force_column(std::size_t isolator) const {
    return members_.size() + 2 * isolator;
  }

  const SparseMatrix& tangent_pattern() const { return pattern_; }

  // As Structure::ConstantTangent: mass, viscous damping, and the members and isolators whose
  // laws all have a constant tangent.
  void ConstantTangent(const TangentFactors& factors, SparseMatrix* tangent) const;

  // As Structure::Evaluate. `responses` of an isolator's component hold its x and y force with
  // the diagonal of its tangent and damping; `connection_forces` has force_columns() entries.
  void Evaluate(std::span<const hysteresis::LawState> committed, double t, const Eigen::VectorXd& u,
                const Eigen::VectorXd& v, std::span<hysteresis::LawState> trial,
                std::span<hysteresis::LawResponse> responses, Eigen::VectorXd* force,
                std::span<double> connection_forces, const TangentFactors& factors,
                SparseMatrix* tangent) const;

  // The deformation of isolator i at dofs u (its displacement vector relative to the ground).
  hysteresis::Vec2 IsolatorDeformation(std::size_t isolator, std::span<const double> u) const;

  double StoredEnergy(std::span<const hysteresis::LawState> states) const;
  double DashpotEnergy(std::span<const hysteresis::LawState> states) const;
  double HystereticEnergy(std::span<const hysteresis::LawState> states) const;

 private:
  double DissipatedEnergy(std::span<const hysteresis::LawState> states) const;
  // k_eff of member k on its terms' pairs; T^T k_eff T into isolator i's floor block.
  void AddMemberTangent(std::size_t member, double k_eff, double* values) const;
  void AddIsolatorTangent(std::size_t isolator, const hysteresis::Mat2& k_eff,
                          double* values) const;

  Eigen::VectorXd mass_;
  std::vector<PlanMember> members_;
  std::vector<PlanIsolator> isolators_;
  SparseMatrix viscous_damping_;
  std::vector<std::size_t> law_offsets_;         // members, then isolators, then the end
  std::vector<std::size_t> viscous_law_states_;  // the law states of dashpots (and dashpot halves)
  SparseMatrix pattern_;
  ConstantTerms constant_terms_;
  // Member k's terms on dofs that exist (kGround ones dropped), packed for the hot loop, with the
  // tangent slots of their pairs, row-major count x count.
  struct MemberTerms {
    int count = 0;
    std::array<int, PlanMember::kMaxTerms> dofs{};
    std::array<double, PlanMember::kMaxTerms> coefficients{};
    std::array<int, PlanMember::kMaxTerms * PlanMember::kMaxTerms> slots{};
  };
  std::vector<MemberTerms> member_terms_;
  // Isolator i's 3x3 block, row-major, from 9 i.
  std::vector<int> isolator_slots_;
  // Per member and per isolator: its laws' stiffness and damping if they do not depend on the
  // state.
  std::vector<std::optional<hysteresis::AssemblyResponse>> member_constants_;
  std::vector<std::optional<hysteresis::PlanResponse>> isolator_constants_;
};

}  // namespace isolab::structure
