// The linear solver of Newmark's effective tangent, chosen once per run from its sparsity pattern
// (the pattern is fixed for a run; only the values change):
//  * a dense LU (dense_lu.h) for at most kDenseMaxDofs dofs: an SDOF, a five-story building, a
//    small plan building, where KLU's general sparse machinery costs more than the arithmetic;
//  * a banded LU (banded_lu.h) when the pattern lies within a band of at most kBandedMaxWidth
//    diagonals off the main one (lower + upper): a shear building without mass-proportional
//    damping relative to the base, which is tridiagonal;
//  * KLU (klu_solver.h) for any other pattern: relative Rayleigh damping couples every floor to
//    the base (a tridiagonal matrix with a full base row and column), plan buildings, modal
//    damping.
// All three factorise with pivoting (tangents of hysteretic and plan laws are unsymmetric) and
// refuse a matrix singular to working precision alike (row_scaling.h).
#pragma once

#include <Eigen/Core>
#include <variant>

#include "banded_lu.h"
#include "dense_lu.h"
#include "isolab/integrators/newmark.h"
#include "isolab/structure/structure.h"
#include "klu_solver.h"

namespace isolab::integrators {

// Thresholds of the automatic choice, set by integrators_benchmark's BM_TangentSolver
// (docs/benchmarks.md, "The linear solver").
inline constexpr int kDenseMaxDofs = 24;
inline constexpr int kBandedMaxWidth = 8;

// The solver kAuto stands for on this pattern; any other choice is returned as it is.
NewmarkOptions::LinearSolver ChooseLinearSolver(const structure::SparseMatrix& pattern,
                                                NewmarkOptions::LinearSolver requested);

class TangentSolver {
 public:
  TangentSolver(const structure::SparseMatrix& pattern, NewmarkOptions::LinearSolver requested);

  // The solver in use (never kAuto).
  NewmarkOptions::LinearSolver kind() const { return kind_; }
  // False when the matrix is singular to working precision; `matrix` has the pattern given to
  // the constructor.
  bool Factorize(structure::SparseMatrix& matrix);
  // Overwrites `rhs` with the solution of the last factorised matrix.
  void Solve(Eigen::VectorXd* rhs);

 private:
  using Solver = std::variant<DenseLu, BandedLu, KluSolver>;
  static Solver Make(const structure::SparseMatrix& pattern, NewmarkOptions::LinearSolver kind);

  NewmarkOptions::LinearSolver kind_;
  Solver solver_;
};

}  // namespace isolab::integrators
