#include "integrator_report.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

namespace isolab::cli {

void PrintIntegratorStatistics(const io::AnalysisSection& analysis,
                               const integrators::RunSummary& summary, std::ostream& out) {
  if (analysis.integrator == io::AnalysisSection::Integrator::kIda) {
    fmt::print(out,
               "IDA: {} steps, {} phase-change events, {} Jacobians, {} error-test failures; "
               "{:.3f} s\n",
               summary.ida_steps, summary.events, summary.jacobian_evaluations,
               summary.error_test_failures, summary.wall_seconds);
  } else {
    fmt::print(out,
               "Newton: {} iterations ({:.3f} solves per step, at most {} in a step), {} "
               "factorisations, {} step cuts; {:.3f} s\n",
               summary.newton_iterations, summary.SolvesPerStep(), summary.max_iterations_in_a_step,
               summary.factorisations, summary.step_cuts, summary.wall_seconds);
  }
}

void AddIntegratorStatistics(const io::AnalysisSection& analysis,
                             const integrators::RunSummary& summary, nlohmann::json* json) {
  if (analysis.integrator == io::AnalysisSection::Integrator::kIda) {
    (*json)["ida"] = {{"steps", summary.ida_steps},
                      {"events", summary.events},
                      {"jacobian_evaluations", summary.jacobian_evaluations},
                      {"error_test_failures", summary.error_test_failures}};
  } else {
    (*json)["newton"] = {{"iterations", summary.newton_iterations},
                         {"solves_per_step", summary.SolvesPerStep()},
                         {"max_iterations_in_a_step", summary.max_iterations_in_a_step},
                         {"factorisations", summary.factorisations},
                         {"step_cuts", summary.step_cuts}};
  }
}

}  // namespace isolab::cli
