#include "result_series.h"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

namespace isolab::io {

std::vector<Series> ResultSeries(const RunDescription& run) {
  const auto& r = *run.response;
  const AnalysisSetup& setup = *run.setup;
  const UnitSystem& units = run.model->units;
  const std::string length = DescribeUnits(units, dimension::kLength);
  const std::string force = DescribeUnits(units, dimension::kForce);
  const std::string velocity = DescribeUnits(units, dimension::kVelocity);
  const std::string acceleration = DescribeUnits(units, dimension::kAcceleration);
  const std::string energy = fmt::format("{}*{}", units.force(), units.length());
  const auto& connections = setup.structure.connections();
  const std::vector<std::string>& dofs = setup.layout.dof_names;

  std::vector<Series> series;
  series.push_back(Vector("time", units.time(), [&r](int row) { return r.time[row]; }));
  if (!setup.record.path.empty()) {
    series.push_back(Vector("ground_acceleration", acceleration, [&r, &setup](int row) {
      return setup.excitation.ground_acceleration.At(r.time[row]);
    }));
  }
  series.push_back(Matrix("displacement", length, dofs, r.displacement));
  series.push_back(Matrix("velocity", velocity, dofs, r.velocity));
  series.push_back(Matrix("acceleration", acceleration, dofs, r.acceleration));
  series.push_back(Matrix("absolute_acceleration", acceleration, dofs, r.absolute_acceleration));
  std::vector<std::string> connection_names;
  for (const auto& connection : connections) connection_names.push_back(connection.name);
  series.push_back(Matrix("connection_force", force, connection_names, r.connection_force));

  if (setup.layout.isolation >= 0) {
    const int k = setup.layout.isolation;
    const int dof = connections[k].dof_j;
    series.push_back(Vector("isolator/displacement", length,
                            [&r, dof](int row) { return r.displacement(row, dof); }));
    series.push_back(
        Vector("isolator/force", force, [&r, k](int row) { return r.connection_force(row, k); }));
    std::vector<std::string> components;
    for (const auto& component : connections[k].assembly.components()) {
      components.push_back(component.name);
    }
    const std::size_t first = setup.structure.law_offset(k);
    series.push_back({"isolator/component_force", force, components,
                      [&r, first, count = components.size()](int row, double* out) {
                        std::copy_n(r.law_force.row(row).data() + first, count, out);
                      }});
  }
  if (!setup.layout.stories.empty()) {
    std::vector<std::string> stories;
    bool heights = false;
    for (std::size_t s = 0; s < setup.layout.stories.size(); ++s) {
      stories.push_back(connections[setup.layout.stories[s]].name);
      heights = heights || setup.layout.story_heights[s] > 0.0;
    }
    // Each story's drift times a factor: 1 for the drift, 100 / height for its ratio (%).
    const auto drifts = [&](std::string name, std::string units, std::vector<double> factors) {
      std::vector<std::pair<int, int>> floors;  // (below, above); kGround: -1
      for (const int k : setup.layout.stories)
        floors.emplace_back(connections[k].dof_i, connections[k].dof_j);
      return Series{std::move(name), std::move(units), stories,
                    [&r, floors, factors](int row, double* out) {
                      const double* u = r.displacement.row(row).data();
                      for (std::size_t s = 0; s < floors.size(); ++s) {
                        const double below = floors[s].first >= 0 ? u[floors[s].first] : 0.0;
                        out[s] = factors[s] * (u[floors[s].second] - below);
                      }
                    }};
    };
    series.push_back(drifts("story/drift", length, std::vector<double>(stories.size(), 1.0)));
    if (heights) {
      std::vector<double> per_height;
      for (const double height : setup.layout.story_heights) {
        per_height.push_back(height > 0.0 ? 100.0 / height
                                          : std::numeric_limits<double>::quiet_NaN());
      }
      series.push_back(drifts("story/drift_ratio", "%", per_height));
    }
    series.push_back({"story/shear", force, stories, [&r, &setup](int row, double* out) {
                        for (std::size_t s = 0; s < setup.layout.stories.size(); ++s) {
                          out[s] = r.connection_force(row, setup.layout.stories[s]);
                        }
                      }});
  }
  const auto energy_term = [&](const char* name, double integrators::Energies::*term) {
    series.push_back(Vector(fmt::format("energy/{}", name), energy,
                            [&r, term](int row) { return r.energies[row].*term; }));
  };
  energy_term("input", &integrators::Energies::input);
  energy_term("kinetic", &integrators::Energies::kinetic);
  energy_term("damping", &integrators::Energies::damping);
  energy_term("elastic", &integrators::Energies::elastic);
  energy_term("hysteretic", &integrators::Energies::hysteretic);
  return series;
}

}  // namespace isolab::io
