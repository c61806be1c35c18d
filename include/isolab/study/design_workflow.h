// `isolab design` and Python's `isolab.design` as one sequence: the output folder claimed, the
// design run on local worker processes, its files written, the front's own finishing step (the
// command line's figures) and the folder committed. The fronts parse options and render the
// outcome, nothing else.
#pragma once

#include <functional>
#include <string>

#include "isolab/model/design_file.h"
#include "isolab/study/design.h"

namespace isolab::study {

struct DesignFolderOptions {
  std::string output;         // the folder; empty: the design's own (ClaimDesignFolder)
  std::string output_option;  // how the front names it in messages ("--output", "output")
  int jobs = 0;               // worker processes; 0: every hardware thread
  bool figures = false;       // DesignReport's figures section names the drawn figures
  std::string version;        // isolab's, written into the results
};

struct DesignRun {
  DesignOutcome outcome;
  std::string folder;     // where it was written
  std::string scheduler;  // the workers, as Scheduler::Describe says
  // True when every run completed and the design was committed; false (the earlier design
  // untouched, nothing written) when a run failed: outcome.runs say which.
  bool committed = false;
};

// `finish` runs on the written folder before the commit (may be empty); what it throws rolls the
// design back. Throws InputError for bad input, before any work.
DesignRun RunDesignIntoFolder(const model::DesignFile& design, const DesignFolderOptions& options,
                              const std::function<void(const std::string&)>& progress,
                              const std::function<void(const std::string& folder)>& finish);

}  // namespace isolab::study
