// Property modification factors of a bearing type (ASCE 7-16 section 17.2.8.4): each property the
// engineer names (a law parameter of one of the bearing's components: a lead-rubber bearing's qd
// and kd, a friction pendulum's mu, any key of any other law) gets a (min, max) pair for testing,
// for ageing and environment, and for the specification tolerance, combined as ASCE 7-16
// Eqs. 17.2-1 and 17.2-2:
//
//   lambda_max = (1 + 0.75 (lambda_ae,max - 1)) lambda_test,max lambda_spec,max
//   lambda_min = (1 - 0.75 (1 - lambda_ae,min)) lambda_test,min lambda_spec,min
//
// (the 0.75 because the ageing and environmental extremes are unlikely to coincide with the
// others), or a combined (min, max) the engineer states. The upper-bound model has every named
// property at its nominal value times lambda_max, the lower-bound model times lambda_min
// (bounds.h writes them).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "isolab/core/errors.h"

namespace isolab::model {

// The share of the ageing and environmental factor's departure from 1 that is combined.
inline constexpr double kAgeingAdjustment = 0.75;

struct FactorPair {
  double min = 1.0;  // <= 1
  double max = 1.0;  // >= 1
};

// The ASCE 7-16 combination above.
FactorPair CombineFactors(const FactorPair& testing, const FactorPair& ageing,
                          const FactorPair& specification);

// The factors of one property of one component of a bearing type.
struct PropertyFactors {
  std::size_t component = 0;   // index into the bearing's components
  std::string component_name;  // its name
  std::string key;             // the law parameter, as the component gives it
  FactorPair testing, ageing, specification;
  std::optional<FactorPair> stated;  // the combined factors as the engineer states them
  SourceLocation location;           // where they are given

  // `stated`, or CombineFactors of the three.
  FactorPair Combined() const;
};

// The modification of one bearing type: a one-direction model's isolation, or one entry of a
// plan model's isolators (every isolator of a group).
struct BearingModification {
  std::string bearing;               // "isolation", or the plan entry's name
  std::optional<std::size_t> entry;  // plan.isolators[entry]; none: the isolation section
  std::vector<PropertyFactors> properties;
};

}  // namespace isolab::model
