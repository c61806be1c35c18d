#include "tangent_solver.h"

#include <utility>

namespace isolab::integrators {

using LinearSolver = NewmarkOptions::LinearSolver;

LinearSolver ChooseLinearSolver(const structure::SparseMatrix& pattern, LinearSolver requested) {
  if (requested != LinearSolver::kAuto) return requested;
  if (pattern.rows() <= kDenseMaxDofs) return LinearSolver::kDense;
  const BandStructure band = BandStructureOf(pattern);
  if (band.lower + band.upper <= kBandedMaxWidth) return LinearSolver::kBanded;
  return LinearSolver::kKlu;
}

TangentSolver::TangentSolver(const structure::SparseMatrix& pattern, LinearSolver requested)
    : kind_(ChooseLinearSolver(pattern, requested)), solver_(Make(pattern, kind_)) {}

TangentSolver::Solver TangentSolver::Make(const structure::SparseMatrix& pattern,
                                          LinearSolver kind) {
  // Each return is a prvalue, so the variant is built in place (KluSolver cannot be moved).
  switch (kind) {
    case LinearSolver::kDense:
      return Solver(std::in_place_type<DenseLu>, pattern);
    case LinearSolver::kBanded:
      return Solver(std::in_place_type<BandedLu>, pattern);
    case LinearSolver::kAuto:
    case LinearSolver::kKlu:
      break;
  }
  return Solver(std::in_place_type<KluSolver>, pattern);
}

bool TangentSolver::Factorize(structure::SparseMatrix& matrix) {
  return std::visit([&](auto& solver) { return solver.Factorize(matrix); }, solver_);
}

void TangentSolver::Solve(Eigen::VectorXd* rhs) {
  std::visit([&](auto& solver) { solver.Solve(rhs); }, solver_);
}

}  // namespace isolab::integrators
