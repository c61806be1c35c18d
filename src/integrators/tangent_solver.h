// The linear solver of Newmark's effective tangent, chosen once per run from its sparsity pattern
// (the pattern is fixed for a run; only the values change):
//  * a dense LU (dense_lu.h) for at most kDenseMaxDofs dofs: an SDOF, a shear building of up to
//    nine stories, where KLU's general sparse machinery costs more than the arithmetic;
//  * a banded LU (banded_lu.h) when the pattern lies within a band of at most kBandedMaxWidth
//    diagonals off the main one (lower + upper) once a few border dofs coupled to many others are
//    set aside: a shear building is tridiagonal, with a full base row and column under relative
//    Rayleigh damping (its mass-proportional part couples every floor to the base);
//  * KLU (klu_solver.h) for any other pattern: modal damping (dense), wide bands, the bundled
//    plan building (its base x dof couples to every floor's x dof without being a border).
// All three factorise with pivoting (tangents of hysteretic and plan laws are unsymmetric) and
// refuse a matrix singular to working precision alike (row_scaling.h).
#pragma once

#include <Eigen/Core>
#include <cassert>
#include <cstring>
#include <variant>
#include <vector>

#include "banded_lu.h"
#include "dense_lu.h"
#include "isolab/integrators/newmark.h"
#include "isolab/structure/structure.h"
#include "klu_solver.h"

namespace isolab::integrators {

// Thresholds of the automatic choice, from callgrind counts of integrators_benchmark's
// BM_StoriesTable9Solver and BM_TangentSolver (docs/benchmarks.md, "The linear solver"): on
// shear buildings with relative Rayleigh damping, dense LU takes fewest instructions a step up to
// 10 dofs (at 9 dofs 13.5 k against KLU's 14.7 k and banded's 15.7 k), banded with the base as its
// border from 11 dofs on (at 12 dofs 15.5 k against KLU's 17.9 k and dense's 18.6 k); banded LU
// beats KLU on every band measured, up to 8 diagonals each side at 1001 dofs. Those counts
// factorised at every iteration; BM_StoriesTable9Solver now mostly keeps its factors (below), so
// measuring them again takes a benchmark whose tangent changes every step (BM_TangentSolver).
inline constexpr int kDenseMaxDofs = 10;
inline constexpr int kBandedMaxWidth = 16;

// The solver kAuto stands for on this pattern; any other choice is returned as it is.
NewmarkOptions::LinearSolver ChooseLinearSolver(const structure::SparseMatrix& pattern,
                                                NewmarkOptions::LinearSolver requested);

class TangentSolver {
 public:
  TangentSolver(const structure::SparseMatrix& pattern, NewmarkOptions::LinearSolver requested);

  // The solver in use (never kAuto).
  NewmarkOptions::LinearSolver kind() const { return kind_; }
  // False when the matrix is singular to working precision; `matrix` has the pattern given to
  // the constructor. A matrix whose values are, bit for bit, those last factorised with success
  // is not factorised again: its factors would be the same. Piecewise-linear laws keep their
  // tangent between events, so under a bilinear isolator and linear stories most Newton
  // iterations repeat the last tangent, and comparing its values costs a fraction of factorising
  // them (docs/benchmarks.md, "The factors kept"). Both are defined here so that the step inlines
  // the dispatch whatever else its translation unit holds (once out of line, they cost the
  // five-story step 0.2 %).
  bool Factorize(structure::SparseMatrix& matrix) {
    assert(static_cast<std::size_t>(matrix.nonZeros()) == factored_values_.size());
    const std::size_t bytes = factored_values_.size() * sizeof(double);
    if (factored_ && std::memcmp(matrix.valuePtr(), factored_values_.data(), bytes) == 0) {
      return true;
    }
    ++factorisations_;
    factored_ = std::visit([&](auto& solver) { return solver.Factorize(matrix); }, solver_);
    if (factored_) std::memcpy(factored_values_.data(), matrix.valuePtr(), bytes);
    return factored_;
  }
  // Factorisations made (attempted), the repeated matrices left out.
  long factorisations() const { return factorisations_; }
  // Overwrites `rhs` with the solution of the last factorised matrix.
  void Solve(Eigen::VectorXd* rhs) {
    std::visit([&](auto& solver) { solver.Solve(rhs); }, solver_);
  }

 private:
  using Solver = std::variant<DenseLu, BandedLu, KluSolver>;
  static Solver Make(const structure::SparseMatrix& pattern, NewmarkOptions::LinearSolver kind);

  NewmarkOptions::LinearSolver kind_;
  Solver solver_;
  std::vector<double> factored_values_;  // of the last matrix factorised with success
  bool factored_ = false;                // whether factored_values_ holds that matrix
  long factorisations_ = 0;
};

}  // namespace isolab::integrators
