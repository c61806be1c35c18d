#include "run_command.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>

#include "common_options.h"
#include "finite_options.h"
#include "isolab/analysis/problem.h"
#include "isolab/analysis/result_series.h"
#include "isolab/analysis/results_file.h"
#include "isolab/analysis/run_band.h"
#include "isolab/analysis/run_report.h"
#include "isolab/analysis/run_text.h"
#include "isolab/analysis/solve.h"
#include "isolab/core/errors.h"
#include "isolab/io/output_check.h"
#include "isolab/model/free_vibration_text.h"
#include "isolab/model/model_file.h"
#include "plot_script.h"
#include "run_report.h"

namespace isolab::cli {
namespace {

// The model's output selection with the command line's options over it, checked before the run.
model::OutputSelection ChooseOutput(const model::ModelFile& model, const RunOptions& options,
                                    const analysis::Problem& problem) {
  model::OutputSelection selection = model.output;
  if (options.summary_only) {
    for (const auto& [given, option] : {std::pair{options.every.has_value(), "--every"},
                                        std::pair{!options.quantities.empty(), "--quantities"},
                                        std::pair{!options.levels.empty(), "--levels"}}) {
      if (given) {
        throw InputError({option},
                         "chooses histories, and --summary-only writes none: give "
                         "one or the other");
      }
    }
  }
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
  analysis::SelectedLevels(selection, problem.layout, levels_key);
  analysis::CheckQuantitiesExist(selection, problem.layout,
                                 options.quantities.empty() ? "output.quantities" : "--quantities");
  if (options.plot) {
    // plot_result.py draws every level's motion, the isolator's loop and the energies: a run that
    // leaves one out would be written, then fail to plot.
    const bool every_level = selection.levels.empty();
    if (selection.summary_only || !every_level) {
      throw InputError({"--plot"}, fmt::format("the plots need every level's histories: leave "
                                               "out {}",
                                               selection.summary_only ? "--summary-only (or "
                                                                        "output.summary_only)"
                                                                      : levels_key));
    }
    for (const char* needed :
         {"displacement", "acceleration", "absolute_acceleration", "energy", "isolator"}) {
      const bool applies = problem.layout.isolated() || std::string_view(needed) != "isolator";
      if (applies && !selection.Records(needed)) {
        throw InputError({"--plot"}, fmt::format("the plots need the '{}' histories: add them to "
                                                 "the quantities, or leave the quantities out",
                                                 needed));
      }
    }
  }
  return selection;
}

analysis::RunOverrides ChooseOverrides(const model::ModelFile& model, const RunOptions& options) {
  analysis::RunOverrides overrides;
  if (!options.record_h2.empty() && options.record.empty()) {
    throw InputError({"--record-h2"}, "needs --record: the pair's first component");
  }
  if (!options.record_v.empty() && options.record.empty()) {
    throw InputError({"--record-v"}, "needs --record: the record's first horizontal component");
  }
  if (options.angle && options.record.empty()) {
    throw InputError({"--angle"}, "needs --record (the model's own pair has its angle)");
  }
  if (!options.record.empty()) {
    analysis::RecordOverride h1;
    h1.file = options.record;
    overrides.records.push_back(h1);
    if (!options.record_h2.empty()) {
      analysis::RecordOverride h2;
      h2.name = "--record-h2";
      h2.file = options.record_h2;
      overrides.records.push_back(h2);
    }
    if (!options.record_v.empty()) {
      analysis::RecordOverride v;
      v.name = "--record-v";
      v.file = options.record_v;
      overrides.vertical = v;
    }
    overrides.angle = options.angle.value_or(0.0);
  }
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
  return overrides;
}

void PrintWarnings(const std::vector<std::string>& warnings) {
  for (const std::string& warning : warnings) fmt::print(stderr, "isolab: warning: {}\n", warning);
}

}  // namespace

void RegisterRunCommand(CLI::App& app, RunOptions& options) {
  CLI::App* command = app.add_subcommand(
      "run",
      "Time-history analysis of a model's structure under its excitation (Newmark or IDA): an "
      "SDOF, a shear building or a building in plan");
  command->add_option("model", options.model, "Model file (YAML)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--record", options.record,
                      "Ground-motion record replacing the model's (the model's units, dt and "
                      "scale do not apply to it); with a building in plan, its H1 component");
  command->add_option("--record-h2", options.record_h2,
                      "With --record, the second horizontal component H2 (a building in plan)");
  command->add_option("--record-v", options.record_v,
                      "With --record, the vertical component (upwards), for a model with "
                      "axial_load: {vertical: true} (friction pendulum bearings' axial loads)");
  command->add_option("--angle", options.angle,
                      "With --record, the angle from the x axis to H1 in degrees (H2 at +90; "
                      "default 0)");
  command->add_option("--units", options.units,
                      "The record's acceleration unit (g, m/s^2, cm/s^2, in/s^2, ...); must "
                      "agree with its header when the header names one");
  command->add_option("--record-dt", options.record_dt,
                      "The record's sampling step (s), for a single-column record; must agree "
                      "with the file's when it gives one");
  command
      ->add_option("--scale", options.scale,
                   "Scale factor of the ground motion, > 0 (replaces the model's scale, a factor "
                   "or a target)")
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
  AddOutputOption(command, &options.output,
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
  command->add_flag("--fixed-base", options.fixed_base,
                    "Analyse the superstructure without its isolation, on a fixed base");
  command
      ->add_option("--integrator", options.integrator,
                   "newmark or ida (replaces the model's analysis.integrator)")
      ->check(CLI::IsMember({"newmark", "ida"}));
  command->add_option("--rtol", options.rtol, "IDA relative tolerance (replaces analysis.ida.rtol)")
      ->check(Between(1e-14, 0.09));
  command->add_option("--atol", options.atol, "IDA absolute tolerance (replaces analysis.ida.atol)")
      ->check(Positive());
  command
      ->add_option("--samples", options.samples,
                   "Parameter sets drawn from the fitted model's uncertainty (isolab fit "
                   "--building) for the 5-50-95 % spread of the peaks")
      ->check(CLI::Range(2, 100000));
  AddSeedOption(command, &options.seed, "Seed of the drawn parameter sets (--samples)");
  AddJsonFlag(command, &options.json, "Print the summary as JSON");
  AddQuietFlag(command, &options.quiet,
               "No preamble (record, model summary, grid) before the peaks");
  command->add_flag("--plot{}", options.plot,
                    "After writing, plot with plot_result.py; --plot=DIR puts the PNGs in DIR "
                    "(default: beside the results file)");
}

int RunRunCommand(const RunOptions& options, std::ostream& out) {
  io::CheckInputFiles({options.model});
  const model::ModelFile model = model::LoadModelFile(options.model);
  const std::string output = ChooseResultsPath(options, model.output_file);
  // Everything that can be refused is refused before the run, not after it.
  analysis::CheckResultsPath(output);
  std::vector<std::string> inputs = model.included_files;
  inputs.push_back(options.model);
  if (!options.record.empty()) {
    inputs.push_back(options.record);
    if (!options.record_h2.empty()) inputs.push_back(options.record_h2);
    if (!options.record_v.empty()) inputs.push_back(options.record_v);
  } else {
    const std::vector<std::string> records = model::RecordFiles(model);
    inputs.insert(inputs.end(), records.begin(), records.end());
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
  if (options.samples > 0) analysis::CheckRunBand(model);
  if (options.seed && options.samples == 0) {
    throw InputError({"--seed"}, "seeds the parameter sets --samples draws: give --samples");
  }
  const unsigned seed = options.seed.value_or(1);
  const analysis::RunOverrides overrides = ChooseOverrides(model, options);
  const analysis::Problem problem = analysis::Prepare(model, overrides);
  analysis::SolveOptions solve;
  solve.analysis = analysis::ChooseIntegrator(
      model.analysis, {options.integrator, options.rtol, options.atol}, "--");
  solve.output = ChooseOutput(model, options, problem);
  solve.results_path = output;
  solve.version = ISOLAB_VERSION;

  if (!options.json && !options.quiet) analysis::PrintPreamble(problem, out);
  out.flush();
  PrintWarnings(problem.summary.warnings);
  const analysis::Summary summary = analysis::Solve(solve, problem);
  std::optional<analysis::RunBand> band;
  if (options.samples > 0 && summary.ok()) {
    if (!options.quiet && !options.json) {
      fmt::print(stderr, "isolab run: {} parameter sets drawn from the model's uncertainty\n",
                 options.samples);
    }
    band = analysis::PredictRunBand(model, overrides, solve.analysis, options.samples, seed);
  }
  if (options.json) {
    nlohmann::json json = analysis::RunReport(problem, solve.analysis, summary);
    if (band) json["band"] = analysis::RunBandJson(*band, seed);
    out << json.dump(2) << "\n";
  } else {
    analysis::PrintSummary(problem, solve.analysis, summary, out);
    if (band) analysis::PrintRunBand(*band, seed, model.units, out);
  }
  // After the run: what the response itself shows (the model's warnings were printed before).
  PrintWarnings({summary.warnings.begin() + static_cast<long>(problem.summary.warnings.size()),
                 summary.warnings.end()});
  if (options.plot) {
    RunPlotScript("plot_result.py", {output, "-o", PlotDirectory(*options.plot, output)},
                  options.quiet);
  }
  return ExitCode(summary.run, problem.grid.dt, output);
}

}  // namespace isolab::cli
