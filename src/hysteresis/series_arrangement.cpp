#include "isolab/hysteresis/series_arrangement.h"

#include <algorithm>
#include <cmath>

namespace isolab::hysteresis {

SeriesArrangement::Step SeriesArrangement::Solve(double u_n, double force_n, int slip_n,
                                                 const SeriesElementStates& elements_n,
                                                 double u) const {
  const double du = u - u_n;
  // An increment of zero continues the last slide (its tangent is the sliding one).
  const int s = du > 0.0 ? 1 : (du < 0.0 ? -1 : (slip_n != 0 ? slip_n : 1));
  const double target = s * du;

  // In phi = s (F - F_n) >= 0, element k moves on [start_k, stop_k) with compliance 1 / k_k:
  // z_k = z_k,n + s (phi - start_k) / k_k there, s d_k from stop_k on.
  std::array<double, kMaxSeriesElements> start{}, stop{}, compliance{};
  std::array<double, 2 * kMaxSeriesElements> breaks{};
  int break_count = 0;
  const auto add_break = [&](double phi) {
    if (!(phi > 0.0) || std::isinf(phi)) return;
    int i = break_count++;
    for (; i > 0 && breaks[i - 1] > phi; --i) breaks[i] = breaks[i - 1];
    breaks[i] = phi;
  };
  for (int k = 0; k < count; ++k) {
    const SeriesElement& e = elements[k];
    const double z = elements_n.z[k];
    compliance[k] = 1.0 / e.stiffness;
    if (z == s * e.stop) {  // pressed against the stop it would move towards: it cannot move
      start[k] = stop[k] = INFINITY;
      continue;
    }
    // A slider that slid this way into the committed state goes on at once: its force is the
    // committed one up to round-off, which must not decide (slip_direction.h).
    start[k] =
        elements_n.slip[k] == s ? 0.0 : std::max(0.0, e.strength + s * (e.stiffness * z - force_n));
    stop[k] = std::isinf(e.stop) ? INFINITY : start[k] + e.stiffness * (e.stop - s * z);
    add_break(start[k]);
    add_break(stop[k]);
  }

  // s (u(F) - u_n) as a function of phi, summed from its parts so no round-off accumulates.
  const auto displacement = [&](double phi) {
    double x = phi / ke;
    for (int k = 0; k < count; ++k) {
      if (phi > start[k]) x += compliance[k] * (std::min(phi, stop[k]) - start[k]);
    }
    return x;
  };
  double low = 0.0, at_low = 0.0;
  for (int i = 0; i < break_count; ++i) {
    if (breaks[i] <= low) continue;
    const double at_break = displacement(breaks[i]);
    if (at_break >= target) break;
    low = breaks[i];
    at_low = at_break;
  }
  double segment_compliance = 1.0 / ke;
  for (int k = 0; k < count; ++k) {
    if (start[k] <= low && low < stop[k]) segment_compliance += compliance[k];
  }
  const double phi = low + (target - at_low) / segment_compliance;

  Step step;
  step.force = force_n + s * phi;
  step.stiffness = 1.0 / segment_compliance;
  for (int k = 0; k < count; ++k) {
    const double z_n = elements_n.z[k];
    double z = z_n;
    if (phi > start[k]) {
      // At the stop exactly, so that a later increment in the same direction finds it there.
      z = phi >= stop[k] ? s * elements[k].stop : z_n + s * compliance[k] * (phi - start[k]);
    }
    const double travel = std::abs(z - z_n);
    step.elements.z[k] = z;
    step.elements.travel[k] = elements_n.travel[k] + travel;
    // Sliding at the end of the increment, with travel or not: the phase the next one starts in.
    step.elements.slip[k] = start[k] <= phi && phi < stop[k] ? s : 0;
    if (step.elements.slip[k] != 0) step.slip = s;
    step.travel += travel;
    step.dissipated += elements[k].strength * travel;
  }
  return step;
}

SeriesElementStates SeriesArrangement::Gather(std::span<const LawState> element_states) const {
  SeriesElementStates elements;
  for (int k = 0; k < count; ++k) {
    elements.z[k] = element_states[k].slider;
    elements.travel[k] = element_states[k].accumulated_slip;
    elements.slip[k] = element_states[k].slip;
  }
  return elements;
}

void SeriesArrangement::Scatter(const SeriesElementStates& elements,
                                std::span<LawState> element_states) const {
  for (int k = 0; k < count; ++k) {
    element_states[k] = LawState{
        .slider = elements.z[k], .accumulated_slip = elements.travel[k], .slip = elements.slip[k]};
  }
}

void SeriesArrangement::Update(const LawState& committed,
                               std::span<const LawState> committed_elements, const LawInput& in,
                               LawState* trial, std::span<LawState> trial_elements,
                               LawResponse* response) const {
  const Step step =
      Solve(committed.u, committed.force, committed.slip, Gather(committed_elements), in.u);
  double sliders = 0.0;
  for (int k = 0; k < count; ++k) sliders += step.elements.z[k];
  *trial = LawState{.u = in.u,
                    .v = in.v,
                    .force = step.force,
                    .slider = sliders,
                    .accumulated_slip = committed.accumulated_slip + step.travel,
                    .slip = step.slip,
                    .dissipated = committed.dissipated + step.dissipated};
  Scatter(step.elements, trial_elements);
  response->force = step.force;
  response->stiffness = step.stiffness;
  response->damping = 0.0;
}

double SeriesArrangement::StoredEnergy(const LawState& state,
                                       std::span<const LawState> elements) const {
  double energy = 0.5 * state.force * state.force / ke;
  for (int k = 0; k < count; ++k) {
    energy += 0.5 * this->elements[k].stiffness * elements[k].slider * elements[k].slider;
  }
  return energy;
}

}  // namespace isolab::hysteresis
