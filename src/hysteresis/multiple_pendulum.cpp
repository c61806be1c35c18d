#include "isolab/hysteresis/multiple_pendulum.h"

#include <algorithm>
#include <cmath>

namespace isolab::hysteresis {
namespace {

// The spring ke before any surface slides: the bearing reaches the lowest friction at u_y.
double PreSlideStiffness(double weight, std::span<const double> friction, double uy) {
  return *std::min_element(friction.begin(), friction.end()) * weight / uy;
}

// R_outer / R_inner of the pair (outer, inner) of a triple pendulum, from its series model:
// k_outer / k_inner = R_inner / (R_outer - R_inner).
double InnerRatio(const SeriesArrangement& series, int outer, int inner) {
  return series.elements[outer].stiffness / series.elements[inner].stiffness;
}

}  // namespace

SeriesArrangement DoublePendulum::Series() const {
  SeriesArrangement series;
  series.ke = PreSlideStiffness(weight, friction, uy);
  series.count = 2;
  for (int i = 0; i < 2; ++i) {
    series.elements[i] = {friction[i] * weight, weight / radius[i], capacity[i]};
  }
  return series;
}

SeriesArrangement TriplePendulum::Series() const {
  const auto& r = radius;
  const auto& d = capacity;
  SeriesArrangement series;
  series.ke = PreSlideStiffness(weight, friction, uy);
  series.count = 4;
  series.elements[0] = {friction[0] * weight, weight / (r[0] - r[1]), d[0] * (r[0] - r[1]) / r[0]};
  series.elements[1] = {friction[1] * weight, weight / r[1], d[1] + d[0] * r[1] / r[0]};
  series.elements[2] = {friction[2] * weight, weight / r[2], d[2] + d[3] * r[2] / r[3]};
  series.elements[3] = {friction[3] * weight, weight / (r[3] - r[2]), d[3] * (r[3] - r[2]) / r[3]};
  return series;
}

bool StopEngaged(const SeriesArrangement& series, std::span<const LawState> elements, int k) {
  return std::abs(elements[k].slider) == series.elements[k].stop;
}

PendulumRegime TriplePendulumRegime(const SeriesArrangement& series,
                                    std::span<const LawState> elements) {
  if (StopEngaged(series, elements, 1) || StopEngaged(series, elements, 2)) {
    return PendulumRegime::kBeyondV;
  }
  bool sliding = false;
  for (int k = 0; k < 4; ++k) sliding = sliding || elements[k].slip != 0;
  if (!sliding) return PendulumRegime::kSticking;
  const int outer_stops = StopEngaged(series, elements, 0) + StopEngaged(series, elements, 3);
  if (outer_stops == 2) return PendulumRegime::kV;
  if (outer_stops == 1) return PendulumRegime::kIV;
  const int outer_sliding = (elements[0].slip != 0) + (elements[3].slip != 0);
  if (outer_sliding == 2) return PendulumRegime::kIII;
  return outer_sliding == 1 ? PendulumRegime::kII : PendulumRegime::kI;
}

std::array<double, 4> TriplePendulumSurfaceDisplacements(const SeriesArrangement& series,
                                                         std::span<const LawState> elements) {
  const double ratio_1 = InnerRatio(series, 0, 1), ratio_4 = InnerRatio(series, 3, 2);
  const double z1 = elements[0].slider, z4 = elements[3].slider;
  return {z1 * (1.0 + ratio_1), elements[1].slider - z1 * ratio_1,
          elements[2].slider - z4 * ratio_4, z4 * (1.0 + ratio_4)};
}

std::array<double, 4> TriplePendulumCapacityUsed(const SeriesArrangement& series,
                                                 std::span<const LawState> elements) {
  const std::array<double, 4> u = TriplePendulumSurfaceDisplacements(series, elements);
  const double ratio_1 = InnerRatio(series, 0, 1), ratio_4 = InnerRatio(series, 3, 2);
  const double d1 = series.elements[0].stop, d4 = series.elements[3].stop;
  // The same expressions as the displacements', so a surface at its restrainer reads exactly 1.
  const std::array<double, 4> capacity = {
      d1 * (1.0 + ratio_1), series.elements[1].stop - d1 * ratio_1,
      series.elements[2].stop - d4 * ratio_4, d4 * (1.0 + ratio_4)};
  std::array<double, 4> used{};
  for (int i = 0; i < 4; ++i) used[i] = std::abs(u[i]) / capacity[i];
  return used;
}

}  // namespace isolab::hysteresis
