#include "building_fit_command.h"

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <fmt/ranges.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "building_measurement.h"
#include "isolab/analysis/building_fit.h"
#include "isolab/analysis/test_data_checks.h"
#include "isolab/core/errors.h"
#include "isolab/io/atomic_file.h"
#include "isolab/io/cyclic_test_file.h"
#include "isolab/io/output_check.h"
#include "isolab/model/building_fit_spec_file.h"
#include "isolab/model/fitted_building_file.h"

namespace isolab::cli {
namespace {

// The 95 % interval of a fitted value from its coordinate's standard deviation.
std::pair<double, double> Interval(const analysis::FittedParameter& p) {
  const double half = 1.96 * p.sigma;
  return p.log ? std::pair{p.value * std::exp(-half), p.value * std::exp(half)}
               : std::pair{p.value - half, p.value + half};
}

// Options that belong to cyclic-test fits; a force-driven building fit reads cyclic-test files,
// so it takes their units.
void RefuseCyclicOptions(const FitOptions& options, bool force_driven) {
  const auto refuse = [](const char* option, const char* why) {
    throw InputError({"command line"}, fmt::format("{} {}", option, why));
  };
  const char* const units =
      "applies to cyclic tests and force-driven fits (input: force), not to "
      "shake-table motions (they carry their units in the column names)";
  if (!options.cycles.empty()) refuse("--cycles", "applies to cyclic tests, not to --building");
  if (options.force) refuse("--force", "applies to cyclic tests, not to --building");
  if (!force_driven && !options.force_unit.empty()) refuse("--force-unit", units);
  if (!force_driven && !options.length_unit.empty()) refuse("--length-unit", units);
  if (force_driven && !options.offsets.empty()) {
    refuse("--offsets", "applies to shake-table motions, not to force-driven tests (input: force)");
  }
}

// Force-driven tests (cyclic-test files: the force applied to level 1 and its displacement), each
// a motion of the fit, sampled at one step. Throws InputError.
std::vector<analysis::BuildingMotion> ReadForceDriven(const FitOptions& options,
                                                      const model::ModelFile& model,
                                                      bool* one_specimen) {
  io::CyclicTestSet set =
      io::ReadCyclicTests(options.data,
                          {options.force_unit.empty() ? "kN" : options.force_unit,
                           options.length_unit.empty() ? "mm" : options.length_unit},
                          model.units);
  analysis::RequireUnits(set, !options.force_unit.empty() && !options.length_unit.empty(),
                         "--force-unit and --length-unit");
  analysis::RequireFiniteSquares(set);
  *one_specimen = io::OneSpecimen(options.specimen, set.one_specimen);
  const double seconds = model.units.SiFactor(dimension::kTime);
  std::vector<analysis::BuildingMotion> motions;
  for (std::size_t t = 0; t < set.tests.size(); ++t) {
    identification::CyclicTestData& test = set.tests[t];
    analysis::BuildingMotion& motion = motions.emplace_back();
    motion.name = test.name;
    analysis::BuildingMeasurements& measured = motion.measured;
    for (const double time : test.time)
      measured.time.push_back((time - test.time.front()) / seconds);
    const double dt = analysis::SampleStep(measured);
    for (std::size_t k = 1; k < measured.time.size(); ++k) {
      const double step = measured.time[k] - measured.time[k - 1];
      if (std::abs(step - dt) > 0.01 * dt) {
        throw InputError({set.source[t]},
                         fmt::format("test {}: sample {} comes {:g} s after the previous one, "
                                     "against {:g} s on average: a force-driven test must be "
                                     "sampled at one step",
                                     test.name, k, step * seconds, dt * seconds));
      }
    }
    measured.applied_force = std::move(test.force);
    measured.displacement = {std::move(test.displacement)};
    measured.acceleration = {{}};
  }
  return motions;
}

}  // namespace

void RunBuildingFitCommand(const FitOptions& options, std::ostream& out) {
  const model::BuildingFitSpecFile file = model::LoadBuildingFitSpec(options.building);
  RefuseCyclicOptions(options, file.force_driven);
  const model::ModelFile model = model::LoadModelFile(file.model);
  const std::string output =
      !options.output.empty()
          ? options.output
          : std::filesystem::path(options.building).stem().string() + ".fitted.yaml";
  std::vector<std::string> inputs = options.data;
  inputs.push_back(options.building);
  inputs.push_back(file.model);
  for (const std::string& included : model.included_files) inputs.push_back(included);
  io::CheckOutputs(inputs, {output});

  analysis::BuildingFitSpec spec;
  for (const model::BuildingFitParameterEntry& entry : file.parameters) {
    spec.parameters.push_back({entry.name, entry.low, entry.high, entry.start});
  }
  for (const std::string& channel : file.channels) {
    spec.channels.push_back(analysis::ParseChannel(channel, file.path));
  }
  spec.band_low = file.band_low;
  spec.band_high = file.band_high;
  spec.pause = file.pause;
  spec.substeps = file.substeps;
  spec.sequential = options.specimen == "sequential";

  const std::size_t levels = analysis::LevelMasses(model).size();
  std::vector<analysis::BuildingMotion> motions;
  if (file.force_driven) {
    motions = ReadForceDriven(options, model, &spec.sequential);
    // What a force-driven test measures: the displacement where the force acts.
    if (spec.channels.empty())
      spec.channels.push_back({analysis::BuildingChannel::Kind::kDisplacement, 1});
  }
  for (const std::string& data : file.force_driven ? std::vector<std::string>{} : options.data) {
    ShakeTableOptions read;
    read.data = data;
    read.model = file.model;
    if (!options.offsets.empty()) read.offsets = options.offsets;
    Measured measured = ReadMeasured(read, model.units, levels);
    if (!options.quiet) {
      fmt::print(stderr,
                 "isolab fit --building: {}: {} samples, levels (slab to roof) = "
                 "channels {}; {}\n",
                 data, measured.time.size(), fmt::join(measured.channels, ","),
                 measured.reference_note);
    }
    motions.push_back({std::filesystem::path(data).stem().string(), std::move(measured)});
  }

  identification::FitOptions fit;
  fit.seed = options.seed;
  fit.budget = options.budget;
  fit.threads = options.threads;
  if (!options.quiet) {
    fmt::print(stderr, "  {} parameters, {} motions ({}), budget {} simulations\n",
               spec.parameters.size(), motions.size(),
               spec.sequential ? "one specimen, in order" : "each from rest", options.budget);
    fit.progress = [](const identification::FitProgress& p) {
      fmt::print(stderr, "  {} generation {:5d}, {:8d} simulations, best mean NRMSE^2 = {:.6g}\n",
                 p.polishing ? "polish    " : "CMA-ES    ", p.generation, p.evaluations, p.best);
    };
  }
  const analysis::BuildingFitResult result = analysis::FitBuilding(model, motions, spec, fit);
  const std::string text = model::FittedBuildingText(
      result.fitted, fmt::format("identified by isolab fit --building {} from {}", options.building,
                                 fmt::join(options.data, ", ")));
  io::WriteTextFileAtomically(output, [&](std::ostream& o) { o << text; });

  if (options.json) {
    nlohmann::json json;
    for (const analysis::FittedParameter& p : result.parameters) {
      const auto [low, high] = Interval(p);
      json["parameters"].push_back({{"name", p.name},
                                    {"start", p.start},
                                    {"value", p.value},
                                    {"sigma", p.sigma},
                                    {"log", p.log},
                                    {"interval_95", {low, high}},
                                    {"at_bound", p.at_bound}});
    }
    for (const analysis::ChannelFit& c : result.channels) {
      json["channels"].push_back({{"motion", c.motion},
                                  {"channel", c.channel},
                                  {"nrmse_start", c.nrmse_start},
                                  {"nrmse", c.nrmse}});
    }
    for (const analysis::CorrelatedParameters& pair : result.not_separated) {
      json["not_separated"].push_back(
          {{"a", pair.a}, {"b", pair.b}, {"correlation", pair.correlation}});
    }
    if (const auto& range = result.fitted.identified_range) {
      json["identified_range"] = {{"displacement", range->displacement},
                                  {"velocity", range->velocity},
                                  {"cycles", range->cycles},
                                  {"data", range->data}};
    }
    json["objective_start"] = result.objective_start;
    json["objective"] = result.objective;
    json["samples"] = result.samples;
    json["effective_samples"] = result.effective_samples;
    json["correlation_time"] = result.correlation_time;
    json["evaluations"] = result.search.evaluations;
    json["stop"] =
        result.search.stop == identification::FitStop::kConverged ? "converged" : "budget";
    json["stop_reason"] = result.search.stop_reason;
    json["seconds"] = result.seconds;
    json["sequential"] = spec.sequential;
    json["output"] = output;
    out << json.dump(2) << "\n";
    return;
  }
  fmt::print(out, "mean NRMSE^2 over {} channels: {:.4g} -> {:.4g}\n{} ({:.1f} s)\n\n",
             result.channels.size(), result.objective_start, result.objective,
             result.search.stop_reason, result.seconds);
  fmt::print(out, "| parameter | start | fitted | 95 % interval |\n|---|---|---|---|\n");
  for (const analysis::FittedParameter& p : result.parameters) {
    const auto [low, high] = Interval(p);
    fmt::print(out, "| {} | {:.4g} | {:.4g} | {:.4g} to {:.4g}{} |\n", p.name, p.start, p.value,
               low, high, p.at_bound ? " (at the range's end)" : "");
  }
  fmt::print(out, "\n| motion | channel | NRMSE start | NRMSE fitted |\n|---|---|---|---|\n");
  for (const analysis::ChannelFit& c : result.channels) {
    fmt::print(out, "| {} | {} | {:.3f} | {:.3f} |\n", c.motion, c.channel, c.nrmse_start, c.nrmse);
  }
  fmt::print(out,
             "\nThe residual is correlated over {:.3g} {}: its {:.0f} samples are worth {:.0f} "
             "independent ones, and the intervals count them so.\n",
             result.correlation_time, model.units.time(), result.samples, result.effective_samples);
  for (const analysis::CorrelatedParameters& pair : result.not_separated) {
    fmt::print(out,
               "not separately identified: {} and {} (correlation {:.3f}): the data fix a "
               "combination of the two\n",
               pair.a, pair.b, pair.correlation);
  }
  fmt::print(out, "fitted model: {}\n", output);
}

}  // namespace isolab::cli
