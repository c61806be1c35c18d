#include "cyclic_command.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "common_options.h"
#include "finite_options.h"
#include "heavy_commands.h"
#include "isolab/core/errors.h"
#include "isolab/cyclic/cyclic_campaign.h"
#include "isolab/cyclic/model_replay.h"
#include "isolab/hysteresis/cyclic_test.h"
#include "isolab/identification/synthetic_tests.h"
#include "isolab/io/atomic_file.h"
#include "isolab/io/cyclic_test_file.h"
#include "isolab/io/output_check.h"
#include "isolab/model/model_file.h"

namespace isolab::cli {
namespace {

using hysteresis::CyclicProtocol;
using hysteresis::CyclicResult;
using hysteresis::ParameterForm;
using Vec2Alias = hysteresis::Vec2;

struct Run {
  const model::ModelFile* model;
  CyclicResult result;
};

std::string ParameterText(const hysteresis::LawParameters& parameters, ParameterForm form) {
  const auto keys = hysteresis::ParameterKeys(parameters.type(), form);
  const auto values = parameters.Values(form);
  std::string text;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (std::isnan(values[i])) continue;  // an omitted breakpoint between equal slopes
    text += fmt::format("{}{}={:.6g}", text.empty() ? "" : " ", keys[i], values[i]);
  }
  return text;
}

void PrintModel(const model::ModelFile& model, std::ostream& out) {
  fmt::print(out, "== {} ==\n", model.path);
  if (!model.description.empty()) fmt::print(out, "{}\n", model.description);
  fmt::print(out, "{:<12} {:<18} {:<48} {}\n", "component", "type", "mathematical", "mechanical");
  for (const auto& component : model.isolation.components()) {
    fmt::print(out, "{:<12} {:<18} {:<48} {}\n", component.name,
               hysteresis::LawName(component.parameters.type()),
               ParameterText(component.parameters, ParameterForm::kMathematical),
               ParameterText(component.parameters, ParameterForm::kMechanical));
  }
}

void PrintRun(const Run& run, std::ostream& out) {
  const UnitSystem& u = run.model->units;
  const CyclicProtocol& p = run.result.protocol;
  fmt::print(out, "\nu_a = {:g} {}, T = {:g} {}, {} cycles, {} steps per cycle\n", p.amplitude,
             u.length(), p.period, u.time(), p.cycles, p.steps_per_cycle);
  fmt::print(out, "{:>5} {:>16} {:>14}   slider displacement at +u_a [{}]\n", "cycle",
             fmt::format("W_d [{}*{}]", u.force(), u.length()),
             fmt::format("peak|F| [{}]", u.force()), u.length());
  fmt::print(out, "{:>38}", "");
  for (const auto& component : run.model->isolation.components()) {
    fmt::print(out, " {:>11}", component.name);
  }
  fmt::print(out, "\n");
  for (const auto& cycle : run.result.cycles) {
    fmt::print(out, "{:>5} {:>16.6g} {:>14.6g}  ", cycle.index, cycle.dissipated, cycle.peak_force);
    for (const auto& component : cycle.components)
      fmt::print(out, " {:>11.6g}", component.slider_at_peak);
    fmt::print(out, "\n");
  }
}

// Energy of the last cycle against amplitude, when one model ran at several amplitudes.
void PrintAmplitudeTable(const std::vector<Run>& runs, std::size_t first, std::ostream& out) {
  const UnitSystem& u = runs[first].model->units;
  fmt::print(out, "\nlast cycle against amplitude\n{:>12} {:>16} {:>14}\n",
             fmt::format("u_a [{}]", u.length()), fmt::format("W_d [{}*{}]", u.force(), u.length()),
             fmt::format("peak|F| [{}]", u.force()));
  for (std::size_t i = first; i < runs.size() && runs[i].model == runs[first].model; ++i) {
    const auto& last = runs[i].result.cycles.back();
    fmt::print(out, "{:>12g} {:>16.6g} {:>14.6g}\n", runs[i].result.protocol.amplitude,
               last.dissipated, last.peak_force);
  }
}

nlohmann::json ParameterJson(const hysteresis::LawParameters& parameters, ParameterForm form) {
  nlohmann::json json = nlohmann::json::object();
  const auto keys = hysteresis::ParameterKeys(parameters.type(), form);
  const auto values = parameters.Values(form);
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (!std::isnan(values[i])) json[std::string(keys[i])] = values[i];
  }
  return json;
}

nlohmann::json RunJson(const Run& run) {
  const auto& components = run.model->isolation.components();
  nlohmann::json json;
  json["model"] = run.model->path;
  json["units"] = {{"force", run.model->units.force()},
                   {"length", run.model->units.length()},
                   {"time", run.model->units.time()}};
  const CyclicProtocol& p = run.result.protocol;
  json["protocol"] = {{"amplitude", p.amplitude},
                      {"period", p.period},
                      {"cycles", p.cycles},
                      {"steps_per_cycle", p.steps_per_cycle}};
  json["components"] = nlohmann::json::array();
  for (const auto& component : components) {
    json["components"].push_back(
        {{"name", component.name},
         {"type", hysteresis::LawName(component.parameters.type())},
         {"mathematical", ParameterJson(component.parameters, ParameterForm::kMathematical)},
         {"mechanical", ParameterJson(component.parameters, ParameterForm::kMechanical)}});
  }
  json["cycles"] = nlohmann::json::array();
  for (const auto& cycle : run.result.cycles) {
    nlohmann::json per_component = nlohmann::json::array();
    for (std::size_t c = 0; c < components.size(); ++c) {
      per_component.push_back({{"name", components[c].name},
                               {"dissipated", cycle.components[c].dissipated},
                               {"slider_at_peak", cycle.components[c].slider_at_peak}});
    }
    json["cycles"].push_back({{"cycle", cycle.index},
                              {"dissipated", cycle.dissipated},
                              {"peak_force", cycle.peak_force},
                              {"components", per_component}});
  }
  return json;
}

void WriteLoopCsv(const Run& run, const std::string& path) {
  const auto& components = run.model->isolation.components();
  const auto& loop = run.result.loop;
  io::WriteTextFileAtomically(path, [&](std::ostream& out) {
    const UnitSystem& u = run.model->units;
    fmt::print(out, "time_{},u_{},force_{}", u.time(), u.length(), u.force());
    for (const auto& component : components)
      fmt::print(out, ",force_{}_{}", component.name, u.force());
    fmt::print(out, "\n");
    for (std::size_t k = 0; k < loop.time.size(); ++k) {
      fmt::print(out, "{:.10g},{:.10g},{:.10g}", loop.time[k], loop.displacement[k], loop.force[k]);
      for (std::size_t c = 0; c < components.size(); ++c) {
        fmt::print(out, ",{:.10g}", loop.component_force[k * components.size() + c]);
      }
      fmt::print(out, "\n");
    }
  });
}

// One CSV per run; with several runs, "loop.csv" becomes "loop_<run>_<model>_<amplitude>.csv",
// the run number keeping repeated models and amplitudes apart.
std::string CsvPath(const std::string& csv, const Run& run, std::size_t index, bool several) {
  if (!several) return csv;
  const std::filesystem::path base(csv);
  const std::string stem = std::filesystem::path(run.model->path).stem().string();
  const std::string name = fmt::format("{}_{}_{}_{:g}{}", base.stem().string(), index + 1, stem,
                                       run.result.protocol.amplitude, base.extension().string());
  return (base.parent_path() / name).string();
}

// --path and --orbit: the model driven along given paths (cyclic/path_replay.h).
using Replayed = cyclic::ReplayRun;

std::string Vector(Vec2Alias v, bool plan) {
  return plan ? fmt::format("({:.6g}, {:.6g})", v.x, v.y) : fmt::format("{:.6g}", v.x);
}

void PrintReplay(const Replayed& run, std::ostream& out) {
  const auto& r = run.result;
  const UnitSystem& u = run.units;
  fmt::print(out, "\n== {} along '{}' ({} samples, {:.6g} {}, {}) ==\n", run.model, r.name,
             r.time.size(), r.time.back() - r.time.front(), u.time(),
             r.plan ? "two directions" : "one direction");
  fmt::print(out, "peak |u| = {:.6g} {}, peak |F| = {:.6g} {}, dissipated {:.6g} {}*{}\n",
             r.peak_displacement, u.length(), r.peak_force, u.force(), r.dissipated.back(),
             u.force(), u.length());
  if (r.comparison) {
    const auto& c = *r.comparison;
    fmt::print(out,
               "against the measured force: e^2 = {:.4g} %, NRMSE = {:.4g} (RMS error over the "
               "measured force's RMS{}), RMS error {:.4g} % of its range, peak |F| measured "
               "{:.6g}, modelled {:.6g} ({:+.1f} %)\n",
               100 * c.e2, c.nrmse,
               c.nrmse > 1.0 ? "; above 1: worse than predicting a force of zero" : "",
               100 * c.error_over_range, c.peak_measured, c.peak_modelled,
               100 * (c.peak_modelled / c.peak_measured - 1));
  }
  if (!r.cycles.empty()) {
    fmt::print(out, "{:>5} {:>16} {:>14}   {:<28} {}\n", "cycle",
               fmt::format("W_d [{}*{}]", u.force(), u.length()),
               fmt::format("peak|F| [{}]", u.force()), fmt::format("u at end [{}]", u.length()),
               fmt::format("F at end [{}]", u.force()));
    for (const auto& c : r.cycles) {
      fmt::print(out, "{:>5} {:>16.6g} {:>14.6g}   {:<28} {}\n", c.index, c.dissipated,
                 c.peak_force, Vector(c.displacement_at_end, r.plan),
                 Vector(c.force_at_end, r.plan));
    }
  }
}

nlohmann::json ReplayJson(const Replayed& run) {
  const auto& r = run.result;
  const auto vec = [&](Vec2Alias v) {
    return r.plan ? nlohmann::json::array({v.x, v.y}) : nlohmann::json(v.x);
  };
  nlohmann::json json = {
      {"model", run.model},
      {"path", r.name},
      {"plan", r.plan},
      {"units",
       {{"force", run.units.force()}, {"length", run.units.length()}, {"time", run.units.time()}}},
      {"samples", r.time.size()},
      {"components", r.components},
      {"peak_displacement", r.peak_displacement},
      {"peak_force", r.peak_force},
      {"dissipated", r.dissipated.back()},
      {"final_force", vec(r.force.back())},
      {"cycles", nlohmann::json::array()}};
  for (const auto& c : r.cycles) {
    json["cycles"].push_back({{"cycle", c.index},
                              {"dissipated", c.dissipated},
                              {"peak_force", c.peak_force},
                              {"displacement_at_end", vec(c.displacement_at_end)},
                              {"force_at_end", vec(c.force_at_end)}});
  }
  if (r.comparison) {
    json["comparison"] = {{"e2", r.comparison->e2},
                          {"nrmse", r.comparison->nrmse},
                          {"error_over_range", r.comparison->error_over_range},
                          {"peak_measured", r.comparison->peak_measured},
                          {"peak_modelled", r.comparison->peak_modelled}};
  }
  return json;
}

void WriteReplayCsv(const Replayed& run, const std::string& path) {
  const auto& r = run.result;
  const UnitSystem& u = run.units;
  const std::vector<std::string> axes =
      r.plan ? std::vector<std::string>{"_x", "_y"} : std::vector<std::string>{""};
  io::WriteTextFileAtomically(path, [&](std::ostream& out) {
    fmt::print(out, "time_{}", u.time());
    for (const auto& a : axes) fmt::print(out, ",u{}_{}", a, u.length());
    for (const auto& a : axes) fmt::print(out, ",force{}_{}", a, u.force());
    for (const auto& c : r.components) {
      for (const auto& a : axes) fmt::print(out, ",force_{}{}_{}", c, a, u.force());
    }
    if (!r.measured.empty()) {
      for (const auto& a : axes) fmt::print(out, ",measured{}_{}", a, u.force());
    }
    fmt::print(out, "\n");
    const std::size_t m = r.components.size();
    const auto put = [&](Vec2Alias v) {
      fmt::print(out, ",{:.10g}", v.x);
      if (r.plan) fmt::print(out, ",{:.10g}", v.y);
    };
    for (std::size_t k = 0; k < r.time.size(); ++k) {
      fmt::print(out, "{:.10g}", r.time[k]);
      put(r.displacement[k]);
      put(r.force[k]);
      for (std::size_t c = 0; c < m; ++c) put(r.component_force[k * m + c]);
      if (!r.measured.empty()) put(r.measured[k]);
      fmt::print(out, "\n");
    }
  });
}

// Options of one mode given in the other are refused, not ignored: the sinusoidal test of a
// one-direction isolation (-a, -T, -n, --steps-per-cycle, --test-data with its --noise, --seed and
// --sequential) and a path (--path with its units, or --orbit shaped by -a, -T, -n,
// --steps-per-cycle; --isolator of a plan model, --uncoupled of a one-direction one).
void RefuseOptionsOfTheOtherMode(const CyclicOptions& options) {
  const auto refuse = [](const char* option, const char* why) { throw InputError({option}, why); };
  const bool path = !options.paths.empty(), orbit = !options.orbit.empty();
  if (path || orbit) {
    const char* sinusoidal = "writes the sinusoidal tests (without --path or --orbit) as test data";
    if (!options.test_data.empty()) refuse("--test-data", sinusoidal);
    if (options.noise != 0.0) refuse("--noise", sinusoidal);
    if (options.seed) refuse("--seed", sinusoidal);
    if (options.sequential) refuse("--sequential", "runs the sinusoidal tests on one specimen");
  } else {
    const char* along = "applies to a model driven along --path or --orbit";
    if (!options.isolator.empty()) refuse("--isolator", along);
    if (options.uncoupled) refuse("--uncoupled", along);
    if (!options.force_unit.empty()) refuse("--force-unit", "the units of a --path file");
    if (!options.length_unit.empty()) refuse("--length-unit", "the units of a --path file");
    if (options.test_data.empty() && (options.noise != 0.0 || options.seed)) {
      refuse(options.noise != 0.0 ? "--noise" : "--seed",
             "noise on --test-data, which is not given");
    }
  }
  if (path) {
    const char* shaped = "shapes an --orbit or the sinusoidal test; a --path gives its own history";
    if (!options.amplitudes.empty()) refuse("--amplitude", shaped);
    if (!options.periods.empty()) refuse("--period", shaped);
    if (options.cycles) refuse("--cycles", shaped);
    if (options.steps_per_cycle) refuse("--steps-per-cycle", shaped);
  }
  if (orbit && (!options.force_unit.empty() || !options.length_unit.empty())) {
    refuse(options.force_unit.empty() ? "--length-unit" : "--force-unit",
           "the units of a --path file; an --orbit is in the model's units");
  }
}

void RunReplay(const CyclicOptions& options, std::ostream& out) {
  if (!options.paths.empty() && !options.orbit.empty()) {
    throw InputError({"command line"}, "--path and --orbit: give one or the other");
  }
  cyclic::ReplayRequest request;
  request.paths = options.paths;
  request.orbit = options.orbit;
  request.amplitudes = options.amplitudes;
  request.periods = options.periods;
  request.cycles = options.cycles;
  request.steps_per_cycle = options.steps_per_cycle;
  request.isolator = options.isolator;
  request.uncoupled = options.uncoupled;
  request.force_unit = options.force_unit;
  request.length_unit = options.length_unit;
  std::vector<Replayed> runs;
  std::vector<std::string> inputs;
  for (const std::string& file : options.models) {
    const model::ModelFile model = model::LoadModelFile(file);
    inputs.push_back(file);
    inputs.insert(inputs.end(), model.included_files.begin(), model.included_files.end());
    for (Replayed& run : cyclic::ReplayModel(model, request, cyclic::OptionStyle::kCommandLine)) {
      runs.push_back(std::move(run));
    }
  }
  inputs.insert(inputs.end(), options.paths.begin(), options.paths.end());
  std::vector<std::string> outputs;
  if (!options.csv.empty()) {
    for (std::size_t i = 0; i < runs.size(); ++i) {
      if (runs.size() == 1) {
        outputs.push_back(options.csv);
      } else {
        const std::filesystem::path base(options.csv);
        outputs.push_back(
            (base.parent_path() / fmt::format("{}_{}_{}{}", base.stem().string(), i + 1,
                                              runs[i].result.name, base.extension().string()))
                .string());
      }
    }
  }
  io::CheckOutputs(inputs, outputs);
  for (std::size_t i = 0; i < outputs.size(); ++i) WriteReplayCsv(runs[i], outputs[i]);
  if (options.json) {
    nlohmann::json json = {{"runs", nlohmann::json::array()}};
    for (const Replayed& run : runs) json["runs"].push_back(ReplayJson(run));
    out << json.dump(2) << "\n";
    return;
  }
  for (const Replayed& run : runs) PrintReplay(run, out);
}

}  // namespace

void RegisterCyclicCommand(CLI::App& app, CyclicOptions& options) {
  CLI::App* command =
      app.add_subcommand(std::string(kCyclicCommand.name), std::string(kCyclicCommand.help));
  command->add_option("models", options.models, "Model files (YAML) with an isolation section")
      ->required()
      ->check(CLI::ExistingFile);
  command
      ->add_option("-a,--amplitude", options.amplitudes,
                   "Displacement amplitude(s) u_a, comma-separated (model length unit)")
      ->delimiter(',');
  command
      ->add_option("-T,--period", options.periods,
                   "Period(s) T, comma-separated (model time unit); one run per amplitude each")
      ->delimiter(',');
  command->add_option("-n,--cycles", options.cycles, "Number of cycles");
  command->add_option("--steps-per-cycle", options.steps_per_cycle,
                      "Samples per cycle, a multiple of 4");
  command->add_option("--csv", options.csv, "Write the loop (time, u, force, force per component)");
  command->add_option("--test-data", options.test_data,
                      "Write the runs as cyclic test data (test,time,displacement,force CSV)");
  command
      ->add_option("--noise", options.noise,
                   "Gaussian force noise on --test-data, relative to each test's RMS force")
      ->check(Between(0.0, 1.0));
  AddSeedOption(command, &options.seed, "Seed of the --noise generator");
  command->add_flag("--sequential", options.sequential,
                    "Run a model's tests one after another on one specimen, each from the state "
                    "the previous left (a campaign); --test-data then says '# specimen: one'");
  command
      ->add_option("--path", options.paths,
                   "Drive the model along displacement paths instead: CSV of time and "
                   "displacement (or displacement_x, displacement_y), with the measured force "
                   "(force, or force_x, force_y) when there is one")
      ->check(CLI::ExistingFile);
  command
      ->add_option("--orbit", options.orbit,
                   "Drive the model round a circle or figure8 in plan, of radius -a, period "
                   "-T, -n cycles")
      ->check(CLI::IsMember({"circle", "figure8"}));
  command->add_option("--isolator", options.isolator,
                      "A plan model's isolator to drive (default: each of them)");
  command->add_flag("--uncoupled", options.uncoupled,
                    "In two directions, each law of a one-direction model along x and y "
                    "separately (default: its coupled form)");
  command->add_option("--force-unit", options.force_unit,
                      "Force unit of path files without a '# units:' line (with --length-unit)");
  command->add_option("--length-unit", options.length_unit,
                      "Length unit of path files without a '# units:' line (with --force-unit)");
  AddJsonFlag(command, &options.json, "Print machine-readable JSON instead of tables");
  AddQuietFlag(command, &options.quiet, "No component table before the cycles");
}

void RunCyclicCommand(const CyclicOptions& options, std::ostream& out) {
  RefuseOptionsOfTheOtherMode(options);
  if (!options.paths.empty() || !options.orbit.empty()) {
    RunReplay(options, out);
    return;
  }
  std::vector<model::ModelFile> models;
  models.reserve(options.models.size());
  for (const std::string& path : options.models) models.push_back(model::LoadModelFile(path));

  cyclic::CyclicRequest request;
  request.amplitudes = options.amplitudes;
  request.periods = options.periods;
  request.cycles = options.cycles;
  request.steps_per_cycle = options.steps_per_cycle;
  request.sequential = options.sequential;
  std::vector<Run> runs;
  for (const model::ModelFile& model : models) {
    for (hysteresis::CyclicResult& result : cyclic::RunCyclicCampaign(model, request)) {
      runs.push_back({&model, std::move(result)});
    }
  }

  // The loops are cheap; their outputs are checked before any is written.
  std::vector<std::string> inputs, outputs;
  for (const model::ModelFile& model : models) {
    inputs.push_back(model.path);
    inputs.insert(inputs.end(), model.included_files.begin(), model.included_files.end());
  }
  if (!options.csv.empty()) {
    for (std::size_t i = 0; i < runs.size(); ++i) {
      outputs.push_back(CsvPath(options.csv, runs[i], i, runs.size() > 1));
    }
  }
  if (!options.test_data.empty()) outputs.push_back(options.test_data);
  io::CheckOutputs(inputs, outputs);
  if (!options.csv.empty()) {
    for (std::size_t i = 0; i < runs.size(); ++i) WriteLoopCsv(runs[i], outputs[i]);
  }

  if (!options.test_data.empty()) {
    std::vector<hysteresis::CyclicResult> loops;
    for (const Run& run : runs) loops.push_back(run.result);
    std::vector<identification::CyclicTestData> tests =
        cyclic::TestsFromLoops(loops, options.periods.size() > 1);
    if (models.size() > 1) {
      for (std::size_t i = 0; i < runs.size(); ++i) {
        tests[i].name =
            std::filesystem::path(runs[i].model->path).stem().string() + ":" + tests[i].name;
      }
    }
    identification::AddForceNoise(&tests, options.noise, options.seed.value_or(1));
    io::WriteCyclicTests(options.test_data, tests, models.front().units,
                         options.sequential && models.size() == 1);
  }

  if (options.json) {
    nlohmann::json json = {{"runs", nlohmann::json::array()}};
    for (const Run& run : runs) json["runs"].push_back(RunJson(run));
    out << json.dump(2) << "\n";
    return;
  }
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const bool first_of_model = i == 0 || runs[i - 1].model != runs[i].model;
    if (first_of_model && options.quiet) fmt::print(out, "== {} ==\n", runs[i].model->path);
    if (first_of_model && !options.quiet) {
      fmt::print(out, "{}", i == 0 ? "" : "\n"), PrintModel(*runs[i].model, out);
    }
    PrintRun(runs[i], out);
    const bool last_of_model = i + 1 == runs.size() || runs[i + 1].model != runs[i].model;
    if (last_of_model && !first_of_model) {
      std::size_t first = i;
      while (first > 0 && runs[first - 1].model == runs[i].model) --first;
      PrintAmplitudeTable(runs, first, out);
    }
  }
}

}  // namespace isolab::cli
