#include "isolab/hysteresis/multiple_pendulum.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace isolab::hysteresis {
namespace {

// The spring ke before any surface slides: the bearing reaches the lowest friction at u_y.
double PreSlideStiffness(double weight, std::span<const double> friction, double uy) {
  return *std::min_element(friction.begin(), friction.end()) * weight / uy;
}

void RequireTriple(const SeriesArrangement& series) {
  if (series.count != 4) {
    throw std::invalid_argument("a triple pendulum's series model has four elements");
  }
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

namespace {

PendulumRegime Regime(std::array<bool, 4> sliding, std::array<bool, 4> at_stop) {
  if (at_stop[1] || at_stop[2]) return PendulumRegime::kBeyondV;
  if (!(sliding[0] || sliding[1] || sliding[2] || sliding[3])) return PendulumRegime::kSticking;
  const int outer_stops = at_stop[0] + at_stop[3];
  if (outer_stops == 2) return PendulumRegime::kV;
  if (outer_stops == 1) return PendulumRegime::kIV;
  const int outer_sliding = sliding[0] + sliding[3];
  if (outer_sliding == 2) return PendulumRegime::kIII;
  return outer_sliding == 1 ? PendulumRegime::kII : PendulumRegime::kI;
}

// u_i from the elements' z_k (the header's map), for numbers or plan vectors.
template <class V>
std::array<V, 4> Surfaces(const SeriesArrangement& series, const std::array<V, 4>& z) {
  const double ratio_1 = InnerRatio(series, 0, 1), ratio_4 = InnerRatio(series, 3, 2);
  return {(1.0 + ratio_1) * z[0], z[1] - ratio_1 * z[0], z[2] - ratio_4 * z[3],
          (1.0 + ratio_4) * z[3]};
}

// The surfaces' capacities d_i by the same expressions, so a surface at its restrainer reads 1
// exactly in one direction.
std::array<double, 4> Capacities(const SeriesArrangement& series) {
  std::array<double, 4> stops{};
  for (int k = 0; k < 4; ++k) stops[k] = series.elements[k].stop;
  return Surfaces(series, stops);
}

}  // namespace

std::string_view PendulumRegimeName(PendulumRegime regime) {
  switch (regime) {
    case PendulumRegime::kSticking:
      return "sticking";
    case PendulumRegime::kI:
      return "I";
    case PendulumRegime::kII:
      return "II";
    case PendulumRegime::kIII:
      return "III";
    case PendulumRegime::kIV:
      return "IV";
    case PendulumRegime::kV:
      return "V";
    case PendulumRegime::kBeyondV:
      return "beyond V";
  }
  return "unknown";
}

PendulumRegime TriplePendulumRegime(const SeriesArrangement& series,
                                    std::span<const LawState> elements) {
  RequireTriple(series);
  std::array<bool, 4> sliding{}, at_stop{};
  for (int k = 0; k < 4; ++k) {
    sliding[k] = elements[k].slip != 0;
    at_stop[k] = StopEngaged(series, elements, k);
  }
  return Regime(sliding, at_stop);
}

PendulumRegime TriplePendulumRegime(const SeriesArrangement& series,
                                    std::span<const PlanLawState> elements) {
  RequireTriple(series);
  std::array<bool, 4> sliding{}, at_stop{};
  for (int k = 0; k < 4; ++k) {
    sliding[k] = elements[k].x.slip != 0;
    at_stop[k] = elements[k].y.slip != 0;
  }
  return Regime(sliding, at_stop);
}

std::array<double, 4> TriplePendulumSurfaceDisplacements(const SeriesArrangement& series,
                                                         std::span<const LawState> elements) {
  RequireTriple(series);
  return Surfaces(series, std::array<double, 4>{elements[0].slider, elements[1].slider,
                                                elements[2].slider, elements[3].slider});
}

std::array<Vec2, 4> TriplePendulumSurfaceDisplacements(const SeriesArrangement& series,
                                                       std::span<const PlanLawState> elements) {
  RequireTriple(series);
  std::array<Vec2, 4> z;
  for (int k = 0; k < 4; ++k) z[k] = {elements[k].x.slider, elements[k].y.slider};
  return Surfaces(series, z);
}

std::array<double, 4> TriplePendulumCapacityUsed(const SeriesArrangement& series,
                                                 std::span<const LawState> elements) {
  const std::array<double, 4> u = TriplePendulumSurfaceDisplacements(series, elements);
  const std::array<double, 4> capacity = Capacities(series);
  std::array<double, 4> used{};
  for (int i = 0; i < 4; ++i) used[i] = std::abs(u[i]) / capacity[i];
  return used;
}

std::array<double, 4> TriplePendulumCapacityUsed(const SeriesArrangement& series,
                                                 std::span<const PlanLawState> elements) {
  const std::array<Vec2, 4> u = TriplePendulumSurfaceDisplacements(series, elements);
  const std::array<double, 4> capacity = Capacities(series);
  std::array<double, 4> used{};
  for (int i = 0; i < 4; ++i) used[i] = Norm(u[i]) / capacity[i];
  return used;
}

}  // namespace isolab::hysteresis
