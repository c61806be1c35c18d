// The files a diagnosis writes, for cyclic tests and buildings alike (private to the cli):
// STEM.md, STEM.json, STEM.model.yaml, STEM.residual.csv and its plot STEM.residual.png.
#pragma once

#include <string>
#include <vector>

#include "isolab/diagnosis/report.h"

namespace isolab::cli {

struct DiagnosisFiles {
  std::string stem;
  bool plot = false;  // asked for, and matplotlib is there (else a note says why not)
  std::vector<std::string> outputs;

  // STEM from --out or the first data file; the plot only where asked and possible (a note in
  // `context` otherwise). Fills the context's model and residual file names.
  static DiagnosisFiles Plan(const std::string& out, const std::string& first_data, bool plot,
                             diagnosis::ReportContext* context);
  // Writes the residual CSV, the JSON (given: callers may add to it), the Markdown and the plot.
  void Write(const diagnosis::DiagnosisReport& report, const std::string& json,
             const std::string& plot_title, bool quiet) const;
  // The summary's last line: where everything went.
  std::string Where(const diagnosis::ReportContext& context) const;
};

}  // namespace isolab::cli
