// A structure for time-history analysis: lumped masses on degrees of freedom (displacements
// relative to the ground; a translation or a rotation each), members that act between them, and
// a constant viscous damping matrix. Every model isolab analyses is built as this: an SDOF, a
// shear building in one direction (one translation per level, shear_building.h) and a building in
// plan (two translations and a rotation per rigid floor, plan_building.h).
//
// A member acts on the dofs through a small influence row, as an element of OpenSees' ndf-generic
// domain does:
//  * Member: a one-direction law (parallel_assembly.h) on the deformation d = sum_k c_k u[dof_k];
//    its force f acts as c_k f on dof_k, and its stiffness k adds c_a k c_b to the tangent. A story
//    of a shear building is d = u_above - u_below; a story of a plan building along x at a plan
//    point adds the floors' rotations times the point's arms.
//  * CoupledMember: a bidirectional law (plan_assembly.h) on the deformation vector
//    u = sum_k t_k q[dof_k] (t_k a 2-vector); its force vector f acts as t_k . f on dof_k, its 2x2
//    stiffness K adds t_a . K t_b. An isolator under a rigid floor at `arm` from the floor's
//    reference point has t = (1, 0), (0, 1), (-arm.y, arm.x) on the floor's (u_x, u_y, theta).
//
// The integrator sees only Evaluate(): resisting force and its tangent at a trial state (MFEM's
// seam between problem and integrator), with ConstantTangent() for the tangent's terms that never
// change within a step size, and UpdateLinearLaws() for the laws an iteration's Evaluate may leave
// to the end of the step; the structure never sees the integrator.
//
// Law states live in one LawState array: a member's components one each, a coupled member's two
// each (x then y: PlanLawState's halves), members first. Force columns (a response row's
// connection forces) are one per member, then two per coupled member (x, y).
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "isolab/hysteresis/dashpot.h"
#include "isolab/hysteresis/elastic_spring.h"
#include "isolab/hysteresis/parallel_assembly.h"
#include "isolab/hysteresis/plan_assembly.h"
#include "isolab/structure/axial_load.h"
#include "isolab/structure/damping_product.h"

namespace isolab::structure {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
using hysteresis::Vec2;

inline constexpr int kGround = -1;
// The most dofs a member's influence row may name: the three of a rigid floor below and above.
inline constexpr int kMaxTerms = 6;

// Position of (row, col) in a compressed column-major matrix's value array, so an assembly can
// write its entries through precomputed slots; throws std::logic_error if the entry is absent.
int SlotOf(const SparseMatrix& matrix, int row, int col);

// A one-direction law on d = sum_k coefficients[k] u[dofs[k]]; terms on kGround are absent.
struct Member {
  std::string name;
  std::array<int, kMaxTerms> dofs{kGround, kGround, kGround, kGround, kGround, kGround};
  std::array<double, kMaxTerms> coefficients{};
  hysteresis::ParallelAssembly assembly;

  // d = u[dof_j] - u[dof_i] (dof_i may be kGround): a spring between two dofs, or to the ground.
  static Member Between(std::string name, int dof_i, int dof_j,
                        hysteresis::ParallelAssembly assembly);
  // Whether the member is such a spring, whatever the order of its terms, and its dof_i, dof_j.
  bool IsBetween(int* dof_i, int* dof_j) const;
};

// A bidirectional law on u = sum_k columns[k] q[dofs[k]]; terms on kGround are absent.
struct CoupledMember {
  std::string name;
  std::array<int, kMaxTerms> dofs{kGround, kGround, kGround, kGround, kGround, kGround};
  std::array<Vec2, kMaxTerms> columns{};
  hysteresis::PlanAssembly assembly;

  // Between the ground and the rigid floor whose dofs (u_x, u_y, theta) start at `first_dof`, at
  // `arm` from the floor's reference point: u = (u_x - arm.y theta, u_y + arm.x theta).
  static CoupledMember UnderFloor(std::string name, int first_dof, Vec2 arm,
                                  hysteresis::PlanAssembly assembly);
};

// Coefficients of the effective tangent  K_t + damping (C_t + C) + mass M.
struct TangentFactors {
  double mass = 0.0;
  double damping = 0.0;
};

// The mass and viscous damping terms of the effective tangent, written through slots precomputed
// in a fixed tangent pattern: factors.mass M on the diagonal and factors.damping C.
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
  // `mass` per dof (a rotation's: its rotational inertia), each > 0; `viscous_damping` is
  // dofs x dofs (may be empty of entries). Throws std::invalid_argument for a mass <= 0 and for
  // a member on dofs that do not exist or on none.
  Structure(Eigen::VectorXd mass, std::vector<Member> members,
            std::vector<CoupledMember> coupled_members, SparseMatrix viscous_damping);

  int dofs() const { return static_cast<int>(mass_.size()); }
  const Eigen::VectorXd& mass() const { return mass_; }
  const std::vector<Member>& members() const { return members_; }
  const std::vector<CoupledMember>& coupled_members() const { return coupled_; }
  const SparseMatrix& viscous_damping() const { return viscous_damping_; }
  // *force = viscous_damping() v (damping_product.h).
  void DampingForce(const Eigen::VectorXd& v, Eigen::VectorXd* force) const {
    damping_product_.Apply(viscous_damping_, v, force);
  }

  // Law states and force columns, laid out as the header says.
  std::size_t law_count() const { return law_offsets_.back(); }
  std::size_t force_columns() const { return member_count_ + 2 * coupled_.size(); }

  // Slots: every member and coupled member through one interface, members first (the order of
  // law offsets). A slot has width 1 (a member: its deformation and force along its own row) or 2
  // (a coupled member: x then y). Its component c's law state is at slot_law_offset + width c (+1
  // for y); its force columns start at slot_force_column. A slot's response may be scaled
  // (Evaluate's `scales`: a pendulum bearing under its axial load).
  std::size_t slots() const { return member_count_ + coupled_.size(); }
  std::size_t coupled_slot(std::size_t coupled) const { return member_count_ + coupled; }
  int slot_width(std::size_t slot) const { return slot < member_count_ ? 1 : 2; }
  const std::string& slot_name(std::size_t slot) const {
    return slot < member_count_ ? members_[slot].name : coupled_[slot - member_count_].name;
  }
  std::size_t slot_law_offset(std::size_t slot) const { return law_offsets_[slot]; }
  std::size_t slot_force_column(std::size_t slot) const {
    return slot < member_count_ ? slot : 2 * slot - member_count_;
  }
  // The slot's deformation at dofs u, and its force in a row of force columns; (value, 0) for a
  // slot of width 1.
  Vec2 SlotDeformation(std::size_t slot, std::span<const double> u) const {
    return slot < member_count_ ? Vec2{MemberDeformation(slot, u), 0.0}
                                : CoupledDeformation(slot - member_count_, u);
  }
  Vec2 SlotForce(std::size_t slot, std::span<const double> force_columns) const {
    const std::size_t column = slot_force_column(slot);
    return slot < member_count_ ? Vec2{force_columns[column], 0.0}
                                : Vec2{force_columns[column], force_columns[column + 1]};
  }
  // The dofs the slot acts on and, per dof, the column that maps the dof's motion to the slot's
  // deformation ((coefficient, 0) for a slot of width 1).
  struct Influence {
    int count = 0;
    std::array<int, kMaxTerms> dofs{};
    std::array<Vec2, kMaxTerms> columns{};
  };
  Influence SlotInfluence(std::size_t slot) const;
  // visit(assembly) with the slot's law assembly: a ParallelAssembly (width 1) or a PlanAssembly
  // (width 2), for what both kinds answer (components, pendulum weight, secant stiffness).
  template <class Visitor>
  decltype(auto) VisitSlotAssembly(std::size_t slot, Visitor&& visit) const {
    if (slot < member_count_) return visit(members_[slot].assembly);
    return visit(coupled_[slot - member_count_].assembly);
  }
  // The recoverable and the dissipated energy of one slot's laws (at their own W: unscaled).
  double SlotStoredEnergy(std::size_t slot, std::span<const hysteresis::LawState> states) const;
  double SlotDissipatedEnergy(std::size_t slot, std::span<const hysteresis::LawState> states) const;

  // The axial loads its pendulum bearings take (axial_load.h); empty: every law at its own W.
  // An integrator that runs the structure scales those bearings' slots by AxialLoads::Scale.
  void SetAxialLoads(AxialLoads loads) { axial_loads_ = std::move(loads); }
  const AxialLoads& axial_loads() const { return axial_loads_; }

  // The effective tangent's sparsity: mass diagonal, members, viscous damping. Fixed for the
  // structure's life, so a solver analyses it once.
  const SparseMatrix& tangent_pattern() const { return pattern_; }

  // The terms of the effective tangent with `factors` that do not depend on the state, into
  // `tangent`'s values (its pattern tangent_pattern()): the mass, the viscous damping and every
  // member whose laws all have a constant tangent (linear springs, dashpots: a building's elastic
  // stories). An integrator writes them once per step size and starts every Evaluate's tangent
  // from a copy.
  void ConstantTangent(const TangentFactors& factors, SparseMatrix* tangent) const;

  // What Evaluate does with the linear members between two dofs (their laws linear springs and
  // dashpots alone: a building's elastic stories). kUpdate: their laws' trial states and
  // responses are written as every other law's. kForceOnly: only their force is, their states and
  // responses are left as they were, for UpdateLinearLaws once the trial is final. Their force
  // depends on the trial (u, v) alone and their tangent is constant, so an integrator's Newton
  // iterations need nothing else of them.
  enum class LinearLaws { kUpdate, kForceOnly };

  // Updates every law at trial (u, v) at time t from `committed`, writes `trial` states and
  // `responses` (law_count() each; a coupled component's x and y force with the diagonal of its
  // tangent and damping), the resisting force (members plus C v) into `force`, each force column
  // into `member_forces` (force_columns()), and, when `tangent` is not null, adds the terms of the
  // effective tangent with `factors` that depend on the state to its values, which must hold
  // ConstantTangent(factors). `scales`, when not empty, has one factor per slot (slots()): each
  // slot's force, tangent and law responses are its laws' times that factor (the laws' states stay
  // those at their own W); kForceOnly takes no scales. Allocates nothing.
  void Evaluate(std::span<const hysteresis::LawState> committed, double t, const Eigen::VectorXd& u,
                const Eigen::VectorXd& v, std::span<hysteresis::LawState> trial,
                std::span<hysteresis::LawResponse> responses, Eigen::VectorXd* force,
                std::span<double> member_forces, const TangentFactors& factors,
                SparseMatrix* tangent, std::span<const double> scales = {},
                LinearLaws linear = LinearLaws::kUpdate) const;
  // The trial states and responses at (u, v) at time t from `committed` of the laws that Evaluate
  // leaves with kForceOnly: what it writes for them with kUpdate, to the bit.
  void UpdateLinearLaws(std::span<const hysteresis::LawState> committed, double t,
                        const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                        std::span<hysteresis::LawState> trial,
                        std::span<hysteresis::LawResponse> responses) const;

  // A member's deformation at dofs u (inline: the results' rows and the peaks take it for every
  // story at every step).
  double MemberDeformation(std::size_t member, std::span<const double> u) const {
    const Terms& terms = member_terms_[member];
    double d = 0.0;
    for (int a = 0; a < terms.count; ++a) d += terms.coefficients[a] * u[terms.dofs[a]];
    return d;
  }

  // Recoverable energy of all laws; the energy all laws dissipated, and the dashpots' part of it
  // (the rest is hysteretic: the sliders').
  double StoredEnergy(std::span<const hysteresis::LawState> states) const;
  double DissipatedEnergy(std::span<const hysteresis::LawState> states) const;
  double DashpotEnergy(std::span<const hysteresis::LawState> states) const;

 private:
  Vec2 CoupledDeformation(std::size_t coupled, std::span<const double> u) const;

  // A member's terms packed for the hot loop: the dofs that exist, with the tangent slots of
  // their pairs (row-major count x count). A spring between two dofs or to the ground (the
  // members of a one-direction building) takes a shorter path through `between`.
  struct Terms {
    int count = 0;
    std::array<int, kMaxTerms> dofs{};
    std::array<double, kMaxTerms> coefficients{};
    std::array<int, kMaxTerms * kMaxTerms> slots{};
  };
  // A linear member's laws, linear_laws_[begin, end); empty for any other.
  struct LinearRange {
    std::uint32_t begin = 0, end = 0;
  };
  struct Between {
    std::size_t member = 0;
    int dof_i = kGround, dof_j = 0;
    int ii = -1, jj = -1, ij = -1, ji = -1;
    LinearRange linear;  // empty unless the member is linear
  };
  // A law of a linear member: a spring of constant stiffness, or a dashpot.
  using LinearLaw = std::variant<hysteresis::ElasticSpring, hysteresis::Dashpot>;
  static std::optional<std::vector<LinearLaw>> LinearLawsOf(
      const hysteresis::ParallelAssembly& assembly);
  hysteresis::LawInput BetweenInput(const Between& spring, double t, const Eigen::VectorXd& u,
                                    const Eigen::VectorXd& v) const {
    const bool grounded = spring.dof_i == kGround;
    return {u[spring.dof_j] - (grounded ? 0.0 : u[spring.dof_i]),
            v[spring.dof_j] - (grounded ? 0.0 : v[spring.dof_i]), t};
  }
  // A coupled member's terms, packed as a member's are. One under a rigid floor (its columns
  // (1, 0), (0, 1) and (-arm.y, arm.x): UnderFloor) keeps its arm, for a tangent block written in
  // closed form (the multiplications by the map's zeros and ones left out).
  struct CoupledTerms {
    int count = 0;
    std::array<int, kMaxTerms> dofs{};
    std::array<Vec2, kMaxTerms> columns{};
    std::array<int, kMaxTerms * kMaxTerms> slots{};
    bool under_floor = false;
    Vec2 arm;
  };

  void AddMemberTangent(std::size_t member, double k_eff, double* values) const;
  void AddBetweenTangent(const Between& spring, double k_eff, double* values) const;
  void AddCoupledTangent(std::size_t coupled, const hysteresis::Mat2& k_eff, double* values) const;
  // Evaluate's parts: the springs between two dofs, and the coupled members; kScaled: each slot's
  // response times scales[slot] (a separate instantiation, so an unscaled run pays nothing).
  template <bool kScaled>
  void EvaluateAll(std::span<const hysteresis::LawState> committed, double t,
                   const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                   std::span<hysteresis::LawState> trial,
                   std::span<hysteresis::LawResponse> responses, Eigen::VectorXd* force,
                   std::span<double> member_forces, double damping_factor, double* values,
                   const double* scales, bool linear_force_only) const;
  template <bool kScaled>
  void EvaluateSprings(std::span<const hysteresis::LawState> committed, double t,
                       const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                       std::span<hysteresis::LawState> trial,
                       std::span<hysteresis::LawResponse> responses, Eigen::VectorXd* force,
                       std::span<double> member_forces, double damping_factor, double* values,
                       const double* scales, bool linear_force_only) const;
  template <bool kScaled>
  void EvaluateCoupled(std::span<const hysteresis::LawState> committed, double t,
                       const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                       std::span<hysteresis::LawState> trial,
                       std::span<hysteresis::LawResponse> responses, Eigen::VectorXd* force,
                       std::span<double> member_forces, double damping_factor, double* values,
                       const double* scales) const;
  // One component of an assembly with sliders in series, whose elements' states sit after every
  // component's own (plan_assembly.h).
  [[gnu::noinline]] void UpdateCoupledComponent(std::size_t coupled, std::size_t component,
                                                std::span<const hysteresis::LawState> committed,
                                                const hysteresis::PlanLawInput& in,
                                                std::span<hysteresis::LawState> trial,
                                                hysteresis::PlanLawResponse* response) const;
  template <bool kScaled>
  void EvaluateMember(std::size_t k, std::span<const hysteresis::LawState> committed,
                      const hysteresis::LawInput& in, std::span<hysteresis::LawState> trial,
                      std::span<hysteresis::LawResponse> responses, std::span<double> member_forces,
                      double damping_factor, double* values, const double* scales) const;

  Eigen::VectorXd mass_;
  std::vector<Member> members_;
  std::vector<CoupledMember> coupled_;
  // members_.size(), the first coupled member's slot, kept as a number: the slot accessors run
  // per isolator at every step, and size() divides by sizeof(Member).
  std::size_t member_count_ = 0;
  SparseMatrix viscous_damping_;
  DampingProduct damping_product_;
  std::vector<std::size_t> law_offsets_;         // members, then coupled members, then the end
  std::vector<std::size_t> viscous_law_states_;  // the law states of dashpots (and their halves)
  SparseMatrix pattern_;
  ConstantTerms constant_terms_;
  std::vector<Terms> member_terms_;
  std::vector<Between> between_;        // the members that are springs between two dofs
  std::vector<LinearLaw> linear_laws_;  // the linear members' laws, in the order of between_
  std::vector<std::size_t> general_;    // the others
  std::vector<CoupledTerms> coupled_terms_;
  // Per member and coupled member: its laws' stiffness and damping if they do not depend on the
  // state.
  std::vector<std::optional<hysteresis::AssemblyResponse>> member_constants_;
  std::vector<std::optional<hysteresis::PlanResponse>> coupled_constants_;
  AxialLoads axial_loads_;
};

}  // namespace isolab::structure
