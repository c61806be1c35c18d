// What the small-system factorisations (dense_lu.h, banded_lu.h) share with KLU's defaults: rows
// scaled by their largest magnitude before pivoting, and a factorisation refused as singular to
// working precision when its pivot ratio min |u_kk| / max |u_kk| (of the scaled matrix) is at or
// below 1e-12, the estimate and threshold klu_solver.cpp applies to klu_rcond. Scaling makes the
// ratio independent of each equation's unit (a floor's rotation next to its translations).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "isolab/structure/structure.h"

namespace isolab::integrators {

inline constexpr double kMinPivotRatio = 1e-12;

// 1 / max_j |a_ij| of each row of `matrix` into `inverse` (sized once by the caller); false when a
// row is zero or not finite, a matrix singular before any pivot is chosen.
bool InverseRowScales(const structure::SparseMatrix& matrix, std::vector<double>* inverse);

// Tracks the pivots' magnitudes during a factorisation.
class PivotRatio {
 public:
  void Add(double pivot) {
    const double size = pivot < 0.0 ? -pivot : pivot;
    if (!(size <= kHuge)) finite_ = false;  // infinite or NaN
    if (size < smallest_) smallest_ = size;
    if (size > largest_) largest_ = size;
  }
  // True when every pivot was finite and the ratio is above kMinPivotRatio (false on NaN too).
  bool Acceptable() const { return finite_ && smallest_ > kMinPivotRatio * largest_; }

 private:
  static constexpr double kHuge = 1.7976931348623157e308;
  double smallest_ = kHuge, largest_ = 0.0;
  bool finite_ = true;
};

}  // namespace isolab::integrators
