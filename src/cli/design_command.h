// `isolab design`: an isolated building designed as ASCE 7-16 chapter 17 asks, from a design file
// (include/isolab/model/design_file.h): bound models, the ELF procedure, a suite scaled to the
// target spectrum, every bound x eccentricity case x record on local worker processes, the design
// values and the code's checks; the report, its figures (scripts/plot_design.py) and CSV files in
// the output folder (study/design.h, study/design_report.h).
#pragma once

#include <ostream>
#include <string>

namespace CLI {
class App;
}

namespace isolab::cli {

struct DesignOptions {
  std::string design;
  std::string output;  // folder; default: the design's output.directory, else its file stem
  int jobs = 0;        // threads; 0: every hardware thread
  bool quiet = false;
  bool figures = true;  // plot_design.py after the runs
};

void RegisterDesignCommand(CLI::App& app, DesignOptions& options);

// Returns 0 when every run completed, 1 when any failed (their messages on stderr, no design
// values written). Throws InputError for a bad design file or option, and under mpirun.
int RunDesignCommand(const DesignOptions& options, std::ostream& out);

}  // namespace isolab::cli
