#include "tridiagonal_pencil.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace isolab::structure {

int TridiagonalPencil::CountBelow(double x) const {
  const Eigen::Index n = diagonal.size();
  // A pivot that vanishes is replaced by a tiny negative one (LAPACK's dstebz does the same), so
  // an eigenvalue exactly at x is not counted below it and the recurrence never divides by 0.
  const double smallest_pivot =
      std::numeric_limits<double>::min() *
      std::max(1.0, off_diagonal.size() ? off_diagonal.squaredNorm() : 0.0);
  int count = 0;
  double pivot = 1.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    pivot = diagonal[i] - x * mass[i] -
            (i > 0 ? off_diagonal[i - 1] * off_diagonal[i - 1] / pivot : 0.0);
    if (std::abs(pivot) <= smallest_pivot) pivot = -smallest_pivot;
    count += pivot < 0.0;
  }
  return count;
}

double TridiagonalPencil::Eigenvalue(int k) const {
  const Eigen::Index n = diagonal.size();
  if (k < 1 || k > n) throw std::out_of_range("TridiagonalPencil::Eigenvalue: no such mode");
  // Gershgorin discs of M^-1 K (similar to the symmetric M^-1/2 K M^-1/2) bound the spectrum.
  double lower = INFINITY, upper = -INFINITY;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double radius = ((i > 0 ? std::abs(off_diagonal[i - 1]) : 0.0) +
                           (i + 1 < n ? std::abs(off_diagonal[i]) : 0.0)) /
                          mass[i];
    lower = std::min(lower, diagonal[i] / mass[i] - radius);
    upper = std::max(upper, diagonal[i] / mass[i] + radius);
  }
  const double margin =
      4.0 * std::numeric_limits<double>::epsilon() * std::max(std::abs(lower), std::abs(upper)) +
      std::numeric_limits<double>::min();
  lower -= margin;  // CountBelow(lower) = 0 < k
  upper += margin;  // CountBelow(upper) = n >= k
  // Halve [lower, upper] while it holds eigenvalue k (CountBelow(lower) < k <= CountBelow(upper))
  // until its midpoint is no longer strictly inside: the interval is then a few ulps wide.
  for (;;) {
    const double middle = 0.5 * (lower + upper);
    if (!(middle > lower && middle < upper)) break;
    if (CountBelow(middle) >= k) {
      upper = middle;
    } else {
      lower = middle;
    }
  }
  return 0.5 * (lower + upper);
}

}  // namespace isolab::structure
