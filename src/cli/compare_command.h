// `isolab compare`: a study's isolator variants under a suite of records and scale factors, on
// local worker processes or, under mpirun, on MPI ranks; per-run HDF5 results, and a summary (CSV,
// HDF5 and a terminal table) of the compared quantities with their statistics over records and
// ratios to a reference variant. See include/isolab/model/study_file.h for the study file.
#pragma once

#include <ostream>
#include <string>

namespace CLI {
class App;
}

namespace isolab::cli {

struct CompareOptions {
  std::string study;
  std::string output;          // folder; default: the study's output.directory, else its file stem
  int jobs = 0;                // threads without mpirun; 0: every hardware thread
  bool quiet = false;          // no progress on stderr
  bool plot = false;           // bar charts by scripts/plot_study.py after the summary
  std::string free_vibration;  // "auto" or a time (s) after each record; empty: the study's
  std::string runs;            // "none", "summary" or "full"; empty: the study's output.runs
};

void RegisterCompareCommand(CLI::App& app, CompareOptions& options);

// Returns the exit code: 0 when every run completed, 1 when any failed (the summary is still
// written, with the failed runs and their messages); under mpirun, rank 0's (the others return
// 0, mpirun returns rank 0's). Throws InputError for a bad study (on ranks other than 0 it
// returns 2 silently, so the message appears once).
int RunCompareCommand(const CompareOptions& options, std::ostream& out);

}  // namespace isolab::cli
