#include "tangent_solver.h"

#include <utility>

namespace isolab::integrators {

// NewmarkOptions::LinearSolver is spelt out: ida.cpp has a LinearSolver of its own, and the unity
// build puts both files in one translation unit.
NewmarkOptions::LinearSolver ChooseLinearSolver(const structure::SparseMatrix& pattern,
                                                NewmarkOptions::LinearSolver requested) {
  if (requested != NewmarkOptions::LinearSolver::kAuto) return requested;
  if (pattern.rows() <= kDenseMaxDofs) return NewmarkOptions::LinearSolver::kDense;
  const BandStructure band = BandStructureOf(pattern);
  if (band.lower + band.upper <= kBandedMaxWidth) return NewmarkOptions::LinearSolver::kBanded;
  return NewmarkOptions::LinearSolver::kKlu;
}

TangentSolver::TangentSolver(const structure::SparseMatrix& pattern,
                             NewmarkOptions::LinearSolver requested)
    : kind_(ChooseLinearSolver(pattern, requested)),
      solver_(Make(pattern, kind_)),
      factored_values_(static_cast<std::size_t>(pattern.nonZeros())) {}

TangentSolver::Solver TangentSolver::Make(const structure::SparseMatrix& pattern,
                                          NewmarkOptions::LinearSolver kind) {
  // Each return is a prvalue, so the variant is built in place (KluSolver cannot be moved).
  switch (kind) {
    case NewmarkOptions::LinearSolver::kDense:
      return Solver(std::in_place_type<DenseLu>, pattern);
    case NewmarkOptions::LinearSolver::kBanded:
      return Solver(std::in_place_type<BandedLu>, pattern);
    case NewmarkOptions::LinearSolver::kAuto:
    case NewmarkOptions::LinearSolver::kKlu:
      break;
  }
  return Solver(std::in_place_type<KluSolver>, pattern);
}

}  // namespace isolab::integrators
