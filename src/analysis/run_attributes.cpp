#include "run_attributes.h"

#include <fmt/format.h>

#include "isolab/analysis/solve.h"

namespace isolab::analysis {

void WriteProgramAttributes(io::Hdf5File& file, const std::string& version,
                            const std::string& model_path, const UnitSystem& units) {
  file.WriteAttribute("/", "isolab_version", version);
  file.WriteAttribute("/", "model_file", model_path);
  file.WriteAttribute(
      "/", "units",
      fmt::format("force {}, length {}, time {}", units.force(), units.length(), units.time()));
}

void WriteIntegratorAttributes(io::Hdf5File& file, const model::AnalysisSection& analysis,
                               double dt, const integrators::RunSummary& summary) {
  const auto integer = [&](const char* name, long value) {
    file.WriteIntegerAttribute("/", name, value);
  };
  file.WriteAttribute("/", "integrator", DescribeIntegrator(analysis, dt));
  file.WriteAttribute("/", "dt", dt);
  integer("steps", summary.steps);
  integer("newton_iterations", summary.newton_iterations);
  file.WriteAttribute("/", "solves_per_step", summary.SolvesPerStep());
  integer("max_iterations_in_a_step", summary.max_iterations_in_a_step);
  integer("factorisations", summary.factorisations);
  integer("step_cuts", summary.step_cuts);
  integer("ida_steps", summary.ida_steps);
  integer("events", summary.events);
  integer("jacobian_evaluations", summary.jacobian_evaluations);
  integer("error_test_failures", summary.error_test_failures);
  file.WriteAttribute("/", "wall_seconds", summary.wall_seconds);
  file.WriteAttribute("/", "termination", summary.ok() ? "completed" : "failed");
  file.WriteAttribute("/", "message", summary.message);
  file.WriteAttribute("/", "energy_balance_error", summary.energy_balance_error);
}

std::set<std::string> CreateSeriesGroups(io::Hdf5File& file, const std::vector<Series>& series) {
  std::set<std::string> groups;
  for (const Series& s : series) {
    const std::size_t slash = s.name.rfind('/');
    if (slash != std::string::npos && groups.insert(s.name.substr(0, slash)).second) {
      file.CreateGroup(s.name.substr(0, slash));
    }
  }
  return groups;
}

}  // namespace isolab::analysis
