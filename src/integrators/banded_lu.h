// Banded LU with partial pivoting (LAPACK's gbtf2/gbtrs, unblocked) of an effective tangent whose
// entries lie within kl diagonals below and ku above the main one: a one-direction shear building
// without mass-proportional damping is tridiagonal. Storage is LAPACK's band layout with kl extra
// rows for the fill that row exchanges bring into U, sized once; rows are scaled as KLU scales
// them (row_scaling.h). Work per factorisation is O(n kl (kl + ku)), with no index arrays.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "isolab/structure/structure.h"

namespace isolab::integrators {

// The lower and upper bandwidths of a pattern: the largest i - j and j - i of its entries.
struct Bandwidths {
  int lower = 0, upper = 0;
};
Bandwidths BandwidthsOf(const structure::SparseMatrix& pattern);

class BandedLu {
 public:
  explicit BandedLu(const structure::SparseMatrix& pattern);

  // False when the matrix is singular to working precision (row_scaling.h); `matrix` has the
  // pattern given to the constructor.
  bool Factorize(const structure::SparseMatrix& matrix);
  // Overwrites `rhs` with the solution.
  void Solve(Eigen::VectorXd* rhs) const;

 private:
  // Entry (row r, column c) of the band storage: LAPACK's ab(kl + ku + r - c, c) with a leading
  // dimension of 2 kl + ku + 1, so a row runs at stride 2 kl + ku.
  double& At(int r, int c) { return band_[kv_ + r + c * stride_]; }
  double At(int r, int c) const { return band_[kv_ + r + c * stride_]; }

  int n_, kl_, ku_, kv_, stride_;
  std::vector<int> positions_;  // of each stored entry of the pattern in band_
  std::vector<double> band_;
  std::vector<int> pivots_;         // row exchanged with row k at step k
  std::vector<double> row_scales_;  // 1 / largest magnitude of each row
};

}  // namespace isolab::integrators
