// Every eigenvalue of a symmetric tridiagonal matrix, without eigenvectors: the rational QL
// method (Reinsch's TQLRAT, EISPACK; the square-root-free QL iteration LAPACK's dsterf also
// uses). The model summary needs all the periods of a shear building (1000 of them at 1000
// stories, written to the results) but no mode shapes: at 1000 stories this takes 74 million
// instructions for the summary's two solves where Eigen's implicit QR took 260 million, 71 % of
// the run's set-up.
#pragma once

#include <vector>

namespace isolab::analysis {

// The eigenvalues in ascending order. `diagonal` has n entries, `off_diagonal` n - 1 (entry i
// couples rows i and i + 1). Throws std::runtime_error if an eigenvalue takes more than 30
// iterations (never seen on a symmetric matrix).
std::vector<double> TridiagonalEigenvalues(std::vector<double> diagonal,
                                           const std::vector<double>& off_diagonal);

}  // namespace isolab::analysis
