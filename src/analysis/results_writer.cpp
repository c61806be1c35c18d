#include "results_writer.h"

#include <algorithm>
#include <numeric>

#include "results_sink.h"

namespace isolab::analysis {

ResultsWriter::ResultsWriter(const std::string& path, const RunDescription& run,
                             std::size_t buffer_rows, Mode mode)
    : run_(run), path_(path), mode_(mode) {
  CheckResultsPath(path);
  series_ = ResultSeries(*run.problem, run.selection);
  for (const Series& s : series_) widths_.push_back(s.width());
  const std::size_t width = std::accumulate(widths_.begin(), widths_.end(), std::size_t{0});
  const std::size_t most_rows =
      buffer_rows > 0
          ? buffer_rows
          : std::max(kMinBufferRows, kBufferBytes / (8 * std::max<std::size_t>(width, 1)));
  every_ = std::max(run.selection.every, 1);
  const std::size_t expected_rows = static_cast<std::size_t>(run.problem->grid.steps / every_ + 1);
  // The blocks are the file's chunks, and HDF5 stores a last partial chunk whole: blocks of
  // equal size that tile the run leave fewer than one row per block unused, where blocks of
  // `most_rows` could leave almost a whole one (10,001 rows in chunks of 8,322 were 40 % padding).
  const std::size_t blocks = (expected_rows + most_rows - 1) / most_rows;
  buffer_rows_ = mode == Mode::kHeld ? expected_rows : (expected_rows + blocks - 1) / blocks;
  for (const std::size_t w : widths_) buffers_.emplace_back(buffer_rows_ * w);
  if (mode_ == Mode::kStreaming) OpenSink();
}

void ResultsWriter::OpenSink() {
  if (IsCsvPath(path_)) {
    sink_ = OpenCsvSink(path_, series_);
  } else if (mode_ == Mode::kHeld) {
    // One chunk per history: the rows held are written whole, in one call each.
    sink_ = OpenHdf5Sink(path_, series_, std::max<std::size_t>(buffered_, 1));
  } else {
    sink_ = OpenHdf5Sink(path_, series_, buffer_rows_);
  }
}

ResultsWriter::~ResultsWriter() = default;

void ResultsWriter::Observe(const integrators::ResponseRow& row) {
  if (row.step % every_ != 0 || series_.empty()) return;
  if (buffered_ == buffer_rows_) {  // held: more rows than the grid's (never with Newmark or IDA)
    buffer_rows_ *= 2;
    for (std::size_t s = 0; s < series_.size(); ++s) {
      buffers_[s].resize(buffer_rows_ * widths_[s]);
    }
  }
  // Locals, since the fill functions are opaque to the compiler: read through `this`, the
  // vectors' bounds and the row would be loaded again after every call.
  const std::size_t count = series_.size(), at = buffered_;
  const Series* series = series_.data();
  Block* buffers = buffers_.data();
  const std::size_t* widths = widths_.data();
  for (std::size_t s = 0; s < count; ++s) series[s].fill(row, buffers[s].data() + at * widths[s]);
  ++rows_;
  if (++buffered_ == buffer_rows_ && mode_ == Mode::kStreaming) Flush();
}

void ResultsWriter::Flush() {
  if (buffered_ == 0) return;
  if (buffered_ < buffer_rows_ && mode_ == Mode::kStreaming) {
    // The last block, part-filled: its chunk goes to the file whole, padded with zeros.
    for (std::size_t s = 0; s < series_.size(); ++s) {
      std::fill(buffers_[s].begin() + static_cast<std::ptrdiff_t>(buffered_ * widths_[s]),
                buffers_[s].end(), 0.0);
    }
  }
  sink_->Write(buffers_, buffered_);
  buffered_ = 0;
}

void ResultsWriter::Finish(const integrators::RunSummary& summary, const ResponsePeaks& peaks) {
  RunDescription run = run_;
  run.summary = &summary;
  run.peaks = &peaks;
  Finish(run);
}

void ResultsWriter::Finish(const RunDescription& run) {
  run_ = run;
  if (!sink_) OpenSink();
  Flush();
  sink_->Finish(run_);
}

}  // namespace isolab::analysis
