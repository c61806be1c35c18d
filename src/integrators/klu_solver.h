// SuiteSparse KLU for the effective tangent: symbolic analysis once per run (the pattern is fixed),
// numeric factorisation per Newton iteration reusing KLU's numeric object (klu_refactor), so a
// factorisation allocates nothing after the first.
#pragma once

#include <klu.h>

#include <Eigen/Core>

#include "isolab/structure/structure.h"

namespace isolab::integrators {

class KluSolver {
 public:
  explicit KluSolver(const structure::SparseMatrix& pattern);
  ~KluSolver();
  KluSolver(const KluSolver&) = delete;
  KluSolver& operator=(const KluSolver&) = delete;

  // False when the matrix is singular to working precision.
  bool Factorize(structure::SparseMatrix& matrix);
  // Overwrites `rhs` with the solution.
  void Solve(Eigen::VectorXd* rhs);

 private:
  klu_common common_;
  klu_symbolic* symbolic_ = nullptr;
  klu_numeric* numeric_ = nullptr;
};

}  // namespace isolab::integrators
