// The per-run results files of a study, written away from the runs' computation. A job runs into
// memory (analysis::HeldResultsFile: the histories of one run as the file holds them, no HDF5
// call) and hands the finished run over; the file is then written
// either at once on the job's thread (one thread, MPI ranks) or by writer threads fed by a
// bounded queue (several threads: no job waits for HDF5's global lock while another writes; each
// file is built in memory under the lock and written to disk outside it, io::Hdf5File::Storage,
// so that writers overlap the system's writes).
// Whoever writes it, a file is written by the same code from the same values, so the files are
// byte-identical whatever the thread count. Memory stays bounded: the runs being computed, at
// most `capacity` waiting or being written.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "isolab/analysis/problem.h"
#include "isolab/analysis/response_peaks.h"
#include "isolab/analysis/results_file.h"
#include "isolab/integrators/response.h"
#include "isolab/model/model_file.h"
#include "isolab/model/output_selection.h"

namespace isolab::study {

// A finished run, all its file needs.
struct RunFile {
  std::size_t job = 0;
  std::string path;  // where the file goes (its folder exists)
  std::shared_ptr<const analysis::Problem> problem;
  model::AnalysisSection analysis;
  integrators::RunSummary run;
  analysis::ResponsePeaks peaks;
  model::OutputSelection selection;               // summary_only: no histories
  std::string version;                            // isolab's, written into the file
  std::optional<analysis::HeldResultsFile> held;  // the rows, observed during the run
};

class RunFileWriter {
 public:
  // `writers` threads write the files, with at most `capacity` (>= writers) files waiting or being
  // written; with none, Submit writes the file itself.
  RunFileWriter(std::size_t writers, std::size_t capacity);
  ~RunFileWriter();  // waits for the files submitted (Finish)
  RunFileWriter(const RunFileWriter&) = delete;
  RunFileWriter& operator=(const RunFileWriter&) = delete;

  // Hands the file over. Returns the seconds the caller spent: writing it (not in the background)
  // or waiting for room in the queue. Not in the background, throws InputError when the file
  // cannot be written; in the background such a failure is reported by Finish.
  double Submit(RunFile file);

  // Waits until every submitted file is written; the jobs whose file could not be written, with
  // the reason, in the order they failed.
  std::vector<std::pair<std::size_t, std::string>> Finish();

  // Seconds spent writing files so far (on whichever thread wrote them).
  double writing_seconds() const;

 private:
  void Write(RunFile& file);
  void Loop();

  std::size_t capacity_ = 1;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<RunFile> queue_;
  std::size_t writing_ = 0;  // files taken from the queue, not yet written
  bool stopping_ = false;
  std::vector<std::pair<std::size_t, std::string>> failures_;
  double writing_seconds_ = 0.0;
  std::vector<std::thread> threads_;
};

}  // namespace isolab::study
