// Eigenvalues of a symmetric tridiagonal pencil (K, M) with M diagonal and positive, the
// stiffness and lumped masses of a shear building, one at a time by Sturm-sequence bisection
// (Wilkinson 1965; Golub & Van Loan 2013, Sec. 8.4.1): the number of eigenvalues below x is the
// number of negative pivots of K - x M (Sylvester's law of inertia), which the LDL^T recurrence
// gives in O(n). Bisection on that count halves an interval holding eigenvalue k until it is a
// few ulps wide (about 70 counts for the first mode of 1000 stories), so a few modes of a tall
// building cost O(n), where a dense eigensolution costs O(n^3) and gives every mode.
#pragma once

#include <Eigen/Core>

namespace isolab::structure {

struct TridiagonalPencil {
  Eigen::VectorXd diagonal;      // K_ii (n)
  Eigen::VectorXd off_diagonal;  // K_i,i+1 (n - 1)
  Eigen::VectorXd mass;          // M_ii (n), > 0

  // How many eigenvalues lie below x.
  int CountBelow(double x) const;

  // Eigenvalue k (1-based, ascending), to within a few units in the last place of the largest
  // eigenvalue's magnitude.
  double Eigenvalue(int k) const;
};

}  // namespace isolab::structure
