// A rate-form system's Jacobian (rate_form_system.h) against central
// differences of its residual, at a given state or at one inside the phases every law starts in,
// shared by the tests of the systems' structures.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "rate_form_system.h"

namespace isolab::integrators::testing {

// At (y, yp) under the system's current phases; steps[j] is the difference step of state j
// (states of different units and curvature, a floor's rotation beside its translations, need
// their own).
template <class System>
void ExpectJacobianAt(System& system, const Eigen::VectorXd& y, const Eigen::VectorXd& yp,
                      const Eigen::VectorXd& steps) {
  const int n = system.size();
  const double t = 1.234, cj = 250.0;
  const auto& pattern = system.jacobian_pattern();
  std::vector<double> values(pattern.nonZeros());
  system.Jacobian(t, cj, y.data(), values.data());
  structure::SparseMatrix jacobian = pattern;
  std::copy(values.begin(), values.end(), jacobian.valuePtr());
  const Eigen::MatrixXd analytic(jacobian);

  Eigen::MatrixXd numeric(n, n);
  Eigen::VectorXd plus(n), minus(n);
  for (int j = 0; j < n; ++j) {
    const double h = steps[j];
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
  // Row by row: an equation's round-off scales with its own largest entry, and a plan model's
  // rows differ by orders of magnitude (a rotation's inertia against a slider's rate).
  for (int i = 0; i < n; ++i) {
    const double scale = analytic.row(i).cwiseAbs().maxCoeff();
    EXPECT_LE((analytic.row(i) - numeric.row(i)).cwiseAbs().maxCoeff(), 1e-6 * scale)
        << "row " << i << "\nanalytic " << analytic.row(i) << "\nnumeric  " << numeric.row(i);
  }
}

template <class System>
void ExpectJacobianIsTheDerivativeOfTheResidual(System& system) {
  const int n = system.size();
  // Small nonzero displacements, velocities and internal variables: the laws still stick on
  // their inner segments, where they start.
  Eigen::VectorXd y(n), yp(n);
  for (int i = 0; i < n; ++i) {
    y[i] = 0.01 * std::sin(1.0 + i);
    yp[i] = 0.3 * std::cos(2.0 + i);
  }
  ExpectJacobianAt(system, y, yp, Eigen::VectorXd::Constant(n, 1e-7));
}

}  // namespace isolab::integrators::testing
