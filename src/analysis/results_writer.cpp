#include "results_writer.h"

#include <algorithm>

#include "results_sink.h"

namespace isolab::analysis {

ResultsWriter::ResultsWriter(const std::string& path, const RunDescription& run,
                             std::size_t buffer_rows)
    : run_(run) {
  CheckResultsPath(path);
  series_ = ResultSeries(*run.problem, run.selection);
  std::size_t width = 0;
  for (const Series& s : series_) width += s.width();
  buffer_rows_ = buffer_rows > 0 ? buffer_rows
                                 : std::max<std::size_t>(
                                       1, kBufferBytes / (8 * std::max<std::size_t>(width, 1)));
  const int every = std::max(run.selection.every, 1);
  const std::size_t expected_rows = static_cast<std::size_t>(run.problem->grid.steps / every + 1);
  buffer_rows_ = std::min(buffer_rows_, expected_rows);
  for (const Series& s : series_) buffers_.emplace_back(buffer_rows_ * s.width());
  if (IsCsvPath(path)) {
    sink_ = OpenCsvSink(path, series_);
  } else {
    sink_ = OpenHdf5Sink(path, series_, expected_rows);
  }
}

ResultsWriter::~ResultsWriter() = default;

void ResultsWriter::Observe(const integrators::ResponseRow& row) {
  if (row.step % std::max(run_.selection.every, 1) != 0 || series_.empty()) return;
  for (std::size_t s = 0; s < series_.size(); ++s) {
    series_[s].fill(row, buffers_[s].data() + buffered_ * series_[s].width());
  }
  ++rows_;
  if (++buffered_ == buffer_rows_) Flush();
}

void ResultsWriter::Flush() {
  if (buffered_ == 0) return;
  sink_->Write(buffers_, buffered_);
  buffered_ = 0;
}

void ResultsWriter::Finish(const integrators::RunSummary& summary, const ResponsePeaks& peaks) {
  Flush();
  run_.summary = &summary;
  run_.peaks = &peaks;
  sink_->Finish(run_);
}

}  // namespace isolab::analysis
