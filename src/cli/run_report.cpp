#include "run_report.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <cstdio>
#include <filesystem>

namespace isolab::cli {

model::AnalysisSection ChooseIntegrator(const RunOptions& options,
                                        model::AnalysisSection analysis) {
  if (options.integrator == "ida") analysis.integrator = model::AnalysisSection::Integrator::kIda;
  if (options.integrator == "newmark") {
    analysis.integrator = model::AnalysisSection::Integrator::kNewmark;
  }
  if (options.rtol) analysis.ida.relative_tolerance = *options.rtol;
  if (options.atol) analysis.ida.absolute_tolerance = *options.atol;
  return analysis;
}

std::string ChooseResultsPath(const RunOptions& options, const std::string& model_output_file) {
  if (!options.output.empty()) return options.output;
  if (!model_output_file.empty()) return model_output_file;
  return std::filesystem::path(options.model).stem().string() + ".h5";
}

void PrintGrid(const integrators::TimeGrid& grid, double excitation_end, double free_vibration,
               int dofs, const UnitSystem& units, std::ostream& out) {
  const std::string time = units.time();
  fmt::print(out,
             "dt = {:g} {}, {} steps ({:.4g} {} of excitation, then {:.4g} {} of free "
             "vibration), {} dofs\n\n",
             grid.dt, time, grid.steps, excitation_end, time, free_vibration, time, dofs);
}

void PrintRunOutcome(const model::AnalysisSection& analysis, const integrators::RunSummary& summary,
                     const std::string& output, std::ostream& out) {
  fmt::print(out, "energy balance error: {:.2e} of the input energy\n",
             summary.energy_balance_error);
  if (analysis.integrator == model::AnalysisSection::Integrator::kIda) {
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
  fmt::print(out, "results: {}\n", output);
}

int ExitCode(const integrators::RunSummary& summary, double dt, const std::string& output) {
  if (summary.ok()) return 0;
  fmt::print(stderr, "isolab: the run stopped early: {}; results up to t = {:g} are in {}\n",
             summary.message, summary.steps * dt, output);
  return 1;
}

}  // namespace isolab::cli
