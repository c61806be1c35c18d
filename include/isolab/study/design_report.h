// What `isolab design` writes beside its runs, and prints: every number of a design
// (study/design.h) in CSV, the report in Markdown, and a terminal summary. Files, in the output
// folder, each written whole or not at all:
//   design.md            the report: target, ELF per bound, the scaled suite, the design values,
//                        the code's checks, and the figures plot_design.py draws
//   design_values.csv    bound,quantity,unit,statistic,value: the ELF and response-history values,
//                        and the code's design values (bound "design", statistic "design")
//   design_checks.csv    check,clause,unit,demand,limit,basis,verdict: the code's checks
//                        (design_checks.h)
//   design_parts.csv     bound,quantity,part,unit,statistic,value: each story's, floor's and
//                        bearing's design values (DesignPartValue), mean and most unfavourable
//   design_bearings.csv  bound,bearing,D_M,k_eff,beta_eff,energy_per_cycle,Qd_equivalent,
//                        Kd_equivalent: each isolator at its bound's D_M (ELF), for another
//                        program's link properties
//   design_runs.csv      every run: bound, eccentricity case, record, factor, its quantities,
//                        its summary file and the `isolab run` command (from the output folder)
//                        that reproduces it on the case's model written in models/
//   design_spectra.csv   period_s, in_range (1 inside the scaling range), target_g, each record's
//                        scaled spectrum, the suite's mean, from 0.05 s to twice the range's top
// Lengths and forces are in the model's units.
#pragma once

#include <string>
#include <vector>

#include "isolab/model/design_file.h"
#include "isolab/study/design.h"

namespace isolab::study {

// `figures`: the report shows the figures plot_design.py draws; without, it says they were not
// drawn.
void WriteDesignFiles(const model::DesignFile& design, const DesignOutcome& outcome,
                      const std::string& output_directory, bool figures);

// The terminal summary: ELF per bound, the suite, the design values and the checks.
std::string DesignSummaryText(const model::DesignFile& design, const DesignOutcome& outcome);

}  // namespace isolab::study
