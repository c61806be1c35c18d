#include "multiple_pendulum_parameters.h"

#include <fmt/format.h>

#include "isolab/hysteresis/multiple_pendulum.h"

namespace isolab::hysteresis {
namespace {

constexpr std::string_view kDoubleKeys[] = {"w", "r1", "r2", "mu1", "mu2", "d1", "d2", "uy"};
constexpr std::string_view kTripleKeys[] = {"w",   "r1",  "r2", "r3", "r4", "mu1", "mu2",
                                            "mu3", "mu4", "d1", "d2", "d3", "d4",  "uy"};

// The series model (multiple_pendulum.h) splits surface 1 (4) into a pendulum of radius
// R1 - R2 (R4 - R3) after the inner surface's: it needs R1 > R2, and the inner surface sliding
// before the outer one (with mu2 > mu1 surface 1 would slide first, on its own radius, which the
// series model does not represent).
void CheckOuterAndInner(const RuleChecker& r, std::string_view outer, std::string_view inner,
                        std::string_view mu_outer, std::string_view mu_inner) {
  r.Holds(outer, r(outer) > r(inner),
          fmt::format("must be > {} = {:g}: the series model's element for surface {} is a "
                      "pendulum of radius {} - {} (Fenz & Constantinou 2008)",
                      inner, r(inner), outer.substr(1), outer, inner));
  r.Holds(mu_inner, r(mu_inner) <= r(mu_outer),
          fmt::format("must be <= {} = {:g}: the inner surface slides before the outer one in "
                      "the series model (the triple pendulum's standard configuration)",
                      mu_outer, r(mu_outer)));
}

// In regime I the inner slider moves on surface 2 (3) alone until the force reaches surface 1's
// (4's) friction: by (mu1 - mu2) r2 (the pendulum's travel between the two frictions). An inner
// capacity below that puts the slider against its restrainer before surface 1 slides, and the
// bearing stiffens there; the series model has no such stop (its inner element stops only at
// d2 + d1 r2 / r1), so it would run on as if the restrainer were not there.
void CheckInnerCapacity(const RuleChecker& r, std::string_view capacity, std::string_view radius,
                        std::string_view mu_outer, std::string_view mu_inner) {
  const double travel = (r(mu_outer) - r(mu_inner)) * r(radius);
  r.Holds(capacity, r(capacity) >= travel,
          fmt::format("must be >= ({} - {}) {} = {:g}, the inner slider's travel before the outer "
                      "surface slides: a smaller inner capacity stops the slider in regime I, "
                      "which the series model (Fenz & Constantinou 2008) does not represent",
                      mu_outer, mu_inner, radius, travel));
}

}  // namespace

bool IsMultiplePendulum(LawType type) {
  return type == LawType::kDoubleFrictionPendulum || type == LawType::kTripleFrictionPendulum;
}

Keys MultiplePendulumKeys(LawType type) {
  return type == LawType::kDoubleFrictionPendulum ? Keys(kDoubleKeys) : Keys(kTripleKeys);
}

void ValidateMultiplePendulum(LawType type, const ParameterArray& values) {
  const Keys keys = MultiplePendulumKeys(type);
  const RuleChecker r(keys, values);
  for (const std::string_view key : keys) r.Greater(key, 0.0);
  if (type == LawType::kTripleFrictionPendulum) {
    CheckOuterAndInner(r, "r1", "r2", "mu1", "mu2");
    CheckOuterAndInner(r, "r4", "r3", "mu4", "mu3");
    CheckInnerCapacity(r, "d2", "r2", "mu1", "mu2");
    CheckInnerCapacity(r, "d3", "r3", "mu4", "mu3");
  }
}

LawKernel MultiplePendulumKernel(LawType type, const ParameterArray& v) {
  if (type == LawType::kDoubleFrictionPendulum) {
    return DoublePendulum{v[0], {v[1], v[2]}, {v[3], v[4]}, {v[5], v[6]}, v[7]}.Series();
  }
  return TriplePendulum{
      v[0], {v[1], v[2], v[3], v[4]}, {v[5], v[6], v[7], v[8]}, {v[9], v[10], v[11], v[12]}, v[13]}
      .Series();
}

}  // namespace isolab::hysteresis
