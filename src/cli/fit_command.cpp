#include "fit_command.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "building_fit_command.h"
#include "finite_options.h"
#include "isolab/analysis/test_data_checks.h"
#include "isolab/core/errors.h"
#include "isolab/identification/fit.h"
#include "isolab/identification/identifiability.h"
#include "isolab/identification/testing_factors.h"
#include "isolab/io/cyclic_test_file.h"
#include "isolab/io/output_check.h"
#include "isolab/model/fit_spec_file.h"
#include "isolab/model/fitted_model_file.h"
#include "specimen_option.h"
#include "testing_factors_text.h"

namespace isolab::cli {
namespace {

using identification::FitData;
using identification::FitResult;
using identification::ModelParametrisation;

struct EnergyRow {
  std::string test;
  int cycle = 0;
  double amplitude = 0.0, measured = 0.0, fitted = 0.0;
};

// Energy of every fitted span, measured and modelled: a whole cycle's loop area, or, for a
// history fitted whole (cycle 0), the work of the force over it.
std::vector<EnergyRow> EnergyTable(const hysteresis::ParallelAssembly& model, const FitData& data) {
  std::vector<EnergyRow> rows;
  const auto forces = identification::SimulateForces(model, data.tests, data.one_specimen);
  for (std::size_t i = 0; i < data.tests.size(); ++i) {
    const auto& test = data.tests[i];
    const std::vector<double>& force = forces[i];
    for (const auto& span : data.fitted[i]) {
      int cycle = 0;
      for (std::size_t c = 0; c < test.cycles.size(); ++c) {
        const auto& whole = test.cycles[c];
        if (whole.begin == span.begin && whole.end == span.end) cycle = static_cast<int>(c) + 1;
      }
      rows.push_back({test.name, cycle, identification::SpanAmplitude(test.displacement, span),
                      identification::LoopEnergy(test.displacement, test.force, span),
                      identification::LoopEnergy(test.displacement, force, span)});
    }
  }
  return rows;
}

// Writes the fitted model: components the fit gave no stiffness dropped, those it left a
// simpler law written as that law (identification::SimplifyComponents). Returns the notes.
std::vector<std::string> WriteFittedModel(const std::string& path, const model::FitSpec& spec,
                                          const FitOptions& options, const FitResult& result,
                                          const std::vector<identification::ComponentSpec>& kept,
                                          const FitData& data,
                                          const std::vector<std::string>& testing) {
  model::FittedModel model;
  model.comment.push_back(
      fmt::format("Identified by isolab fit from {} (specification {}, seed {}, {} evaluations).",
                  fmt::join(options.data, ", "), spec.path, options.seed, result.evaluations));
  std::string errors = fmt::format(
      "e^2 = {:.6g} % per test on average, {:.6g} % summed (Markou & Manolis 2016, Eq. 20)",
      100 * result.error.Mean(), 100 * result.error.total);
  for (std::size_t i = 0; i < data.tests.size(); ++i) {
    errors += fmt::format("{}{}: {:.4g} %", i == 0 ? "; per test: " : ", ", data.tests[i].name,
                          100 * result.error.per_test[i]);
  }
  model.comment.push_back(errors);
  model.comment.insert(model.comment.end(), testing.begin(), testing.end());
  model.description = fmt::format("Fitted to {}", fmt::join(options.data, ", "));
  model.specification = spec.path;
  model.units = spec.units;
  model.range = identification::RangeOf(data);
  std::vector<std::string> names;
  std::vector<hysteresis::LawType> types;
  for (const auto& component : kept)
    names.push_back(component.name), types.push_back(component.type);
  std::vector<std::vector<double>> mathematical = result.mathematical;
  std::vector<std::string> notes = identification::SimplifyComponents(names, &types, &mathematical);
  model.components = kept;
  for (std::size_t c = 0; c < kept.size(); ++c) model.components[c].type = types[c];
  model.mathematical = mathematical;
  for (const std::string& note : notes) model.comment.push_back(note + ".");
  model::WriteFittedModel(path, model);
  return notes;
}

}  // namespace

void RegisterFitCommand(CLI::App& app, FitOptions& options) {
  CLI::App* command = app.add_subcommand(
      "fit", "Identify an isolator model's parameters from cyclic tests (CMA-ES)");
  command
      ->add_option("data", options.data,
                   "CSV test data: test,time,displacement,force (with --building: shake-table "
                   "CSV files, one per motion)")
      ->required()
      ->check(CLI::ExistingFile);
  CLI::Option* model =
      command
          ->add_option("--model", options.spec, "Specification: component types and counts (YAML)")
          ->check(CLI::ExistingFile);
  command
      ->add_option("--building", options.building,
                   "Building fit specification (YAML): a building model and the parameters to "
                   "identify from shake-table motions by output error")
      ->check(CLI::ExistingFile)
      ->excludes(model);
  command
      ->add_option("--offsets", options.offsets,
                   "With --building: accelerometer offsets, pre-event (each channel less its mean "
                   "before the table moves; default) or none, as isolab shaketable takes them")
      ->check(CLI::IsMember({"pre-event", "none"}));
  command->add_option("--seed", options.seed, "Seed; a fixed seed reproduces the fit exactly");
  command->add_option("--budget", options.budget, "Model evaluations (default 60000)")
      ->check(Between(100, 1e9));
  command
      ->add_option("--global-budget", options.global_budget,
                   "With --building: simulations of the global search (CMA-ES) before the "
                   "least-squares refinement; 0 refines from the specification's start (default: "
                   "half the budget, or one chunk of CMA-ES generations where that is more and "
                   "the budget allows it)")
      ->check(Between(0, 1e9));
  command->add_flag("--cross-validate", options.cross_validate,
                    "With --building and two motions or more: fit the building to all but one, "
                    "predict the one held out, each in turn; writes no model");
  command->add_option("--cycles", options.cycles,
                      "Whole cycles to fit, 1-based, e.g. --cycles 3 as the paper fits HDRB tests "
                      "(default: every test's whole history)");
  AddSpecimenOption(command, &options.specimen);
  command->add_option("-o,--output", options.output, "Fitted model file (YAML)");
  command->add_option("--force-unit", options.force_unit,
                      "Force unit of data files without a '# units:' line (with --length-unit)");
  command->add_option("--length-unit", options.length_unit,
                      "Length unit of data files without a '# units:' line (with --force-unit)");
  command
      ->add_option("--threads", options.threads,
                   "Threads (default: every hardware thread); the result does not depend on it")
      ->check(CLI::Range(0, 1024));
  command->add_flag("--force", options.force,
                    "Fit even when the work (evaluations x samples x laws) is beyond the limit");
  command->add_flag("--json", options.json, "Print the result as JSON");
  command->add_flag("-q,--quiet", options.quiet, "No progress on stderr");
}

void RunFitCommand(const FitOptions& options, std::ostream& out) {
  if (!options.building.empty()) return RunBuildingFitCommand(options, out);
  if (options.spec.empty()) {
    throw InputError({"command line"},
                     "give --model (cyclic tests) or --building (shake-table "
                     "motions)");
  }
  if (!options.offsets.empty()) {
    throw InputError({"command line"}, "--offsets applies to --building, not to cyclic tests");
  }
  if (options.global_budget >= 0) {
    throw InputError({"command line"},
                     "--global-budget applies to --building, not to cyclic tests");
  }
  if (options.cross_validate) {
    throw InputError({"command line"},
                     "--cross-validate applies to --building, not to cyclic tests");
  }
  const model::FitSpec spec = model::LoadFitSpec(options.spec);
  const std::string output =
      !options.output.empty()
          ? options.output
          : std::filesystem::path(options.spec).stem().string() + ".fitted.yaml";
  std::vector<std::string> inputs = options.data;
  inputs.push_back(options.spec);
  io::CheckOutputs(inputs, {output});
  const bool units_given = !options.force_unit.empty() && !options.length_unit.empty();
  io::CyclicTestSet set =
      io::ReadCyclicTests(options.data, {options.force_unit, options.length_unit}, spec.units);
  analysis::RequireUnits(set, units_given, "--force-unit and --length-unit");
  analysis::RequireFiniteSquares(set);
  const bool one_specimen = io::OneSpecimen(options.specimen, set.one_specimen);
  FitData data;
  try {
    data = identification::SelectCycles(std::move(set.tests), options.cycles, one_specimen);
  } catch (const std::invalid_argument& error) {
    throw InputError({"command line"}, fmt::format("--cycles: {}", error.what()));
  }
  std::optional<ModelParametrisation> model;
  try {
    model.emplace(spec.components, identification::ScalesOf(data));
  } catch (const std::invalid_argument& error) {
    throw InputError({spec.path}, error.what());
  }
  analysis::RequireMoreSamplesThanParameters(data, *model, spec.path);

  identification::FitOptions fit;
  fit.seed = options.seed;
  fit.budget = options.budget;
  fit.threads = options.threads;
  const analysis::FitWork work = analysis::EstimateFitWork(*model, data, fit);
  analysis::RequireWorkWithin(work, analysis::kWorkLimit, options.force, "command line (--force)");
  if (!options.quiet) {
    fmt::print(stderr,
               "isolab fit: {} tests ({}), {} shape coordinates and {} stiffnesses, budget {}\n  "
               "{}\n",
               data.tests.size(), one_specimen ? "one specimen, in order" : "independent specimens",
               model->dimension(), model->amplitude_count(), options.budget,
               work.Describe(analysis::kWorkLimit));
    fit.progress = [](const identification::FitProgress& p) {
      fmt::print(stderr, "  {} generation {:5d}, {:8d} evaluations, best e^2 = {:.6g} %\n",
                 p.polishing ? "polish    " : "CMA-ES    ", p.generation, p.evaluations,
                 100 * p.best);
    };
  }
  FitResult result;
  try {
    result = identification::Fit(*model, data, fit);
  } catch (const std::invalid_argument& error) {
    throw InputError({options.data.front()}, error.what());
  }
  const identification::Identifiability identifiability =
      identification::AssessIdentifiability(*model, data, result);
  const auto energy = EnergyTable(model->Assembly(result.point, result.amplitudes), data);
  // Components the fit gave no stiffness carry no force: dropped, with a note, e^2 unchanged.
  const std::vector<std::size_t> zero = identification::ZeroComponents(*model, result.amplitudes);
  std::vector<std::string> notes;
  for (const std::size_t c : zero) {
    notes.push_back(fmt::format(
        "{} ({}) was dropped: the fit gave it no stiffness, so the data need no such component",
        spec.components[c].name, hysteresis::LawName(spec.components[c].type)));
  }
  FitResult written = result;
  std::vector<identification::ComponentSpec> kept = spec.components;
  if (!zero.empty()) {
    if (zero.size() == spec.components.size()) {
      throw InputError({spec.path},
                       "the fit gave every component zero stiffness: the data have "
                       "no force these laws can carry");
    }
    kept = identification::DropComponents(*model, zero, &written);
  }
  const identification::TestingFactors testing = identification::TestingFactorsOf(data.tests);
  for (std::string& note : WriteFittedModel(output, spec, options, written, kept, data,
                                            TestingFactorsComment(testing, spec.units))) {
    notes.push_back(std::move(note));
  }
  const std::vector<std::string> findings = identifiability.Findings();

  if (options.json) {
    nlohmann::json json;
    json["e2"] = result.error.total;
    json["e2_mean"] = result.error.Mean();
    for (std::size_t i = 0; i < data.tests.size(); ++i) {
      json["e2_per_test"][data.tests[i].name] = result.error.per_test[i];
    }
    for (std::size_t c = 0; c < spec.components.size(); ++c) {
      const auto type = spec.components[c].type;
      const auto keys = hysteresis::ParameterKeys(type, hysteresis::ParameterForm::kMathematical);
      nlohmann::json parameters;
      for (std::size_t k = 0; k < keys.size(); ++k) {
        parameters[std::string(keys[k])] = result.mathematical[c][k];
      }
      json["components"].push_back({{"name", spec.components[c].name},
                                    {"type", hysteresis::LawName(type)},
                                    {"parameters", parameters}});
    }
    for (const EnergyRow& row : energy) {
      json["energy_per_cycle"].push_back({{"test", row.test},
                                          {"cycle", row.cycle},
                                          {"amplitude", row.amplitude},
                                          {"measured", row.measured},
                                          {"fitted", row.fitted}});
    }
    const identification::IdentifiedRange range = identification::RangeOf(data);
    json["identified_range"] = {{"displacement", range.displacement},
                                {"velocity", range.velocity},
                                {"cycles", range.cycles},
                                {"data", range.data}};
    json["evaluations"] = result.evaluations;
    json["restarts"] = result.restarts;
    json["seconds"] = result.seconds;
    json["stop"] = result.stop == identification::FitStop::kConverged ? "converged" : "budget";
    json["stop_reason"] = result.stop_reason;
    json["identifiability"] = findings;
    json["testing_factors"] = TestingFactorsJson(testing);
    json["notes"] = notes;
    json["work"] = work.Work();
    json["seed"] = options.seed;
    json["one_specimen"] = one_specimen;
    json["output"] = output;
    out << json.dump(2) << "\n";
    return;
  }
  const auto [low, high] =
      std::minmax_element(result.error.per_test.begin(), result.error.per_test.end());
  fmt::print(out,
             "e^2 per test: {:.4g} % on average ({:.4g} to {:.4g} % over {} tests; the paper's sum "
             "{:.4g} %)\n{} ({:.1f} s)\n\n",
             100 * result.error.Mean(), 100 * *low, 100 * *high, data.tests.size(),
             100 * result.error.total, result.stop_reason, result.seconds);
  fmt::print(out, "{:<14} {:>12} {:>16} {:>16} {:>9} {:>10}\n", "test", "amplitude", "W_d measured",
             "W_d fitted", "diff", "e^2");
  std::size_t test_index = 0;
  for (const EnergyRow& row : energy) {
    while (data.tests[test_index].name != row.test) ++test_index;
    fmt::print(out, "{:<14} {:>9.4g} {:<2} {:>16.6g} {:>16.6g} {:>8.2f}% {:>9.4f}%  ({})\n",
               row.test, row.amplitude, spec.units.length(), row.measured, row.fitted,
               100 * (row.fitted / row.measured - 1), 100 * result.error.per_test[test_index],
               row.cycle > 0 ? fmt::format("cycle {}", row.cycle) : "whole history");
  }
  fmt::print(out, "\n");
  for (std::size_t c = 0; c < spec.components.size(); ++c) {
    const auto type = spec.components[c].type;
    const auto keys = hysteresis::ParameterKeys(type, hysteresis::ParameterForm::kMathematical);
    fmt::print(out, "{:<8} {:<18}", spec.components[c].name, hysteresis::LawName(type));
    for (std::size_t k = 0; k < keys.size(); ++k) {
      fmt::print(out, " {}={:.6g}", keys[k], result.mathematical[c][k]);
    }
    fmt::print(out, "\n");
  }
  fmt::print(out, "\n{}", TestingFactorsText(testing, spec.units));
  if (!findings.empty()) {
    fmt::print(out, "\nidentifiability:\n");
    for (const std::string& finding : findings) fmt::print(out, "  {}\n", finding);
  }
  for (const std::string& note : notes) fmt::print(out, "\nnote: {}", note);
  fmt::print(out, "{}\nfitted model: {}\n", notes.empty() ? "" : "\n", output);
}

}  // namespace isolab::cli
