#include "run_command.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "isolab/io/analysis_setup.h"
#include "isolab/io/model_file.h"
#include "isolab/io/response_peaks.h"
#include "isolab/io/results_file.h"
#include "isolab/io/run_analysis.h"
#include "plot_script.h"

namespace isolab::cli {
namespace {

nlohmann::json PeakJson(const io::Peak& peak) {
  return {{"value", peak.value}, {"time", peak.time}, {"index", peak.index}};
}

void PrintSummary(const io::ModelFile& model, const io::AnalysisSection& analysis,
                  const io::AnalysisSetup& setup,
                  const io::ResponsePeaks& peaks, const integrators::RunSummary& summary,
                  const integrators::ResponseHistory& response, const std::string& output,
                  std::ostream& out) {
  const io::UnitSystem& u = model.units;
  const std::string length = u.length(), force = u.force(), time = u.time();
  const std::string acceleration = io::DescribeUnits(u, io::dimension::kAcceleration);
  const double g = u.Convert(1.0, "g", io::dimension::kAcceleration);
  fmt::print(out, "== {} ==\n", model.path);
  if (!model.description.empty()) fmt::print(out, "{}\n", model.description);
  if (!setup.record_path.empty()) {
    fmt::print(out, "record: {} (scale {:g})\n", setup.record_path, setup.scale);
  }
  fmt::print(out, "dt = {:g} {}, {} steps, {} dofs\n\n", setup.grid.dt, time, setup.grid.steps,
             setup.structure.dofs());
  const auto line = [&](const char* what, const io::Peak& peak, const std::string& unit,
                        const std::string& extra = "") {
    fmt::print(out, "{:<34} {:>12.5g} {:<8} at t = {:.4g} {}{}\n", what, peak.value, unit,
               peak.time, time, extra);
  };
  if (setup.layout.isolation >= 0) {
    line("peak isolator displacement", peaks.isolator_displacement, length);
    line("peak isolator force", peaks.isolator_force, force);
  }
  line("peak base shear", peaks.base_shear, force);
  if (!setup.layout.stories.empty()) {
    line("peak first-story shear", peaks.first_story_shear, force);
    line("peak story drift", peaks.story_drift, length,
         fmt::format(" (story {}{})", peaks.story_drift.index + 1,
                     peaks.story_drift_ratio > 0.0
                         ? fmt::format(", {:.3g} % of its height", 100 * peaks.story_drift_ratio)
                         : ""));
  }
  line("peak roof absolute acceleration", peaks.roof_absolute_acceleration, acceleration,
       fmt::format(" ({:.3g} g)", peaks.roof_absolute_acceleration.value / g));
  if (response.rows_written > 0) {
    const integrators::Energies& e = response.energies[response.rows_written - 1];
    const double input = e.input != 0.0 ? e.input : 1.0;
    fmt::print(out,
               "\nenergy at the end [{}*{}]: input {:.5g} = kinetic {:.3g} + damping {:.5g} "
               "({:.1f} %) + elastic {:.3g} + hysteretic {:.5g} ({:.1f} %)\n",
               force, length, e.input, e.kinetic, e.damping, 100 * e.damping / input, e.elastic,
               e.hysteretic, 100 * e.hysteretic / input);
  }
  fmt::print(out, "energy balance error: {:.2e} of the input energy\n",
             summary.energy_balance_error);
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
               summary.newton_iterations, summary.SolvesPerStep(),
               summary.max_iterations_in_a_step,
               summary.factorisations, summary.step_cuts, summary.wall_seconds);
  }
  fmt::print(out, "results: {}\n", output);
}

nlohmann::json SummaryJson(const io::ModelFile& model, const io::AnalysisSection& analysis,
                           const io::AnalysisSetup& setup,
                           const io::ResponsePeaks& peaks, const integrators::RunSummary& summary,
                           const integrators::ResponseHistory& response,
                           const std::string& output) {
  nlohmann::json json;
  json["model"] = model.path;
  json["record"] = setup.record_path;
  json["scale"] = setup.scale;
  json["dt"] = setup.grid.dt;
  json["steps"] = setup.grid.steps;
  json["units"] = {{"force", model.units.force()},
                   {"length", model.units.length()},
                   {"time", model.units.time()}};
  json["termination"] = summary.ok() ? "completed" : "failed";
  json["message"] = summary.message;
  json["peaks"] = {{"isolator_displacement", PeakJson(peaks.isolator_displacement)},
                   {"isolator_force", PeakJson(peaks.isolator_force)},
                   {"base_shear", PeakJson(peaks.base_shear)},
                   {"first_story_shear", PeakJson(peaks.first_story_shear)},
                   {"roof_absolute_acceleration", PeakJson(peaks.roof_absolute_acceleration)},
                   {"story_drift", PeakJson(peaks.story_drift)},
                   {"story_drift_ratio", peaks.story_drift_ratio}};
  if (response.rows_written > 0) {
    const integrators::Energies& e = response.energies[response.rows_written - 1];
    json["energy"] = {{"input", e.input},
                      {"kinetic", e.kinetic},
                      {"damping", e.damping},
                      {"elastic", e.elastic},
                      {"hysteretic", e.hysteretic}};
  }
  json["energy_balance_error"] = summary.energy_balance_error;
  json["integrator"] = io::DescribeIntegrator(analysis, setup.grid.dt);
  if (analysis.integrator == io::AnalysisSection::Integrator::kIda) {
    json["ida"] = {{"steps", summary.ida_steps},
                   {"events", summary.events},
                   {"jacobian_evaluations", summary.jacobian_evaluations},
                   {"error_test_failures", summary.error_test_failures}};
  } else {
    json["newton"] = {{"iterations", summary.newton_iterations},
                      {"solves_per_step", summary.SolvesPerStep()},
                      {"max_iterations_in_a_step", summary.max_iterations_in_a_step},
                      {"factorisations", summary.factorisations},
                      {"step_cuts", summary.step_cuts}};
  }
  json["steps_completed"] = summary.steps;
  json["wall_seconds"] = summary.wall_seconds;
  json["results"] = output;
  return json;
}

}  // namespace

void RegisterRunCommand(CLI::App& app, RunOptions& options) {
  CLI::App* command = app.add_subcommand(
      "run", "Time-history analysis of a model's structure under its excitation (Newmark or IDA)");
  command->add_option("model", options.model, "Model file (YAML)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--record", options.record, "Ground-motion record replacing the model's");
  command->add_option("--scale", options.scale, "Scale factor of the ground motion");
  command->add_option("--dt", options.dt, "Analysis step (model time unit), at most the record's");
  command->add_option("-o,--output", options.output, "HDF5 results file");
  command->add_flag("--fixed-base", options.fixed_base, "Analyse the building without isolation");
  command->add_option("--integrator", options.integrator,
                      "newmark or ida (replaces the model's analysis.integrator)")
      ->check(CLI::IsMember({"newmark", "ida"}));
  command->add_option("--rtol", options.rtol, "IDA relative tolerance (replaces analysis.ida.rtol)")
      ->check(CLI::Range(1e-14, 0.09));
  command->add_option("--atol", options.atol, "IDA absolute tolerance (replaces analysis.ida.atol)")
      ->check(CLI::PositiveNumber);
  command->add_flag("--json", options.json, "Print the summary as JSON");
  command->add_option("--plot", options.plot,
                      "After writing, plot with scripts/plot_result.py into DIR (default: beside "
                      "the results file)")
      ->expected(0, 1);
}

int RunRunCommand(const RunOptions& options, std::ostream& out) {
  if (options.plot) CheckPlotScript("plot_result.py");  // before the run, not after it
  const io::ModelFile model = io::LoadModelFile(options.model);
  const io::AnalysisSetup setup =
      io::PrepareAnalysis(model, {options.record, options.scale, options.dt, options.fixed_base});
  std::string output = options.output;
  if (output.empty()) {
    output = !model.output_file.empty()
                 ? model.output_file
                 : std::filesystem::path(options.model).stem().string() + ".h5";
  }

  io::AnalysisSection analysis = model.analysis;
  if (options.integrator == "ida") analysis.integrator = io::AnalysisSection::Integrator::kIda;
  if (options.integrator == "newmark") {
    analysis.integrator = io::AnalysisSection::Integrator::kNewmark;
  }
  if (options.rtol) analysis.ida.relative_tolerance = *options.rtol;
  if (options.atol) analysis.ida.absolute_tolerance = *options.atol;

  integrators::ResponseHistory response;
  const integrators::RunSummary summary = io::RunAnalysis(analysis, setup, &response);
  io::WriteResultsFile(output,
                       {&model, &setup, &analysis, &response, &summary, ISOLAB_VERSION});
  const io::ResponsePeaks peaks = io::ComputePeaks(setup, response);
  if (options.json) {
    out << SummaryJson(model, analysis, setup, peaks, summary, response, output).dump(2) << "\n";
  } else {
    PrintSummary(model, analysis, setup, peaks, summary, response, output, out);
  }
  if (options.plot) {
    RunPlotScript("plot_result.py", {output, "-o", PlotDirectory(*options.plot, output)}, false);
  }
  if (!summary.ok()) {
    fmt::print(stderr, "isolab: the run stopped early: {}; results up to t = {:g} are in {}\n",
               summary.message, summary.steps * setup.grid.dt, output);
    return 1;
  }
  return 0;
}

}  // namespace isolab::cli
