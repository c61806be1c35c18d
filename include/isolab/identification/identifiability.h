// Whether a fit's parameters are separately determined by the data, read off the fit itself:
//
//  * Cancelling components. Two components whose forces over the tested histories point against
//    each other and mostly cancel (a spring of +3.02 beside a THM1 of -3.08 force/length): the
//    data see only their small sum, so each one's size is not identified and neither is
//    physical. Measured on the forces themselves, weighted per test as e^2 is: the opposition
//    -<f_a, f_b> / (|f_a| |f_b|) and the sum's size |f_a + f_b| against the smaller part. Each
//    component's secant stiffness over the tests, <f, u> / <u, u>, says it in stiffnesses.
//  * Parameters at their bounds: a shape coordinate at either end of its range (the data push it
//    out of what the specification allows) and a stiffness the sign constraint holds at zero.
//  * Strongly correlated pairs: the correlation of two parameters' estimates, from the Jacobian
//    J of the weighted residual at the fit (shape coordinates by central differences in the unit
//    cube, stiffnesses exactly: their columns are the basis forces), C = (J^T J)^-1 scaled to a
//    unit diagonal. |C_ij| near 1 means the data fix only a combination of the two. Parameters
//    at a bound are left out: the constraint, not the data, holds them.
#pragma once

#include <string>
#include <vector>

#include "isolab/identification/fit.h"

namespace isolab::identification {

struct IdentifiabilityOptions {
  double opposition = 0.9;     // cancelling: -cos of the angle between the forces, in (0, 1]
  double cancelled_sum = 0.5;  // cancelling: |f_a + f_b| below this share of the smaller part
  double correlation = 0.95;   // a pair is reported from this |correlation|, in (0, 1]
  double bound_margin = 1e-3;  // a shape coordinate this close to 0 or 1 (unit cube) is at a bound

  // Throws InvalidParameter naming the first field out of range.
  void Validate() const;
};

struct ComponentContribution {
  std::string name;
  double rms_force = 0.0;   // over the fitted samples, weighted per test as e^2 (force)
  double peak_force = 0.0;  // largest |force| over the fitted samples (force)
  double secant = 0.0;      // <f, u> / <u, u> over the fitted samples (force/length)
};

struct CancellingPair {
  std::size_t a = 0, b = 0;  // component indices, a < b
  double opposition = 0.0;   // -cos of the angle between their forces
  double sum_share = 0.0;    // |f_a + f_b| / min(|f_a|, |f_b|)
  std::string finding;       // one sentence with the numbers
};

struct BoundParameter {
  std::string name;  // "c1.uy", "base.k0-k1"
  double value = 0.0;
  std::string where;  // "lower bound", "upper bound", "zero (sign constraint)"
};

struct CorrelatedPair {
  std::string a, b;
  double correlation = 0.0;
};

struct Identifiability {
  std::vector<ComponentContribution> components;
  double device_peak_force = 0.0;  // largest |measured force| over the fitted samples
  std::vector<CancellingPair> cancelling;
  std::vector<BoundParameter> at_bounds;
  std::vector<CorrelatedPair> correlated;  // strongest first
  // The Jacobian has a direction the data do not see at all (singular to round-off), and the
  // parameters that direction moves most (weights above 0.3 of the unit direction).
  bool singular = false;
  std::vector<std::string> unseen;

  bool Cancels(std::size_t component) const;
  // Sentences for a reader: cancelling pairs, components far larger than the device, bounds, the
  // unseen combination, the three most correlated pairs (all are in `correlated`); empty when
  // nothing is wrong.
  std::vector<std::string> Findings() const;
};

Identifiability AssessIdentifiability(const ModelParametrisation& model, const FitData& data,
                                      const FitResult& fit,
                                      const IdentifiabilityOptions& options = {});

}  // namespace isolab::identification
