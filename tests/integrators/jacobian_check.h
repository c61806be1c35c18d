// The rate-form system's Jacobian against central differences of its residual, at a state inside
// the phases every law starts in, shared by the tests of the system's structures.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "rate_form_system.h"

namespace isolab::integrators::testing {

inline void ExpectJacobianIsTheDerivativeOfTheResidual(RateFormSystem& system) {
  const int n = system.size();
  // Small nonzero displacements, velocities and internal variables: the laws still stick on
  // their inner segments, where they start.
  Eigen::VectorXd y(n), yp(n);
  for (int i = 0; i < n; ++i) {
    y[i] = 0.01 * std::sin(1.0 + i);
    yp[i] = 0.3 * std::cos(2.0 + i);
  }
  const double t = 1.234, cj = 250.0;
  const auto& pattern = system.jacobian_pattern();
  std::vector<double> values(pattern.nonZeros());
  system.Jacobian(t, cj, y.data(), values.data());
  structure::SparseMatrix jacobian = pattern;
  std::copy(values.begin(), values.end(), jacobian.valuePtr());
  const Eigen::MatrixXd analytic(jacobian);

  Eigen::MatrixXd numeric(n, n);
  Eigen::VectorXd plus(n), minus(n);
  const double h = 1e-7;
  for (int j = 0; j < n; ++j) {
    // d/dy_j + cj d/dy'_j, as IDA defines its Jacobian.
    Eigen::VectorXd y1 = y, yp1 = yp;
    y1[j] += h;
    yp1[j] += cj * h;
    system.Residual(t, y1.data(), yp1.data(), plus.data());
    y1[j] -= 2 * h;
    yp1[j] -= 2 * cj * h;
    system.Residual(t, y1.data(), yp1.data(), minus.data());
    numeric.col(j) = (plus - minus) / (2 * h);
  }
  const double scale = analytic.cwiseAbs().maxCoeff();
  EXPECT_LT((analytic - numeric).cwiseAbs().maxCoeff(), 1e-6 * scale) << "analytic\n"
                                                                      << analytic << "\nnumeric\n"
                                                                      << numeric;
}

}  // namespace isolab::integrators::testing
