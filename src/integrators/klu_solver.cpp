#include "klu_solver.h"

#include <stdexcept>

#include "row_scaling.h"

namespace isolab::integrators {

KluSolver::KluSolver(const structure::SparseMatrix& pattern) {
  klu_defaults(&common_);
  const int n = static_cast<int>(pattern.rows());
  symbolic_ = klu_analyze(n, const_cast<int*>(pattern.outerIndexPtr()),
                          const_cast<int*>(pattern.innerIndexPtr()), &common_);
  if (symbolic_ == nullptr) {
    throw std::runtime_error("klu_analyze failed with status " + std::to_string(common_.status));
  }
}

KluSolver::~KluSolver() {
  if (numeric_ != nullptr) klu_free_numeric(&numeric_, &common_);
  klu_free_symbolic(&symbolic_, &common_);
}

bool KluSolver::Factorize(structure::SparseMatrix& matrix) {
  int* columns = matrix.outerIndexPtr();
  int* rows = matrix.innerIndexPtr();
  double* values = matrix.valuePtr();
  if (numeric_ != nullptr && klu_refactor(columns, rows, values, symbolic_, numeric_, &common_) &&
      klu_rcond(symbolic_, numeric_, &common_) && common_.rcond > kMinPivotRatio) {
    return true;
  }
  // First factorisation, or the pivots chosen earlier went bad: factor afresh with pivoting.
  if (numeric_ != nullptr) klu_free_numeric(&numeric_, &common_);
  // The fresh pivots are held to the same bound: a matrix singular to working precision is refused
  // whichever solver factorises it (row_scaling.h).
  numeric_ = klu_factor(columns, rows, values, symbolic_, &common_);
  return numeric_ != nullptr && common_.status == KLU_OK &&
         klu_rcond(symbolic_, numeric_, &common_) && common_.rcond > kMinPivotRatio;
}

void KluSolver::Solve(Eigen::VectorXd* rhs) {
  klu_solve(symbolic_, numeric_, static_cast<int>(rhs->size()), 1, rhs->data(), &common_);
}

}  // namespace isolab::integrators
