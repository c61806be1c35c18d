#include "run_command.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>

#include "finite_options.h"
#include "isolab/analysis/analysis_setup.h"
#include "isolab/analysis/model_summary.h"
#include "isolab/analysis/response_peaks.h"
#include "isolab/analysis/result_series.h"
#include "isolab/analysis/results_file.h"
#include "isolab/analysis/run_analysis.h"
#include "isolab/analysis/run_report.h"
#include "isolab/core/errors.h"
#include "isolab/io/output_check.h"
#include "isolab/model/free_vibration_text.h"
#include "isolab/model/model_file.h"
#include "isolab/model/plan_model_file.h"
#include "plan_run_command.h"
#include "plot_script.h"
#include "run_report.h"

namespace isolab::cli {
namespace {

std::string Join(const std::vector<double>& values, std::size_t count, const char* format) {
  std::string text;
  for (std::size_t i = 0; i < std::min(count, values.size()); ++i) {
    text += (i > 0 ? ", " : "") + fmt::format(fmt::runtime(format), values[i]);
  }
  return text;
}

// The record as applied and the model summary, before the run: what the engineer checks first.
void PrintPreamble(const model::ModelFile& model, const analysis::AnalysisSetup& setup,
                   std::ostream& out) {
  const UnitSystem& u = model.units;
  const analysis::ModelSummary& m = setup.summary;
  const double g = u.Convert(1.0, "g", dimension::kAcceleration);
  fmt::print(out, "== {} ==\n", model.path);
  if (!model.description.empty()) fmt::print(out, "{}\n", model.description);
  if (!setup.record.path.empty()) {
    const io::AppliedRecord& r = setup.record;
    fmt::print(
        out, "record: {} ({}, dt = {:g} s, in {} from {}), scale {:g}: PGA {:.4g} g ({:.5g} {})\n",
        r.path, r.format, r.dt, r.units, r.units_source == "header" ? "its header" : r.units_source,
        r.scale, r.pga / g, r.pga, DescribeUnits(u, dimension::kAcceleration));
  }
  const double tonnes = m.total_mass * u.SiFactor(dimension::kMass) / 1000.0;
  fmt::print(out, "model: total weight {:.5g} {} ({:.5g} t)", m.total_weight, u.force(), tonnes);
  if (!m.fixed_base_periods.empty()) {
    fmt::print(out, "; fixed-base periods {} {}{}", Join(m.fixed_base_periods, 3, "{:.4g}"),
               u.time(), m.fixed_base_periods.size() > 3 ? ", ..." : "");
  }
  if (m.isolated) {
    fmt::print(out, "; {} {:.4g} {} at {:g} {} (secant stiffness {:.4g} {})",
               setup.layout.stories.empty() ? "period" : "isolated period", m.isolated_period,
               u.time(), m.trial_displacement, u.length(), m.secant_stiffness,
               DescribeUnits(u, dimension::kStiffness));
  }
  fmt::print(out, "\n");
  PrintGrid(setup.grid, setup.excitation_end, setup.free_vibration, setup.structure.dofs(), u, out);
}

void PrintSummary(const model::ModelFile& model, const model::AnalysisSection& analysis,
                  const analysis::AnalysisSetup& setup, const analysis::ResponsePeaks& peaks,
                  const integrators::RunSummary& summary, const std::string& output,
                  std::ostream& out) {
  const UnitSystem& u = model.units;
  const std::string length = u.length(), force = u.force(), time = u.time();
  const std::string acceleration = DescribeUnits(u, dimension::kAcceleration);
  const double g = u.Convert(1.0, "g", dimension::kAcceleration);
  const auto line = [&](const char* what, const analysis::Peak& peak, const std::string& unit,
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
  if (setup.layout.isolation >= 0) {
    fmt::print(out, "{:<34} {:>12.5g} {:<8} ", "residual isolator displacement",
               peaks.residual_isolator_displacement, length);
    if (setup.free_vibration > 0.0) {
      fmt::print(out, "after {:.4g} {} of free vibration (still swinging +-{:.3g} {})",
                 setup.free_vibration, time, peaks.residual_oscillation, length);
    }
    fmt::print(out, "\n{:<34} {:>12.5g} {}\n", "  at the end of the excitation",
               peaks.isolator_displacement_at_excitation_end, length);
    const analysis::ModelSummary& m = setup.summary;
    if (m.isolated && peaks.isolator_displacement.value > 0.0) {
      const double k =
          analysis::SecantStiffness(model.isolation, peaks.isolator_displacement.value);
      if (k > 0.0) {
        fmt::print(out, "{:<34} {:>12.4g} {:<8} (secant stiffness {:.4g} {} at the peak)\n",
                   "period at the peak displacement",
                   2.0 * std::numbers::pi * std::sqrt(m.total_mass / k), time, k,
                   DescribeUnits(u, dimension::kStiffness));
      }
    }
  }
  if (peaks.rows > 0) {
    const integrators::Energies& e = peaks.energies;
    const double input = e.input != 0.0 ? e.input : 1.0;
    fmt::print(out,
               "\nenergy at the end [{}*{}]: input {:.5g} = kinetic {:.3g} + damping {:.5g} "
               "({:.1f} %) + elastic {:.3g} + hysteretic {:.5g} ({:.1f} %)\n",
               force, length, e.input, e.kinetic, e.damping, 100 * e.damping / input, e.elastic,
               e.hysteretic, 100 * e.hysteretic / input);
  }
  PrintRunOutcome(analysis, summary, output, out);
}

// The model's output selection with the command line's options over it, checked before the run.
model::OutputSelection ChooseOutput(const model::ModelFile& model, const RunOptions& options,
                                    const analysis::AnalysisSetup& setup) {
  model::OutputSelection selection = model.output;
  if (options.every) selection.every = *options.every;
  if (options.summary_only) selection.summary_only = true;
  if (!options.quantities.empty()) {
    selection.quantities.clear();
    for (const std::string& name : options.quantities) {
      const std::string error = model::UnknownQuantity(name);
      if (!error.empty()) throw InputError({"--quantities"}, error);
      selection.quantities.push_back(name);
    }
  }
  std::string levels_key = "output.levels";
  if (!options.levels.empty()) {
    selection.levels.clear();
    for (const std::string& text : options.levels) {
      const std::optional<int> level = model::ParseLevel(text);
      if (!level) {
        throw InputError({"--levels"}, fmt::format("'{}' is not a level (0 for the base, k for "
                                                   "floor k, or roof)",
                                                   text));
      }
      selection.levels.push_back(*level);
    }
    levels_key = "--levels";
  }
  // --fixed-base takes the base away: a level may exist in the model and not in this run.
  analysis::SelectedDofs(selection, setup, levels_key);
  return selection;
}

void PrintWarnings(const std::vector<std::string>& warnings) {
  for (const std::string& warning : warnings) fmt::print(stderr, "isolab: warning: {}\n", warning);
}

}  // namespace

void RegisterRunCommand(CLI::App& app, RunOptions& options) {
  CLI::App* command = app.add_subcommand(
      "run", "Time-history analysis of a model's structure under its excitation (Newmark or IDA)");
  command->add_option("model", options.model, "Model file (YAML)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--record", options.record,
                      "Ground-motion record replacing the model's (the model's units, dt and "
                      "scale do not apply to it)");
  command->add_option("--units", options.units,
                      "The record's acceleration unit (g, m/s^2, cm/s^2, in/s^2, ...); must "
                      "agree with its header when the header names one");
  command->add_option("--record-dt", options.record_dt,
                      "The record's sampling step (s), for a single-column record; must agree "
                      "with the file's when it gives one");
  command->add_option("--scale", options.scale, "Scale factor of the ground motion, > 0")
      ->check(Positive());
  command->add_option("--dt", options.dt, "Analysis step (model time unit), at most the record's");
  command
      ->add_option("--max-steps", options.max_steps,
                   "Refuse runs of more analysis steps than this (default 10^7), before they start")
      ->check(Between(1, std::numeric_limits<int>::max()));
  command->add_option("--free-vibration", options.free_vibration,
                      "Free vibration after the excitation: auto (5 x the longest period; the "
                      "default), a time in s, or 0");
  command
      ->add_option("--trial-displacement", options.trial_displacement,
                   "Isolator displacement (model length unit) for the isolated period printed "
                   "before the run (default 0.1 m)")
      ->check(Positive());
  command->add_option("-o,--output", options.output,
                      "Results file: .h5/.hdf5 (HDF5) or .csv (time histories)");
  command
      ->add_option("--every", options.every,
                   "Write every N-th analysis step (replaces output.every; peaks and energies "
                   "still see every step)")
      ->check(Positive());
  command
      ->add_option("--quantities", options.quantities,
                   "Histories to write, comma-separated (replaces output.quantities): "
                   "displacement, velocity, acceleration, absolute_acceleration, "
                   "connection_force, isolator, story, energy")
      ->delimiter(',');
  command
      ->add_option("--levels", options.levels,
                   "Levels to write, comma-separated (replaces output.levels): 0 the base, k "
                   "floor k, roof")
      ->delimiter(',');
  command->add_flag("--summary-only", options.summary_only,
                    "Write peaks and energies only, no histories (replaces output.summary_only)");
  command->add_flag("--fixed-base", options.fixed_base, "Analyse the building without isolation");
  command
      ->add_option("--integrator", options.integrator,
                   "newmark or ida (replaces the model's analysis.integrator)")
      ->check(CLI::IsMember({"newmark", "ida"}));
  command->add_option("--rtol", options.rtol, "IDA relative tolerance (replaces analysis.ida.rtol)")
      ->check(Between(1e-14, 0.09));
  command->add_option("--atol", options.atol, "IDA absolute tolerance (replaces analysis.ida.atol)")
      ->check(Positive());
  command->add_flag("--json", options.json, "Print the summary as JSON");
  command->add_flag("-q,--quiet", options.quiet,
                    "No preamble (record, model summary, grid) before the peaks");
  command->add_flag("--plot{}", options.plot,
                    "After writing, plot with plot_result.py; --plot=DIR puts the PNGs in DIR "
                    "(default: beside the results file)");
}

int RunRunCommand(const RunOptions& options, std::ostream& out) {
  io::CheckInputFiles({options.model});
  if (model::IsPlanModelFile(options.model)) return RunPlanRunCommand(options, out);
  const model::ModelFile model = model::LoadModelFile(options.model);
  const std::string output = ChooseResultsPath(options, model.output_file);
  // Everything that can be refused is refused before the run, not after it.
  analysis::CheckResultsPath(output);
  std::vector<std::string> inputs = model.included_files;
  inputs.push_back(options.model);
  if (!options.record.empty()) {
    inputs.push_back(options.record);
  } else if (model.excitation.ground_motion) {
    inputs.push_back(model.excitation.ground_motion->file);
  }
  io::CheckOutputs(inputs, {output});
  if (options.plot) {
    if (std::filesystem::path(output).extension() == ".csv") {
      throw InputError({"--plot"},
                       "the plot script reads HDF5 results: write them with -o "
                       "OUT.h5");
    }
    CheckPlotScript("plot_result.py");
  }
  analysis::RunOverrides overrides;
  overrides.record = options.record;
  overrides.record_units = options.units;
  if (options.record_dt) {
    overrides.record_dt = model.units.Convert(*options.record_dt, "s", dimension::kTime);
  }
  overrides.scale = options.scale;
  overrides.dt = options.dt;
  overrides.max_steps = options.max_steps;
  overrides.fixed_base = options.fixed_base;
  overrides.trial_displacement = options.trial_displacement;
  if (!options.free_vibration.empty()) {
    overrides.free_vibration =
        model::ParseFreeVibration(options.free_vibration, model.units, "--free-vibration");
  }
  const analysis::AnalysisSetup setup = analysis::PrepareAnalysis(model, overrides);

  const model::AnalysisSection analysis = ChooseIntegrator(options, model.analysis);
  const model::OutputSelection selection = ChooseOutput(model, options, setup);

  if (!options.json && !options.quiet) PrintPreamble(model, setup, out);
  out.flush();
  PrintWarnings(setup.summary.warnings);
  const analysis::RecordedRun run =
      analysis::RunAndRecord(model, analysis, setup, selection, output, ISOLAB_VERSION);
  const analysis::ResponsePeaks& peaks = run.peaks;
  const integrators::RunSummary& summary = run.summary;
  const std::vector<std::string>& warnings = run.warnings;
  if (options.json) {
    const analysis::RunDescription description{&model, &setup, &analysis, &summary, &peaks, "", {}};
    out << analysis::RunReport(description, warnings, output).dump(2) << "\n";
  } else {
    PrintSummary(model, analysis, setup, peaks, summary, output, out);
  }
  // After the run: what the response itself shows (the model's warnings were printed before).
  PrintWarnings(
      {warnings.begin() + static_cast<long>(setup.summary.warnings.size()), warnings.end()});
  if (options.plot) {
    RunPlotScript("plot_result.py", {output, "-o", PlotDirectory(*options.plot, output)},
                  options.quiet);
  }
  return ExitCode(summary, setup.grid.dt, output);
}

}  // namespace isolab::cli
