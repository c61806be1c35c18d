// The CSV results layout (results_file.h): one column per series and column, named with its
// units, after '#' lines describing the run.
#include <fmt/format.h>
#include <fmt/ostream.h>

#include "isolab/io/atomic_file.h"
#include "isolab/io/csv.h"
#include "isolab/io/run_analysis.h"
#include "results_writers.h"

namespace isolab::io {
namespace {

void WriteComments(std::ostream& out, const RunDescription& run) {
  const AnalysisSetup& setup = *run.setup;
  const UnitSystem& units = run.model->units;
  const integrators::RunSummary& summary = *run.summary;
  const double g = units.Convert(1.0, "g", dimension::kAcceleration);
  fmt::print(out, "# isolab {} results of {}\n", run.version, run.model->path);
  fmt::print(out, "# units: force {}, length {}, time {}\n", units.force(), units.length(),
             units.time());
  if (!setup.record.path.empty()) {
    const AppliedRecord& r = setup.record;
    fmt::print(out,
               "# record: {} ({}, units {} from {}, dt {:g} s), scale {:g}, PGA {:.6g} {} "
               "({:.4g} g)\n",
               r.path, r.format, r.units, r.units_source, r.dt, r.scale, r.pga,
               DescribeUnits(units, dimension::kAcceleration), r.pga / g);
  }
  fmt::print(out, "# integrator: {}\n", DescribeIntegrator(*run.analysis, setup.grid.dt));
  fmt::print(out, "# excitation ends at {:g} {}, then free vibration for {:g} {}\n",
             setup.excitation_end, units.time(), setup.free_vibration, units.time());
  if (setup.layout.isolation >= 0) {
    const ResponsePeaks& peaks = *run.peaks;
    fmt::print(out, "# residual isolator displacement: {:.6g} {} (still oscillating +-{:.3g})\n",
               peaks.residual_isolator_displacement, units.length(), peaks.residual_oscillation);
  }
  fmt::print(out, "# termination: {}{}\n", summary.ok() ? "completed" : "failed",
             summary.message.empty() ? "" : ": " + summary.message);
  fmt::print(out, "# energy balance error: {:.3e} of the input energy\n",
             summary.energy_balance_error);
  for (const std::string& warning : RunWarnings(run)) fmt::print(out, "# warning: {}\n", warning);
}

}  // namespace

void WriteResultsCsv(const std::string& path, const RunDescription& run) {
  const std::vector<Series> series = ResultSeries(run);
  WriteTextFileAtomically(path, [&](std::ostream& out) {
    WriteComments(out, run);
    std::vector<std::string> fields;
    for (const Series& s : series) {
      const std::string units = s.units.empty() ? "" : fmt::format(" [{}]", s.units);
      if (s.columns.empty()) fields.push_back(s.name + units);
      for (const std::string& column : s.columns) {
        fields.push_back(fmt::format("{}/{}{}", s.name, column, units));
      }
    }
    out << CsvLine(fields);
    std::vector<double> values;
    for (int row = 0; row < run.response->rows_written; ++row) {
      fields.clear();
      for (const Series& s : series) {
        values.resize(s.width());
        s.fill(row, values.data());
        for (const double value : values) fields.push_back(ExactNumber(value));
      }
      out << CsvLine(fields);
    }
  });
}

}  // namespace isolab::io
