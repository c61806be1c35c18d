#include "isolab/cyclic/path_replay.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "isolab/core/errors.h"
#include "isolab/hysteresis/cyclic_test.h"
#include "isolab/hysteresis/plan_law_kernel.h"

namespace isolab::cyclic {
namespace {

using hysteresis::LawState;
using hysteresis::PlanLawState;

// One direction's laws seen as a plan model moving along x: the same update, the force's x.
struct OneDirection {
  const hysteresis::ParallelAssembly& model;
  std::vector<LawState> committed, trial;
  std::vector<hysteresis::LawResponse> responses;

  explicit OneDirection(const hysteresis::ParallelAssembly& m)
      : model(m), committed(m.state_size()), trial(m.state_size()), responses(m.size()) {}
  std::size_t size() const { return model.size(); }
  Vec2 Update(Vec2 u, Vec2 v, double t) {
    const double f = model.Update(committed, {u.x, v.x, t}, trial, responses).force;
    std::swap(committed, trial);
    return {f, 0.0};
  }
  Vec2 ComponentForce(std::size_t c) const { return {responses[c].force, 0.0}; }
  double Dissipated() const { return model.DissipatedEnergy(committed); }
};

struct TwoDirections {
  const hysteresis::PlanAssembly& model;
  std::vector<PlanLawState> committed, trial;
  std::vector<hysteresis::PlanLawResponse> responses;

  explicit TwoDirections(const hysteresis::PlanAssembly& m)
      : model(m), committed(m.state_size()), trial(m.state_size()), responses(m.size()) {}
  std::size_t size() const { return model.size(); }
  Vec2 Update(Vec2 u, Vec2 v, double t) {
    const Vec2 f = model.Update(committed, {u, v, t}, trial, responses).force;
    std::swap(committed, trial);
    return f;
  }
  Vec2 ComponentForce(std::size_t c) const { return responses[c].force; }
  double Dissipated() const { return model.DissipatedEnergy(committed); }
};

// The one loop: both kinds of model along any path.
template <typename Driver>
ReplayResult Drive(Driver driver, std::vector<std::string> components,
                   const io::DisplacementPath& path, const std::vector<std::size_t>& cycle_starts) {
  ReplayResult r;
  r.name = path.name;
  r.plan = path.plan;
  r.time = path.time;
  r.displacement = path.displacement;
  r.measured = path.force;
  r.components = std::move(components);
  const std::size_t n = path.time.size(), m = driver.size();
  r.force.resize(n);
  r.component_force.resize(n * m);
  r.dissipated.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double dt = k > 0 ? path.time[k] - path.time[k - 1] : 0.0;
    const Vec2 v = dt > 0.0 ? (path.displacement[k] - path.displacement[k - 1]) / dt : Vec2{};
    r.force[k] = driver.Update(path.displacement[k], v, path.time[k]);
    for (std::size_t c = 0; c < m; ++c) r.component_force[k * m + c] = driver.ComponentForce(c);
    r.dissipated[k] = driver.Dissipated();
    r.peak_displacement = std::max(r.peak_displacement, Norm(path.displacement[k]));
    r.peak_force = std::max(r.peak_force, Norm(r.force[k]));
  }
  for (std::size_t c = 0; c + 1 < cycle_starts.size(); ++c) {
    ReplayCycle cycle;
    cycle.index = static_cast<int>(c) + 1;
    const std::size_t begin = cycle_starts[c], end = cycle_starts[c + 1];
    cycle.dissipated = r.dissipated[end] - r.dissipated[begin];
    for (std::size_t k = begin + 1; k <= end; ++k) {
      cycle.peak_force = std::max(cycle.peak_force, Norm(r.force[k]));
    }
    cycle.displacement_at_end = r.displacement[end];
    cycle.force_at_end = r.force[end];
    r.cycles.push_back(cycle);
  }
  if (!path.force.empty()) {
    ReplayComparison c;
    double error = 0.0, norm = 0.0;
    Vec2 low{INFINITY, INFINITY}, high{-INFINITY, -INFINITY};
    for (std::size_t k = 0; k < n; ++k) {
      const Vec2 f0 = path.force[k];
      error += std::pow(Norm(f0 - r.force[k]), 2);
      norm += std::pow(Norm(f0), 2);
      c.peak_measured = std::max(c.peak_measured, Norm(f0));
      low = {std::min(low.x, f0.x), std::min(low.y, f0.y)};
      high = {std::max(high.x, f0.x), std::max(high.y, f0.y)};
    }
    c.peak_modelled = r.peak_force;
    c.e2 = norm > 0.0 ? error / norm : error;
    const double range = std::max(high.x - low.x, high.y - low.y);
    c.nrmse = std::sqrt(c.e2);
    c.error_over_range = range > 0.0 ? std::sqrt(error / double(n)) / range : 0.0;
    r.comparison = c;
  }
  return r;
}

std::vector<std::string> Names(const auto& components) {
  std::vector<std::string> names;
  for (const auto& component : components) names.push_back(component.name);
  return names;
}

}  // namespace

void OrbitProtocol::Validate() const {
  // The same fields and bounds as a sinusoidal test's.
  hysteresis::CyclicProtocol{amplitude, period, cycles, steps_per_cycle}.Validate();
}

io::DisplacementPath OrbitPath(const OrbitProtocol& p, std::vector<std::size_t>* cycles) {
  p.Validate();
  io::DisplacementPath path;
  path.name = p.shape == OrbitShape::kCircle ? "circle" : "figure_eight";
  path.plan = true;
  const double dt = p.period / p.steps_per_cycle;
  int k = 0;
  const auto add = [&](Vec2 u) {
    path.time.push_back(k++ * dt);
    path.displacement.push_back(u);
  };
  add({0.0, 0.0});
  if (p.shape == OrbitShape::kCircle) {
    const int ramp = p.steps_per_cycle / 4;
    for (int j = 1; j <= ramp; ++j) add({p.amplitude * j / ramp, 0.0});
  }
  cycles->assign(1, path.time.size() - 1);
  for (int c = 0; c < p.cycles; ++c) {
    for (int j = 1; j <= p.steps_per_cycle; ++j) {
      // The phase restarts every cycle, so each cycle ends exactly where it began.
      const double theta = 2.0 * std::numbers::pi * j / p.steps_per_cycle;
      add(p.shape == OrbitShape::kCircle
              ? Vec2{p.amplitude * std::cos(theta), p.amplitude * std::sin(theta)}
              : Vec2{p.amplitude * std::sin(theta), 0.5 * p.amplitude * std::sin(2 * theta)});
    }
    cycles->push_back(path.time.size() - 1);
  }
  return path;
}

ReplayResult Replay(const hysteresis::ParallelAssembly& model, const io::DisplacementPath& path,
                    const std::vector<std::size_t>& cycle_starts) {
  if (path.plan) {
    throw std::invalid_argument("a path in two directions needs a plan model (PlanFromIsolation)");
  }
  return Drive(OneDirection(model), Names(model.components()), path, cycle_starts);
}

ReplayResult Replay(const hysteresis::PlanAssembly& model, const io::DisplacementPath& path,
                    const std::vector<std::size_t>& cycle_starts) {
  return Drive(TwoDirections(model), Names(model.components()), path, cycle_starts);
}

hysteresis::PlanAssembly PlanFromIsolation(const hysteresis::ParallelAssembly& isolation,
                                           bool coupled) {
  std::vector<hysteresis::PlanComponent> components;
  for (const auto& component : isolation.components()) {
    if (coupled && !hysteresis::HasCoupledForm(component.parameters.type())) {
      throw std::invalid_argument(fmt::format(
          "{} ({}) has no coupled form in two directions; drive it as an uncoupled pair",
          component.name, hysteresis::LawName(component.parameters.type())));
    }
    components.push_back({component.name, component.parameters,
                          coupled ? std::nullopt : std::optional(component.parameters)});
  }
  return hysteresis::PlanAssembly(std::move(components));
}

}  // namespace isolab::cyclic
