#include "shaketable_command.h"

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numeric>
#include <optional>
#include <sstream>

#include "building_measurement.h"
#include "isolab/analysis/analysis_setup.h"
#include "isolab/analysis/response_peaks.h"
#include "isolab/analysis/results_file.h"
#include "isolab/analysis/run_analysis.h"
#include "isolab/core/errors.h"
#include "isolab/io/atomic_file.h"
#include "isolab/io/cyclic_test_file.h"
#include "isolab/io/output_check.h"
#include "isolab/model/model_file.h"

namespace isolab::cli {
namespace {

// The prediction sampled at the measured times (linear between output rows).
Series AtTimes(const std::vector<double>& time, const integrators::RowMatrix& columns, int column,
               const Series& at, int rows) {
  Series out(at.size());
  std::size_t j = 0;
  for (std::size_t k = 0; k < at.size(); ++k) {
    while (j + 2 < static_cast<std::size_t>(rows) && time[j + 1] < at[k]) ++j;
    const double t0 = time[j], t1 = time[std::min<std::size_t>(j + 1, rows - 1)];
    const double w = t1 > t0 ? std::clamp((at[k] - t0) / (t1 - t0), 0.0, 1.0) : 0.0;
    out[k] =
        (1 - w) * columns(j, column) + w * columns(std::min<std::size_t>(j + 1, rows - 1), column);
  }
  return out;
}

struct Row {
  std::string quantity, unit;
  double measured = 0.0, predicted = 0.0;
};

}  // namespace

void RegisterShakeTableCommand(CLI::App& app, ShakeTableOptions& options) {
  CLI::App* command = app.add_subcommand(
      "shaketable",
      "Shake-table measurements of an isolated building: the isolator's measured history, the "
      "table record, and the model's prediction against the measurements");
  command->add_option("data", options.data, "Shake-table CSV (named columns with units)")
      ->required()
      ->check(CLI::ExistingFile);
  command
      ->add_option("--model", options.model,
                   "Building model: shear_building with base_mass (floor masses); its "
                   "isolation and damping for --predict")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--levels", options.levels,
                      "Channel numbers from the isolation slab to the roof, e.g. 6,5,4,3,2,1; "
                      "auto: by RMS displacement relative to the table (default)");
  command
      ->add_option("--displacements", options.displacements,
                   "Floor displacements relative to the table, absolute, or auto (default: "
                   "decided from the data)")
      ->check(CLI::IsMember({"auto", "relative", "absolute"}));
  command
      ->add_option("--offsets", options.offsets,
                   "Accelerometer offsets: pre-event (each channel less its mean before the "
                   "table moves; default) or none")
      ->check(CLI::IsMember({"pre-event", "none"}));
  command->add_option("--acceleration-prefix", options.acceleration_prefix,
                      "Floor acceleration channels are PREFIX<n> (default a)");
  command->add_option("--displacement-prefix", options.displacement_prefix,
                      "Floor displacement channels are PREFIX<n> (default d)");
  command->add_option("--isolator", options.isolator,
                      "Write the isolator's history as cyclic-test CSV (for fit and diagnose)");
  command->add_option("--record", options.record,
                      "Write the table acceleration as a record CSV (for isolab run --record)");
  command->add_flag("--predict", options.predict,
                    "Run the model under the measured table acceleration and compare");
  command->add_option("--results", options.results, "HDF5 results of the prediction");
  command->add_option("--comparison", options.comparison,
                      "CSV of measured and predicted histories (for the overlay plot)");
  command->add_flag("--json", options.json, "Print the summary as JSON");
  command->add_flag("-q,--quiet", options.quiet, "No progress on stderr");
}

void RunShakeTableCommand(const ShakeTableOptions& options, std::ostream& out) {
  const model::ModelFile model = model::LoadModelFile(options.model);
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
  const std::vector<double> masses = LevelMasses(model);
  const UnitSystem& units = model.units;
  const Measured m = ReadMeasured(options, units, masses.size());
  if (!options.quiet) {
    fmt::print(stderr, "isolab shaketable: {} samples, levels (slab to roof) = channels {}; {}\n",
               m.time.size(), fmt::join(m.channels, ","), m.reference_note);
  }
  const Series shear = BaseShear(m.acceleration, masses);
  identification::CyclicTestData isolator;
  isolator.name = std::filesystem::path(options.data).stem().string();
  isolator.time = m.time;
  isolator.displacement = m.displacement.front();
  isolator.force = shear;
  identification::Segment(&isolator);
  if (isolator.half_cycles.empty()) {
    throw InputError({options.data}, "the isolator never reverses: too short to identify anything");
  }

  // Everything is composed before anything is written.
  std::string record_text;
  if (!options.record.empty() || options.predict) {
    const double to_si = units.SiFactor(dimension::kAcceleration);
    record_text = "time (s),acceleration (m/s^2)\n";
    for (std::size_t k = 0; k < m.time.size(); ++k) {
      record_text += fmt::format("{:.6f},{:.9g}\n", m.time[k] - m.time.front(),
                                 m.table_acceleration[k] * to_si);
    }
  }

  std::vector<Row> rows;
  Series predicted_u, predicted_roof, predicted_shear;
  if (options.predict) {
    const std::string record_path =
        !options.record.empty() ? options.record
                                : (std::filesystem::temp_directory_path() /
                                   fmt::format("isolab_shaketable_{}.record.csv", ::getpid()))
                                      .string();
    io::WriteTextFileAtomically(record_path, [&](std::ostream& o) { o << record_text; });
    std::optional<analysis::AnalysisSetup> prepared;
    integrators::ResponseHistory response;
    integrators::RunSummary summary;
    try {
      analysis::RunOverrides overrides;
      overrides.record = record_path;
      overrides.scale = 1.0;
      prepared.emplace(analysis::PrepareAnalysis(model, overrides));
      const analysis::AnalysisSetup& setup = *prepared;
      if (setup.layout.isolation < 0) {
        throw InputError({options.model}, "--predict needs an isolation layer in the model");
      }
      if (!options.quiet) {
        fmt::print(stderr, "  predicting: {} steps of {} s\n", setup.grid.steps, setup.grid.dt);
      }
      summary = analysis::RunAnalysis(model.analysis, setup, &response);
    } catch (...) {
      if (options.record.empty()) std::filesystem::remove(record_path);
      throw;
    }
    if (options.record.empty()) std::filesystem::remove(record_path);
    if (!summary.ok()) throw std::runtime_error("the prediction stopped: " + summary.message);
    Series at(m.time.size());
    for (std::size_t k = 0; k < at.size(); ++k) at[k] = m.time[k] - m.time.front();
    const int rows_written = response.rows_written;
    predicted_u = AtTimes(response.time, response.displacement, 0, at, rows_written);
    const int roof = static_cast<int>(masses.size()) - 1;
    predicted_roof = AtTimes(response.time, response.absolute_acceleration, roof, at, rows_written);
    std::vector<Series> predicted_a;
    for (int l = 0; l <= roof; ++l) {
      predicted_a.push_back(
          AtTimes(response.time, response.absolute_acceleration, l, at, rows_written));
    }
    predicted_shear = BaseShear(predicted_a, masses);
    const std::string length = units.length(), force = units.force();
    const std::string acceleration = DescribeUnits(units, dimension::kAcceleration);
    rows = {
        {"peak isolator displacement", length, PeakAbs(m.displacement.front()),
         PeakAbs(predicted_u)},
        {"peak base shear", force, PeakAbs(shear), PeakAbs(predicted_shear)},
        {"peak roof absolute acceleration", acceleration, PeakAbs(m.acceleration.back()),
         PeakAbs(predicted_roof)},
    };
    const analysis::ResponsePeaks peaks = analysis::ComputePeaks(*prepared, response);
    analysis::WriteResultsFile(
        results_path, {&model, &*prepared, &model.analysis, &summary, &peaks, ISOLAB_VERSION, {}},
        response);
  }
  const double nrmse_u = options.predict ? Nrmse(m.displacement.front(), predicted_u) : 0.0;
  const double nrmse_roof = options.predict ? Nrmse(m.acceleration.back(), predicted_roof) : 0.0;
  double total_mass = 0.0;
  for (const double mass : masses) total_mass += mass;
  const double weight = total_mass * units.Convert(1.0, "g", dimension::kAcceleration);

  if (!options.isolator.empty()) io::WriteCyclicTests(options.isolator, {isolator}, units);
  if (!options.record.empty() && !options.predict) {
    io::WriteTextFileAtomically(options.record, [&](std::ostream& o) { o << record_text; });
  }
  if (!options.comparison.empty() && options.predict) {
    io::WriteTextFileAtomically(options.comparison, [&](std::ostream& o) {
      fmt::print(o,
                 "time_s,isolator_displacement_measured,isolator_displacement_predicted,"
                 "base_shear_measured,base_shear_predicted,roof_acceleration_measured,"
                 "roof_acceleration_predicted\n");
      for (std::size_t k = 0; k < m.time.size(); ++k) {
        fmt::print(o, "{:.4f},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}\n", m.time[k],
                   m.displacement.front()[k], predicted_u[k], shear[k], predicted_shear[k],
                   m.acceleration.back()[k], predicted_roof[k]);
      }
    });
  }

  if (options.json) {
    nlohmann::json json;
    json["data"] = options.data;
    json["model"] = options.model;
    json["levels"] = m.channels;
    json["displacement_reference"] = m.reference_note;
    json["samples"] = m.time.size();
    json["half_cycles"] = isolator.half_cycles.size();
    json["weight"] = weight;
    json["units"] = {{"force", units.force()}, {"length", units.length()}, {"time", units.time()}};
    for (const Row& row : rows) {
      json["comparison"].push_back({{"quantity", row.quantity},
                                    {"unit", row.unit},
                                    {"measured", row.measured},
                                    {"predicted", row.predicted}});
    }
    if (options.predict) {
      json["nrmse"] = {{"isolator_displacement", nrmse_u}, {"roof_acceleration", nrmse_roof}};
      json["results"] = results_path;
    }
    out << json.dump(2) << "\n";
    return;
  }
  fmt::print(out,
             "{}: {} samples, {} half-cycles of the isolator; levels (slab to roof) = "
             "channels {}\n{}\n",
             options.data, m.time.size(), isolator.half_cycles.size(), fmt::join(m.channels, ","),
             m.reference_note);
  fmt::print(out, "peak isolator displacement {:.4g} {}, peak base shear {:.4g} {} ({:.3g} W)\n",
             PeakAbs(m.displacement.front()), units.length(), PeakAbs(shear), units.force(),
             PeakAbs(shear) / weight);
  if (!options.isolator.empty()) fmt::print(out, "isolator history: {}\n", options.isolator);
  if (!options.record.empty()) fmt::print(out, "table record: {}\n", options.record);
  if (options.predict) {
    fmt::print(out,
               "\n| quantity | measured | predicted | predicted / measured |\n|---|---|---|---|\n");
    for (const Row& row : rows) {
      fmt::print(out, "| {} [{}] | {:.4g} | {:.4g} | {:.3f} |\n", row.quantity, row.unit,
                 row.measured, row.predicted, row.predicted / row.measured);
    }
    fmt::print(out, "| NRMSE isolator displacement | | {:.3f} | |\n", nrmse_u);
    fmt::print(out, "| NRMSE roof absolute acceleration | | {:.3f} | |\n", nrmse_roof);
    fmt::print(out, "\nresults: {}\n", results_path);
  }
}

}  // namespace isolab::cli
