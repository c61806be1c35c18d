// Banded LU with partial pivoting (LAPACK's gbtf2/gbtrs, unblocked) of an effective tangent whose
// entries lie within kl diagonals below and ku above the main one, apart from a few "border" dofs
// coupled to many others. A one-direction shear building is tridiagonal; relative Rayleigh
// damping's mass-proportional part adds a full row and column on the base (every floor's velocity
// is taken relative to it), and a plan building's three base dofs do the same.
//
// The border dofs are ordered last, so the matrix is [A B; C D] with A banded:
//   A = P L U (band storage, LAPACK's layout with kl extra rows for the fill of row exchanges),
//   W = A^-1 B, S = D - C W (dense, m x m, LU with partial pivoting),
// and A x1 + B x2 = b1, C x1 + D x2 = b2 is solved as x2 = S^-1 (b2 - C A^-1 b1),
// x1 = A^-1 b1 - W x2. Pivoting stays within A and within S (block elimination): the tangents
// this serves have mass on every dof, so A is never singular where the whole matrix is not. Rows
// are scaled as KLU scales them and the pivots of A and S together are held to KLU's bound
// (row_scaling.h). Work per factorisation is O(n (kl (kl + ku) + m (kl + ku + m))), storage sized
// once, no index arrays in the elimination.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "isolab/structure/structure.h"
#include "row_scaling.h"

namespace isolab::integrators {

// How a pattern splits into a band and a border. Border dofs are those with more than
// kBorderEntries entries in their row and column together, at most kMaxBorderDofs of them (with
// more, none: the pattern is then only banded if its whole bandwidth is small); the bandwidths are
// those of the remaining dofs in their own order.
struct BandStructure {
  int lower = 0, upper = 0;  // largest i - j and j - i among the band's entries
  std::vector<int> border;   // dofs ordered last, increasing
};
inline constexpr int kBorderEntries = 20;
inline constexpr int kMaxBorderDofs = 6;
BandStructure BandStructureOf(const structure::SparseMatrix& pattern);

class BandedLu {
 public:
  explicit BandedLu(const structure::SparseMatrix& pattern);

  // False when the matrix is singular to working precision (row_scaling.h); `matrix` has the
  // pattern given to the constructor.
  bool Factorize(const structure::SparseMatrix& matrix);
  // Overwrites `rhs` with the solution.
  void Solve(Eigen::VectorXd* rhs);

 private:
  // Entry (row r, column c) of A's band storage: LAPACK's ab(kl + ku + r - c, c) with a leading
  // dimension of 2 kl + ku + 1, so a row runs at stride 2 kl + ku.
  double& At(int r, int c) { return values_[kv_ + r + c * stride_]; }
  double At(int r, int c) const { return values_[kv_ + r + c * stride_]; }
  // x <- A^-1 x for the band's nb_ entries of x, with A's factors.
  void BandSolve(double* x) const;
  template <int kKl>
  bool FactorBand(PivotRatio* ratio);
  template <int kKl>
  void SolveBand(double* x) const;

  int n_, nb_, m_;  // dofs, band dofs, border dofs
  int kl_, ku_, kv_, stride_;
  std::vector<int> order_;          // original dof of each position: the band's, then the border's
  std::vector<double> row_scales_;  // 1 / largest magnitude of each row (original order)
  // The factors, [A | B | C | D]: A's band storage, B (then W) column-major nb x m, C row-major
  // m x nb, D (then S's LU) column-major m x m; and the position there of each stored entry of the
  // pattern.
  std::vector<double> values_;
  int b_offset_, c_offset_, d_offset_;
  std::vector<int> positions_;
  std::vector<int> pivots_;               // A's: row exchanged with row k at step k
  std::vector<double> inverse_diagonal_;  // 1 / u_kk of A's factor U
  std::vector<int> border_pivots_;        // S's
  std::vector<double> work_;              // the right-hand side in the band-then-border order
};

}  // namespace isolab::integrators
