#include "results_writer.h"

#include <algorithm>

#include "results_sink.h"
#include "row_stage.h"

namespace isolab::analysis {

ResultsWriter::ResultsWriter(const std::string& path, const RunDescription& run,
                             std::size_t buffer_rows, Mode mode)
    : run_(run), path_(path), mode_(mode) {
  CheckResultsPath(path);
  series_ = ResultSeries(*run.problem, run.selection);
  std::size_t width = 0;
  for (const Series& s : series_) width += s.width();
  const std::size_t most_rows =
      buffer_rows > 0
          ? buffer_rows
          : std::max(kMinBufferRows, kBufferBytes / (8 * std::max<std::size_t>(width, 1)));
  every_ = std::max(run.selection.every, 1);
  expected_rows_ = static_cast<std::size_t>(run.problem->grid.steps / every_ + 1);
  // The blocks are the file's chunks, and HDF5 stores a last partial chunk whole: blocks of
  // equal size that tile the run leave fewer than one row per block unused, where blocks of
  // `most_rows` could leave almost a whole one (10,001 rows in chunks of 8,322 were 40 % padding).
  const std::size_t blocks = (expected_rows_ + most_rows - 1) / most_rows;
  buffer_rows_ = mode == Mode::kHeld ? expected_rows_ : (expected_rows_ + blocks - 1) / blocks;
  stage_ = std::make_unique<RowStage>(series_, run.problem->structure, buffer_rows_);
  blocks_.resize(series_.size());
  if (mode_ == Mode::kStreaming) OpenSink();
}

void ResultsWriter::OpenSink() {
  if (IsCsvPath(path_)) {
    sink_ = OpenCsvSink(path_, series_);
  } else if (mode_ == Mode::kHeld) {
    // One chunk per history: the rows held are written whole, in one call each.
    sink_ = OpenHdf5Sink(path_, series_, std::max<std::size_t>(buffered_, 1), buffered_);
  } else {
    sink_ = OpenHdf5Sink(path_, series_, buffer_rows_, expected_rows_);
  }
}

ResultsWriter::~ResultsWriter() = default;

void ResultsWriter::Observe(const integrators::ResponseRow& row) {
  if (row.step % every_ != 0 || series_.empty()) return;
  if (buffered_ == buffer_rows_) {  // held: more rows than the grid's (never with Newmark or IDA)
    buffer_rows_ *= 2;
    stage_->Resize(buffer_rows_);
  }
  stage_->Keep(row, buffered_);
  ++rows_;
  if (++buffered_ == buffer_rows_ && mode_ == Mode::kStreaming) Flush();
}

void ResultsWriter::Flush() {
  if (buffered_ == 0) return;
  stage_->Gather(buffered_);
  // The last block, part-filled: its chunk goes to the file whole, padded with zeros.
  if (buffered_ < buffer_rows_ && mode_ == Mode::kStreaming) stage_->Pad(buffered_);
  for (std::size_t s = 0; s < series_.size(); ++s) blocks_[s] = stage_->Rows(s);
  sink_->Write(blocks_, buffered_);
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
