// Every eigenvalue of a symmetric tridiagonal matrix, without eigenvectors: the rational QL
// method (Reinsch's TQLRAT, EISPACK; the square-root-free QL iteration LAPACK's dsterf also
// uses). The model summary needs all the periods of a shear building (1000 of them at 1000
// stories, written to the results) but no mode shapes, where Eigen's implicit QR would spend
// three and a half times as many instructions.
//
// A sweep's steps form a chain of dependent divisions, which leaves the processor's divider
// mostly waiting on one matrix. Matrices given together are solved two at a time, their sweeps
// interleaved step by step in the two lanes of one vector: the same operations on the same
// values, so each matrix's eigenvalues are bit for bit those it gets alone.
#pragma once

#include <vector>

namespace isolab::analysis {

struct SymmetricTridiagonal {
  std::vector<double> diagonal;      // n entries
  std::vector<double> off_diagonal;  // n - 1 entries; entry i couples rows i and i + 1
};

// The eigenvalues of each matrix in ascending order. Throws std::runtime_error, for all of them,
// if an eigenvalue of one takes more than 30 iterations (never seen on a symmetric matrix).
std::vector<std::vector<double>> TridiagonalEigenvalues(std::vector<SymmetricTridiagonal> matrices);

// One matrix's.
std::vector<double> TridiagonalEigenvalues(std::vector<double> diagonal,
                                           const std::vector<double>& off_diagonal);

}  // namespace isolab::analysis
