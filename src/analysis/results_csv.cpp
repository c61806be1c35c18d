// The CSV results layout (results_file.h): one column per series and column, named with its
// units, after '#' lines describing the run. The rows go to an anonymous temporary file while
// the run advances, and are copied after the header once the summary is known.
#include <fmt/format.h>
#include <fmt/ostream.h>
#include <fmt/ranges.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "isolab/analysis/solve.h"
#include "isolab/analysis/summary_peaks.h"
#include "isolab/core/errors.h"
#include "isolab/io/atomic_file.h"
#include "isolab/io/csv.h"
#include "results_sink.h"

namespace isolab::analysis {
namespace {

void WriteComments(std::ostream& out, const RunDescription& run) {
  const Problem& problem = *run.problem;
  const UnitSystem& units = problem.units();
  const integrators::RunSummary& summary = *run.summary;
  const double g = units.Convert(1.0, "g", dimension::kAcceleration);
  fmt::print(out, "# isolab {} results of {}\n", run.version, problem.model.path);
  fmt::print(out, "# units: force {}, length {}, time {}\n", units.force(), units.length(),
             units.time());
  for (std::size_t i = 0; i < problem.records.size(); ++i) {
    const io::AppliedRecord& r = problem.records[i];
    fmt::print(out,
               "# record{}: {} ({}, units {} from {}, dt {:g} s), {}, PGA {:.6g} {} "
               "({:.4g} g)\n",
               problem.records.size() > 1 ? fmt::format(" h{}", i + 1) : "", r.path, r.format,
               r.units, r.units_source, r.dt, io::DescribeScale(r), r.pga,
               DescribeUnits(units, dimension::kAcceleration), r.pga / g);
  }
  if (const std::optional<double> angle = problem.IncidenceAngle()) {
    fmt::print(out, "# H1 at {:g} degrees from x, H2 at {:g}\n", *angle, *angle + 90.0);
  }
  fmt::print(out, "# integrator: {}\n", DescribeIntegrator(*run.analysis, problem.grid.dt));
  fmt::print(out, "# excitation ends at {:g} {}, then free vibration for {:g} {}\n",
             problem.excitation_end, units.time(), problem.free_vibration, units.time());
  if (problem.layout.isolated()) {
    const ResponsePeaks& peaks = *run.peaks;
    fmt::print(out, "# residual isolator displacement: {:.6g} {} (still oscillating +-{:.3g})\n",
               peaks.residual_isolator_displacement, units.length(), peaks.residual_oscillation);
  }
  const model::OutputSelection& selection = run.selection;
  if (selection.summary_only) {
    fmt::print(out, "# output: summary only (no histories)\n");
  } else {
    fmt::print(out, "# output: every {} steps; quantities: {}; levels: {}\n", selection.every,
               fmt::join(RecordedQuantities(selection), ", "),
               fmt::join(RecordedLevels(selection, problem), ", "));
  }
  const ResponsePeaks& peaks = *run.peaks;
  for (const NamedPeak& p : SummaryPeaks(problem.layout, peaks)) {
    fmt::print(out, "# peak {}: {:.6g} {} at t = {:g} {}\n", p.name, p.peak->value,
               PeakUnit(units, p.dimension), p.peak->time, units.time());
  }
  const integrators::Energies& e = peaks.energies;
  fmt::print(out,
             "# energy at the end [{}*{}]: input {:.6g}, kinetic {:.6g}, damping {:.6g}, "
             "elastic {:.6g}, hysteretic {:.6g}\n",
             units.force(), units.length(), e.input, e.kinetic, e.damping, e.elastic, e.hysteretic);
  fmt::print(out, "# termination: {}{}\n", summary.ok() ? "completed" : "failed",
             summary.message.empty() ? "" : ": " + summary.message);
  fmt::print(out, "# energy balance error: {:.3e} of the input energy\n",
             summary.energy_balance_error);
  for (const std::string& warning : RunWarnings(run)) fmt::print(out, "# warning: {}\n", warning);
}

struct FileCloser {
  void operator()(std::FILE* file) const { std::fclose(file); }
};

class CsvSink final : public ResultsWriter::Sink {
 public:
  CsvSink(const std::string& path, const std::vector<Series>& series)
      : path_(path), series_(series), rows_(std::tmpfile()) {
    if (!rows_) {
      throw ResourceError(path, fmt::format("cannot create a temporary file for the rows ({})",
                                            std::strerror(errno)));
    }
  }

  void Write(std::span<const std::span<const double>> blocks, std::size_t rows) override {
    for (std::size_t r = 0; r < rows; ++r) {
      fields_.clear();
      for (std::size_t s = 0; s < series_.size(); ++s) {
        const std::size_t width = series_[s].width();
        for (std::size_t c = 0; c < width; ++c) {
          fields_.push_back(io::ExactNumber(blocks[s][r * width + c]));
        }
      }
      const std::string line = io::CsvLine(fields_);
      if (std::fwrite(line.data(), 1, line.size(), rows_.get()) != line.size()) {
        throw ResourceError(path_, fmt::format("cannot write the rows to a temporary file ({})",
                                               std::strerror(errno)));
      }
    }
  }

  void Finish(const RunDescription& run) override {
    io::WriteTextFileAtomically(path_, [&](std::ostream& out) {
      WriteComments(out, run);
      if (series_.empty()) return;
      std::vector<std::string> fields;
      for (const Series& s : series_) {
        const std::string units = s.units.empty() ? "" : fmt::format(" [{}]", s.units);
        if (s.columns.empty()) fields.push_back(s.name + units);
        for (const std::string& column : s.columns) {
          fields.push_back(fmt::format("{}/{}{}", s.name, column, units));
        }
      }
      out << io::CsvLine(fields);
      std::rewind(rows_.get());
      char block[1 << 16];
      std::size_t count = 0;
      while ((count = std::fread(block, 1, sizeof block, rows_.get())) > 0) {
        out.write(block, static_cast<std::streamsize>(count));
      }
      if (std::ferror(rows_.get())) {
        throw ResourceError(path_, "cannot read the rows back from their temporary file");
      }
    });
  }

 private:
  std::string path_;
  const std::vector<Series>& series_;
  std::unique_ptr<std::FILE, FileCloser> rows_;
  std::vector<std::string> fields_;
};

}  // namespace

std::unique_ptr<ResultsWriter::Sink> OpenCsvSink(const std::string& path,
                                                 const std::vector<Series>& series) {
  return std::make_unique<CsvSink>(path, series);
}

}  // namespace isolab::analysis
