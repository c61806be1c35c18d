#include "row_scaling.h"

#include <algorithm>
#include <cmath>

namespace isolab::integrators {

bool InverseRowScales(const structure::SparseMatrix& matrix, std::vector<double>* inverse) {
  std::vector<double>& scale = *inverse;
  std::fill(scale.begin(), scale.end(), 0.0);
  const int* rows = matrix.innerIndexPtr();
  const double* values = matrix.valuePtr();
  const int entries = static_cast<int>(matrix.nonZeros());  // a sum in Eigen: once, not per entry
  for (int k = 0; k < entries; ++k) {
    scale[rows[k]] = std::max(scale[rows[k]], std::abs(values[k]));
  }
  for (double& s : scale) {
    if (!(s > 0.0 && std::isfinite(s))) return false;
    s = 1.0 / s;
  }
  return true;
}

}  // namespace isolab::integrators
