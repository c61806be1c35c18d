// Dense LU with partial pivoting (LAPACK's getf2, unblocked) of a small effective tangent: the
// pattern's entries scattered into an n x n array sized once, rows scaled as KLU scales them
// (row_scaling.h); or, for a symmetric tangent with positive pivots (the usual one), LDL^T
// without pivoting, half the work. For the few dofs of an SDOF or a five-story building this is
// a few hundred multiply-adds against KLU's general sparse machinery (tangent_solver.h says when
// it is chosen).
// Up to kDenseFixedDofs dofs the kernels are compiled for each size, so that their short loops
// are unrolled: at run time a loop of 2 to 6 trips costs more in set-up (vectorised prologues and
// epilogues) than in arithmetic.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "isolab/structure/structure.h"

namespace isolab::integrators {

inline constexpr int kDenseFixedDofs = 12;

class DenseLu {
 public:
  explicit DenseLu(const structure::SparseMatrix& pattern);
  DenseLu(const DenseLu&) = delete;  // arrays_ points into the object's own vectors
  DenseLu& operator=(const DenseLu&) = delete;

  // False when the matrix is singular to working precision (row_scaling.h); `matrix` has the
  // pattern given to the constructor. Both calls are defined here so that the step inlines them
  // whatever else its translation unit holds.
  bool Factorize(const structure::SparseMatrix& matrix) {
    return factorize_(arrays_, matrix.valuePtr());
  }
  // Overwrites `rhs` with the solution.
  void Solve(Eigen::VectorXd* rhs) const { solve_(arrays_, rhs->data()); }

  // One size's kernels work on these (DenseLu's own arrays).
  struct Arrays {
    int n;
    double* lu;                // column-major: L below the diagonal (unit), U on and above
                               // (LDL^T: D on the diagonal, the upper triangle unused)
    double* inverse_diagonal;  // 1 / u_kk (LDL^T: 1 / d_k)
    int* pivots;               // row exchanged with row k at step k
    double* scales;            // 1 / largest magnitude of each row
    bool* symmetric;           // the last factorisation was LDL^T
    const int* positions;      // of each stored entry of the pattern in lu
    int entries;
  };
  using Factorizer = bool (*)(const Arrays&, const double* values);
  using Solver = void (*)(const Arrays&, double* rhs);

 private:
  int n_;
  std::vector<int> positions_;
  std::vector<double> lu_;
  std::vector<double> inverse_diagonal_;
  std::vector<int> pivots_;
  std::vector<double> row_scales_;
  bool symmetric_ = false;
  Arrays arrays_;  // points into the vectors above, which are never resized
  Factorizer factorize_;
  Solver solve_;
};

}  // namespace isolab::integrators
