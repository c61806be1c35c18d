#include "shaketable_command.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numeric>
#include <optional>
#include <sstream>

#include "common_options.h"
#include "heavy_commands.h"
#include "isolab/analysis/results_file.h"
#include "isolab/building/prediction_band.h"
#include "isolab/building/shake_table_measurements.h"
#include "isolab/building/shake_table_prediction.h"
#include "isolab/core/errors.h"
#include "isolab/io/atomic_file.h"
#include "isolab/io/cyclic_test_file.h"
#include "isolab/io/output_check.h"
#include "isolab/model/model_file.h"

namespace isolab::cli {

void RegisterShakeTableCommand(CLI::App& app, ShakeTableOptions& options) {
  CLI::App* command = app.add_subcommand(std::string(kShakeTableCommand.name),
                                         std::string(kShakeTableCommand.help));
  command->add_option("data", options.data, "Shake-table CSV (named columns with units)")
      ->required()
      ->check(CLI::ExistingFile);
  command
      ->add_option("--model", options.model,
                   "Building model: shear_building with base_mass (floor masses); its "
                   "isolation and damping for --predict")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--levels", options.channels.levels,
                      "Channel numbers from the isolation slab to the roof, e.g. 6,5,4,3,2,1; "
                      "auto: by RMS displacement relative to the table (default)");
  command
      ->add_option("--displacements", options.channels.displacements,
                   "Floor displacements relative to the table, absolute, or auto (default: "
                   "decided from the data)")
      ->check(CLI::IsMember({"auto", "relative", "absolute"}));
  command
      ->add_option("--offsets", options.channels.offsets,
                   "Accelerometer offsets: pre-event (each channel less its mean before the "
                   "table moves; default) or none")
      ->check(CLI::IsMember({"pre-event", "none"}));
  command->add_option("--acceleration-prefix", options.channels.acceleration_prefix,
                      "Floor acceleration channels are PREFIX<n> (default a)");
  command->add_option("--displacement-prefix", options.channels.displacement_prefix,
                      "Floor displacement channels are PREFIX<n> (default d)");
  command->add_option("--isolator", options.isolator,
                      "Write the isolator's history as cyclic-test CSV (for fit and diagnose)");
  command->add_option("--record", options.record,
                      "Write the table acceleration as a record CSV (for isolab run --record)");
  command->add_flag("--predict", options.predict,
                    "Run the model under the measured table acceleration and compare");
  command
      ->add_option("--samples", options.samples,
                   "With --predict: parameter sets drawn from the fitted model's uncertainty "
                   "(isolab fit --building) for a 5-95 % band on the prediction")
      ->check(CLI::Range(2, 100000));
  AddSeedOption(command, &options.seed, "Seed of the drawn parameter sets (--samples)");
  command->add_option("--results", options.results,
                      "With --predict: HDF5 results of the prediction (default: <data file "
                      "stem>.predicted.h5 in the working folder)");
  command->add_option("--comparison", options.comparison,
                      "With --predict: CSV of measured and predicted histories (for the overlay "
                      "plot)");
  AddJsonFlag(command, &options.json, "Print the summary as JSON");
  AddQuietFlag(command, &options.quiet);
}

namespace {

// What `isolab shaketable` measured and predicted, composed before anything is written.
struct ShakeTableOutcome {
  building::LevelMeasurements m;
  identification::CyclicTestData isolator;  // the slab's displacement against the base shear
  building::Signal shear;
  double weight = 0.0;
  std::optional<building::ShakeTablePrediction> prediction;
  std::optional<building::PredictionBand> band;
  std::string results_path;
};

// Measured against predicted in time, with the band's 5 and 95 % where one was drawn.
void WriteComparison(const std::string& path, const ShakeTableOutcome& o) {
  const building::LevelMeasurements& m = o.m;
  const building::ShakeTablePrediction& p = *o.prediction;
  const std::optional<building::PredictionBand>& band = o.band;
  io::WriteTextFileAtomically(path, [&](std::ostream& file) {
    fmt::print(file,
               "time_s,isolator_displacement_measured,isolator_displacement_predicted,"
               "base_shear_measured,base_shear_predicted,roof_acceleration_measured,"
               "roof_acceleration_predicted{}\n",
               band ? ",isolator_displacement_p5,isolator_displacement_p95,"
                      "roof_acceleration_p5,roof_acceleration_p95"
                    : "");
    for (std::size_t k = 0; k < m.time.size(); ++k) {
      fmt::print(file, "{:.4f},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}", m.time[k],
                 m.displacement.front()[k], p.isolator_displacement[k], o.shear[k], p.base_shear[k],
                 m.acceleration.back()[k], p.roof_acceleration[k]);
      if (band) {
        fmt::print(file, ",{:.6g},{:.6g},{:.6g},{:.6g}", band->isolator_p5[k],
                   band->isolator_p95[k], band->roof_p5[k], band->roof_p95[k]);
      }
      fmt::print(file, "\n");
    }
  });
}

nlohmann::json ShakeTableJson(const ShakeTableOptions& options, const UnitSystem& units,
                              const ShakeTableOutcome& o) {
  const building::LevelMeasurements& m = o.m;
  const std::optional<building::PredictionBand>& band = o.band;
  nlohmann::json json;
  json["data"] = options.data;
  json["model"] = options.model;
  json["levels"] = m.channels;
  json["displacement_reference"] = m.reference_note;
  json["samples"] = m.time.size();
  json["half_cycles"] = o.isolator.half_cycles.size();
  json["weight"] = o.weight;
  json["units"] = {{"force", units.force()}, {"length", units.length()}, {"time", units.time()}};
  if (o.prediction) {
    for (const building::ComparedPeak& row : o.prediction->peaks) {
      json["comparison"].push_back({{"quantity", row.quantity},
                                    {"unit", row.unit},
                                    {"measured", row.measured},
                                    {"predicted", row.predicted}});
    }
  }
  if (band) {
    const auto spread = [](const analysis::Percentiles& p) {
      return nlohmann::json{{"p5", p.p5}, {"p50", p.p50}, {"p95", p.p95}};
    };
    json["band"] = {{"samples", band->samples},
                    {"refused", band->refused},
                    {"contents", band->contents},
                    {"widening", band->widening},
                    {"seed", options.seed.value_or(1)},
                    {"peak_isolator_displacement", spread(band->peak_isolator_displacement)},
                    {"peak_roof_acceleration", spread(band->peak_roof_acceleration)},
                    {"nrmse_isolator_displacement", spread(band->nrmse_isolator_displacement)},
                    {"nrmse_roof_acceleration", spread(band->nrmse_roof_acceleration)},
                    {"coverage",
                     {{"isolator_displacement", band->isolator_coverage},
                      {"roof_acceleration", band->roof_coverage}}},
                    {"peak_inside",
                     {{"isolator_displacement", band->isolator_peak_inside},
                      {"roof_acceleration", band->roof_peak_inside}}}};
  }
  if (options.predict) {
    json["nrmse"] = {{"isolator_displacement", o.prediction->nrmse_isolator_displacement},
                     {"roof_acceleration", o.prediction->nrmse_roof_acceleration}};
    json["results"] = o.results_path;
    json["warnings"] = o.prediction->summary.warnings;
  }
  return json;
}

void PrintShakeTable(const ShakeTableOptions& options, const UnitSystem& units,
                     const ShakeTableOutcome& o, std::ostream& out) {
  const building::LevelMeasurements& m = o.m;
  const std::optional<building::PredictionBand>& band = o.band;
  fmt::print(out,
             "{}: {} samples, {} half-cycles of the isolator; levels (slab to roof) = "
             "channels {}\n{}\n",
             options.data, m.time.size(), o.isolator.half_cycles.size(), fmt::join(m.channels, ","),
             m.reference_note);
  if (band) {
    fmt::print(out, "{}\n",
               building::CoverageSentence(*band, units.length(),
                                          DescribeUnits(units, dimension::kAcceleration)));
  }
  fmt::print(out, "peak isolator displacement {:.4g} {}, peak base shear {:.4g} {} ({:.3g} W)\n",
             building::PeakAbs(m.displacement.front()), units.length(), building::PeakAbs(o.shear),
             units.force(), building::PeakAbs(o.shear) / o.weight);
  if (!options.isolator.empty()) fmt::print(out, "isolator history: {}\n", options.isolator);
  if (!options.record.empty()) fmt::print(out, "table record: {}\n", options.record);
  if (options.predict) {
    fmt::print(out,
               "\n| quantity | measured | predicted | predicted / measured |\n|---|---|---|---|\n");
    for (const building::ComparedPeak& row : o.prediction->peaks) {
      fmt::print(out, "| {} [{}] | {:.4g} | {:.4g} | {:.3f} |\n", row.quantity, row.unit,
                 row.measured, row.predicted, row.predicted / row.measured);
    }
    fmt::print(out, "| NRMSE isolator displacement | | {:.3f} | |\n",
               o.prediction->nrmse_isolator_displacement);
    fmt::print(out, "| NRMSE roof absolute acceleration | | {:.3f} | |\n",
               o.prediction->nrmse_roof_acceleration);
    if (band) {
      const auto row = [&](const char* what, const analysis::Percentiles& p) {
        fmt::print(out, "| {} | {:.4g} | {:.4g} | {:.4g} |\n", what, p.p5, p.p50, p.p95);
      };
      fmt::print(
          out,
          "\n{} parameter sets drawn from the model's uncertainty ({} left out: beyond a "
          "law's rules), seed {}:\n\n| quantity | 5 % | median | 95 % |\n|---|---|---|---|\n",
          band->samples, band->refused, options.seed.value_or(1));
      row("peak isolator displacement", band->peak_isolator_displacement);
      row("peak roof absolute acceleration", band->peak_roof_acceleration);
      row("NRMSE isolator displacement", band->nrmse_isolator_displacement);
      row("NRMSE roof absolute acceleration", band->nrmse_roof_acceleration);
    }
    fmt::print(out, "\nresults: {}\n", o.results_path);
  }
}

}  // namespace

void RunShakeTableCommand(const ShakeTableOptions& options, std::ostream& out) {
  const model::ModelFile model = model::LoadModelFile(options.model);
  // Each option of the prediction is refused without it, as it would be ignored.
  for (const auto& [given, option] : {std::pair{options.samples > 0, "--samples"},
                                      std::pair{!options.results.empty(), "--results"},
                                      std::pair{!options.comparison.empty(), "--comparison"}}) {
    if (given && !options.predict) {
      throw InputError({option}, "belongs to the prediction: give --predict");
    }
  }
  if (options.seed && options.samples == 0) {
    throw InputError({"--seed"}, "seeds the parameter sets --samples draws: give --samples");
  }
  const std::string results_path =
      !options.predict ? std::string()
      : !options.results.empty()
          ? options.results
          : std::filesystem::path(options.data).stem().string() + ".predicted.h5";
  // Every output is checked before the data are read and the prediction runs, not after.
  std::vector<std::string> outputs;
  for (const std::string& path : {options.isolator, options.record, results_path,
                                  options.predict ? options.comparison : std::string()}) {
    if (!path.empty()) outputs.push_back(path);
  }
  std::vector<std::string> inputs = model.included_files;
  inputs.push_back(options.model);
  inputs.push_back(options.data);
  io::CheckOutputs(inputs, outputs);
  if (!results_path.empty()) analysis::CheckResultsPath(results_path);
  const std::vector<double> masses = building::LevelMasses(model);
  const UnitSystem& units = model.units;
  ShakeTableOutcome o;
  o.m = building::ReadShakeTableMeasurements(options.data, options.channels, units, masses.size());
  const building::LevelMeasurements& m = o.m;
  if (!options.quiet) {
    fmt::print(stderr, "isolab shaketable: {} samples, levels (slab to roof) = channels {}; {}\n",
               m.time.size(), fmt::join(m.channels, ","), m.reference_note);
  }
  o.results_path = results_path;
  o.shear = building::BaseShear(m.acceleration, masses);
  identification::CyclicTestData& isolator = o.isolator;
  isolator.name = std::filesystem::path(options.data).stem().string();
  isolator.time = m.time;
  isolator.displacement = m.displacement.front();
  isolator.force = o.shear;
  identification::Segment(&isolator);
  if (isolator.half_cycles.empty()) {
    throw InputError({options.data}, "the isolator never reverses: too short to identify anything");
  }

  // Everything is composed before anything is written.
  std::string record_text;
  if (!options.record.empty()) {
    const double to_si = units.SiFactor(dimension::kAcceleration);
    record_text = "time (s),acceleration (m/s^2)\n";
    for (std::size_t k = 0; k < m.time.size(); ++k) {
      record_text += fmt::format("{:.6f},{:.9g}\n", m.time[k] - m.time.front(),
                                 m.table_acceleration[k] * to_si);
    }
  }

  if (options.predict) {
    analysis::SolveOptions solve;
    solve.analysis = model.analysis;
    solve.results_path = results_path;
    solve.version = ISOLAB_VERSION;
    if (!options.quiet) fmt::print(stderr, "  predicting under the measured table motion\n");
    o.prediction = building::PredictShakeTable(model, m, solve);
  }
  if (options.samples > 0) {
    if (!options.quiet) {
      fmt::print(stderr, "  {} parameter sets drawn from the model's uncertainty\n",
                 options.samples);
    }
    o.band =
        building::PredictBand(model, {isolator.name, m}, options.samples, options.seed.value_or(1));
  }
  double total_mass = 0.0;
  for (const double mass : masses) total_mass += mass;
  o.weight = total_mass * units.Convert(1.0, "g", dimension::kAcceleration);

  if (!options.isolator.empty()) io::WriteCyclicTests(options.isolator, {isolator}, units);
  if (!options.record.empty()) {
    io::WriteTextFileAtomically(options.record, [&](std::ostream& file) { file << record_text; });
  }
  if (!options.comparison.empty() && options.predict) WriteComparison(options.comparison, o);
  // The prediction's warnings (a model beyond the range it was identified on, ...), as `isolab
  // run` prints them; the JSON carries them too.
  if (o.prediction) {
    for (const std::string& warning : o.prediction->summary.warnings) {
      fmt::print(stderr, "isolab: warning: {}\n", warning);
    }
  }
  if (options.json) {
    out << ShakeTableJson(options, units, o).dump(2) << "\n";
    return;
  }
  PrintShakeTable(options, units, o, out);
}

}  // namespace isolab::cli
