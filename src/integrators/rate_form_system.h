// A structure (structure.h) and its excitation as the implicit system IDA integrates, in residual
// form F(t, y, y') = 0 with y = [u; v; q]: the dofs' displacements and velocities, and the
// internal variables of every law that has them (a one-direction law's z, and w for a heated lead
// core, rate_form.h; a coupled law's up to four, plan_rate_form.h):
//   u' - v = 0
//   M v' + C v + f(u, v, q, t) - p_eff(t) = 0
//   q' - r(u, v, q, t) = 0
//
// Every law acts on its deformation through its member's fixed linear map of the dofs: a
// member's d = c . u over its terms (one row), a coupled member's u = T q (two rows). So one "law
// block" serves both: with G the map (r x m), its force f (r) adds G^T f to the dofs'
// equations and its Jacobian block is [G^T f_u G, G^T f_v G, G^T f_q; -r_u G, -r_v G, cj I - r_q]
// on the rows (its dofs' v rows, its q rows) and columns (its dofs' u and v columns, its q
// columns), written through slots into a sparse pattern fixed at construction. Phases are held
// here and changed only by SwitchPhases at a located event. Nothing allocates after construction.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "dof_rows.h"
#include "isolab/hysteresis/plan_rate_form.h"
#include "isolab/hysteresis/rate_form.h"
#include "isolab/integrators/excitation.h"
#include "isolab/integrators/response.h"
#include "isolab/structure/structure.h"

namespace isolab::integrators {

class RateFormSystem {
 public:
  RateFormSystem(const structure::Structure& structure, const Excitation& excitation);

  int size() const { return 2 * dofs_ + internal_count_; }
  int root_count() const { return root_count_; }
  const structure::SparseMatrix& jacobian_pattern() const { return pattern_; }
  // Columns of the response's connection_force and law_force (structure.h).
  int force_columns() const { return static_cast<int>(connection_forces_.size()); }
  int law_columns() const { return static_cast<int>(law_forces_.size()); }

  void Residual(double t, const double* y, const double* yp, double* residual);
  // Values of dF/dy + cj dF/dy' in jacobian_pattern()'s order.
  void Jacobian(double t, double cj, const double* y, double* values);
  void Roots(const double* y, double* roots) const;
  // Switches the phase of every law whose root is flagged (IDAGetRootInfo's -1/0/+1) and puts its
  // internal variables on the new phase's surface, in y. Returns the number of phase changes.
  int SwitchPhases(const int* roots_found, double* y);
  // y' consistent with y at t under the current phases (M is diagonal, so v' is explicit).
  void ConsistentDerivative(double t, const double* y, double* yp);
  void EnergyRates(double t, const double* y, double* rates);
  // The response at grid step `step` (time t) from the state y and the energies integrated so
  // far, viewing y and this system's buffers (valid until the next call).
  ResponseRow Record(int step, double t, const double* y, const double* energy_integrals);

 private:
  static constexpr int kMaxRows = 2;  // a law's force components
  static constexpr int kMaxTerms = structure::kMaxTerms;
  static constexpr int kMaxQ = hysteresis::kMaxPlanInternalVariables;

  // One law (a component of a member or of a coupled member) and where it sits.
  struct LawBlock {
    bool plan = false;  // a coupled member's law (else a member's one-direction law)
    int kernel = 0;     // index into member_kernels_ or plan_kernels_ (and their phases)
    int rows = 1;       // r: 1 for a member, 2 for a coupled member
    int terms = 0;      // m: the dofs it acts on
    std::array<int, kMaxTerms> dofs{};
    std::array<std::array<double, kMaxTerms>, kMaxRows> map{};  // G, r x m
    int q0 = 0, q_count = 0;   // its internal variables at 2 dofs + q0
    int root0 = 0, roots = 0;  // its root functions
    int force_column = 0;      // the first of its r force columns
    int law_column = 0;        // the first of its r law-force columns
    int slot0 = 0;             // its slots: (m + q) rows x (2 m + q) columns, row-major
  };

  // A law's response in the block form (r force rows, q internal variables).
  struct BlockResponse {
    std::array<double, kMaxRows> force{};
    std::array<std::array<double, kMaxRows>, kMaxRows> force_u{}, force_v{};
    std::array<std::array<double, kMaxQ>, kMaxRows> force_q{};
    std::array<double, kMaxQ> rate{};
    std::array<std::array<double, kMaxRows>, kMaxQ> rate_u{}, rate_v{};
    std::array<std::array<double, kMaxQ>, kMaxQ> rate_q{};
    double hysteretic_power = 0.0, viscous_power = 0.0;
  };

  // Appends a slot's component law: its kernel and rest phase, its block with q internal
  // variables and its root functions.
  void AddLaw(LawBlock law, const hysteresis::LawKernel& kernel);
  void AddLaw(LawBlock law, const hysteresis::PlanLawKernel& kernel);
  void AddBlock(LawBlock law, int q_count, int roots);

  // The law's deformation (r) and its rate from y.
  void Deformation(const LawBlock& law, const double* y, std::array<double, kMaxRows>* u,
                   std::array<double, kMaxRows>* v) const;
  BlockResponse EvaluateLaw(const LawBlock& law, double t, const double* y) const;
  // Evaluates every law at t into responses_, and C v + sum G^T f into force_.
  void EvaluateLaws(double t, const double* y);
  void LawRoots(const LawBlock& law, const double* y, double* roots) const;
  // Switches law's phase for root `root` at y (writing its q); true if the phase changed.
  bool SwitchLaw(const LawBlock& law, int root, double* y);
  double LawStoredEnergy(const LawBlock& law, double t, const double* y) const;

  const structure::Structure& structure_;
  const Excitation& excitation_;
  const std::vector<Eigen::VectorXd> mass_influence_;  // M r of each ground component
  int dofs_ = 0;
  DofRows dof_rows_;
  int internal_count_ = 0;
  int root_count_ = 0;
  std::vector<LawBlock> laws_;
  std::vector<const hysteresis::LawKernel*> member_kernels_;
  std::vector<const hysteresis::PlanLawKernel*> plan_kernels_;
  std::vector<hysteresis::LawPhase> member_phases_;
  std::vector<hysteresis::PlanLawPhase> plan_phases_;
  std::vector<BlockResponse> responses_;
  std::vector<double> connection_forces_, law_forces_;
  Eigen::VectorXd load_, force_, viscous_, velocity_, acceleration_, absolute_acceleration_;

  structure::SparseMatrix pattern_;
  std::vector<int> law_slots_;
};

}  // namespace isolab::integrators
