// What `isolab design` writes beside its runs, and prints: every number of a design
// (study/design.h) in CSV, the report in Markdown, and a terminal summary. Files, in the output
// folder, each written whole or not at all:
//   design.md            the report: target, ELF per bound, the scaled suite, the design values,
//                        the code's checks, and the figures plot_design.py draws
//   design_values.csv    bound,quantity,unit,statistic,value: the ELF and response-history values
//   design_runs.csv      every run: bound, eccentricity case, record, factor, its quantities,
//                        its summary file and the `isolab run` command (from the output folder)
//                        that reproduces it on the case's model written in models/
//   design_spectra.csv   period_s, in_range (1 inside the scaling range), target_g, each record's
//                        scaled spectrum, the suite's mean, from 0.05 s to twice the range's top
// Lengths and forces are in the model's units.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "isolab/model/design_file.h"
#include "isolab/study/design.h"

namespace isolab::study {

// D_TM, the design value (the response history's, not below 0.8 of the ELF's: ASCE 7-16 17.6.3),
// against the displacement capacity of the isolators that share one (bearing_capacity.h); one
// entry, without a capacity, for the isolators whose laws give none.
struct CapacityCheck {
  std::vector<std::string> isolators;
  std::optional<BearingCapacity> capacity;
  double demand = 0.0;  // D_TM (length)
  bool met = false;     // demand <= capacity; false without a capacity
};
std::vector<CapacityCheck> CheckCapacities(const DesignOutcome& outcome);

// `figures`: the report shows the figures plot_design.py draws; without, it says they were not
// drawn.
void WriteDesignFiles(const model::DesignFile& design, const DesignOutcome& outcome,
                      const std::string& output_directory, bool figures);

// The terminal summary: ELF per bound, the suite, the design values and the checks.
std::string DesignSummaryText(const model::DesignFile& design, const DesignOutcome& outcome);

}  // namespace isolab::study
