// The formats a ResultsWriter writes through (results_file.h has both layouts). Private to io.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "isolab/analysis/result_series.h"
#include "results_writer.h"

namespace isolab::analysis {

class ResultsWriter::Sink {
 public:
  virtual ~Sink() = default;
  // `rows` rows of every series: blocks[s] begins with rows x series[s].width() values,
  // row-major. In a streamed file, fewer rows than a block holds come last, and the block's other
  // rows are zeros.
  virtual void Write(std::span<const std::span<const double>> blocks, std::size_t rows) = 0;
  // Everything but the histories, then the file appears at its path. `run` is complete.
  virtual void Finish(const RunDescription& run) = 0;
};

// True for a .csv path, false for .h5/.hdf5; throws InputError for any other (results_file.h).
bool IsCsvPath(const std::string& path);

// Chunks of `chunk_rows` rows: the writer's block, so that each Write fills whole chunks. The
// datasets' extent is `expected_rows` from the start (Hdf5File::CreateRows), trimmed at Finish
// to the rows written.
std::unique_ptr<ResultsWriter::Sink> OpenHdf5Sink(const std::string& path,
                                                  const std::vector<Series>& series,
                                                  std::size_t chunk_rows,
                                                  std::size_t expected_rows);
std::unique_ptr<ResultsWriter::Sink> OpenCsvSink(const std::string& path,
                                                 const std::vector<Series>& series);

}  // namespace isolab::analysis
