// A results file written while the run advances: a ResponseObserver that keeps every N-th row of
// the selected series (output_selection.h) in a bounded buffer (row_stage.h: the row's arrays
// staged as they come, the series gathered from them a block at a time) and writes it out
// whenever the buffer fills (HDF5: appended to chunked datasets whose chunks are the buffer's
// rows, so that each write is one call per series of whole new chunks, neither filled first nor
// read back; CSV: to an anonymous temporary file, since its header comes before the rows). Memory
// stays the buffer's whatever the record's length or the building's size. Finish writes the summary
// and makes the file appear at once (atomic_file.h); a writer destroyed without Finish leaves
// nothing behind.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "isolab/analysis/results_file.h"
#include "isolab/integrators/response.h"

namespace isolab::analysis {

struct Series;  // one history of the file (private to the writers)
class RowStage;

class ResultsWriter final : public integrators::ResponseObserver {
 public:
  // Rows buffered when none are asked for: as many rows of the series as fit in kBufferBytes, at
  // least kMinBufferRows. Each block costs a call into HDF5 and a write per series (some 4,000
  // instructions and a system call); each page of the buffer costs a page fault once per run
  // (2.4 us each on a 2-core VM: a 4 MiB buffer was 0.15 us of a five-story step of 1 us). On
  // that VM (1 MiB of L2 cache a core) recording every history of the five-story building cost
  // 1.45-1.58 times the kernel's write of the file's bytes with 512 KiB, 1.36-1.53 with 1 MiB
  // (docs/benchmarks.md). A block is its series' chunks: at 1 MiB, a chunk of a series of up to
  // 2,048 columns fits the 1 MiB chunk cache HDF5 gives a reader by default.
  static constexpr std::size_t kBufferBytes = std::size_t{1} << 20;
  static constexpr std::size_t kMinBufferRows = 64;

  // kStreaming: the file is created at once and written block by block as the run goes.
  // kHeld: every row stays in the buffer (grown as needed: the histories of one run, as compact
  // as the file holds them), nothing is created before Finish, which writes each history as one
  // chunk, straight from the buffer. For a run whose file is written after it (a study's runs) or
  // from rows already in memory.
  enum class Mode { kStreaming, kHeld };

  // For `path` (its extension chooses the format, results_file.h), under a temporary name, for
  // the run `run` describes (its summary and peaks are not read), recording run.selection.
  // Throws InputError for a bad path or a level the structure does not have.
  ResultsWriter(const std::string& path, const RunDescription& run, std::size_t buffer_rows = 0,
                Mode mode = Mode::kStreaming);
  ~ResultsWriter() override;
  ResultsWriter(const ResultsWriter&) = delete;
  ResultsWriter& operator=(const ResultsWriter&) = delete;

  // Keeps the row if its step is a multiple of run.selection.every.
  void Observe(const integrators::ResponseRow& row) override;
  // Writes what is buffered, the summary, peaks and attributes, and renames the file to its path.
  // Throws InputError when the file cannot be written.
  void Finish(const integrators::RunSummary& summary, const ResponsePeaks& peaks);
  // The same for a description of the whole run (its summary and peaks, and what else it points
  // to, replace those given at construction, which need not live until then).
  void Finish(const RunDescription& run);

  // The rows written so far (and buffered), and the rows the buffer holds.
  int rows() const { return rows_; }
  std::size_t buffer_rows() const { return buffer_rows_; }

  class Sink;  // the format (results_sink.h)

  // Values left unset when a block is sized: every value is written (Observe) before it is read,
  // and a held run's rows are megabytes that zeroing would only touch twice.
  template <class T>
  struct UnsetAllocator : std::allocator<T> {
    template <class U>
    struct rebind {
      using other = UnsetAllocator<U>;
    };
    UnsetAllocator() = default;
    template <class U>
    UnsetAllocator(const UnsetAllocator<U>&) noexcept {}
    // Default-initialisation; any other construction is std::construct_at's.
    template <class U>
    void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
      ::new (static_cast<void*>(p)) U;
    }
  };
  using Block = std::vector<double, UnsetAllocator<double>>;

 private:
  void Flush();
  void OpenSink();

  RunDescription run_;
  std::string path_;
  Mode mode_ = Mode::kStreaming;
  std::vector<Series> series_;
  std::unique_ptr<RowStage> stage_;              // reads series_
  std::vector<std::span<const double>> blocks_;  // per series, for the sink: its rows
  int every_ = 1;                                // run.selection.every, at least 1
  std::unique_ptr<Sink> sink_;
  std::size_t expected_rows_ = 0;  // the grid's output rows
  std::size_t buffer_rows_ = 0;
  std::size_t buffered_ = 0;
  int rows_ = 0;
};

}  // namespace isolab::analysis
