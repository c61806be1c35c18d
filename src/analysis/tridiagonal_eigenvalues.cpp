#include "tridiagonal_eigenvalues.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace isolab::analysis {

std::vector<double> TridiagonalEigenvalues(std::vector<double> diagonal,
                                           const std::vector<double>& off_diagonal) {
  std::vector<double>& d = diagonal;
  const std::size_t n = d.size();
  if (n <= 1) return d;
  // e2[i]: the squared coupling of rows i and i + 1; the last is zero, so the search for a
  // negligible coupling always ends.
  std::vector<double> e2(n, 0.0);
  for (std::size_t i = 0; i + 1 < n; ++i) e2[i] = off_diagonal[i] * off_diagonal[i];
  double f = 0.0;  // the shifts so far: d holds the eigenvalues less f
  double t = 0.0, b = 0.0, c = 0.0;
  for (std::size_t l = 0; l < n; ++l) {
    double h = std::abs(d[l]) + std::sqrt(e2[l]);
    if (t <= h) {
      t = h;
      b = std::numeric_limits<double>::epsilon() * t;
      c = b * b;
    }
    std::size_t m = l;
    while (e2[m] > c) ++m;
    for (int iteration = 0; m != l; ++iteration) {
      if (iteration == 30) {
        throw std::runtime_error("the tridiagonal eigenvalue iteration did not converge");
      }
      // The shift: the eigenvalue of the leading 2 x 2 block nearer d[l].
      double s = std::sqrt(e2[l]);
      double g = d[l];
      double p = (d[l + 1] - g) / (2.0 * s);
      double r = std::hypot(p, 1.0);
      d[l] = s / (p + std::copysign(r, p));
      h = g - d[l];
      for (std::size_t i = l + 1; i < n; ++i) d[i] -= h;
      f += h;
      // One rational QL sweep from m up to l.
      g = d[m];
      if (g == 0.0) g = b;
      h = g;
      s = 0.0;
      for (std::size_t i = m; i-- > l;) {
        p = g * h;
        r = p + e2[i];
        e2[i + 1] = s * r;
        s = e2[i] / r;
        d[i + 1] = h + s * (h + d[i]);
        g = d[i] - e2[i] / g;
        if (g == 0.0) g = b;
        h = g * p / r;
      }
      e2[l] = s * g;
      d[l] = h;
      // Converged when the coupling is negligible (guarded against underflow).
      if (h == 0.0 || std::abs(e2[l]) <= std::abs(c / h)) break;
      e2[l] *= h;
      if (e2[l] == 0.0) break;
    }
    // The eigenvalue, inserted in order among those found.
    const double eigenvalue = d[l] + f;
    std::size_t i = l;
    for (; i > 0 && eigenvalue < d[i - 1]; --i) d[i] = d[i - 1];
    d[i] = eigenvalue;
  }
  return d;
}

}  // namespace isolab::analysis
