// A run as `isolab run` prints it, for every structure: before the run, what the engineer checks
// first (the records as applied, the model summary, the time grid); after it, the peaks, the
// residual displacement, the energies and the outcome. run_report.h has the same as JSON.
#pragma once

#include <ostream>

#include "isolab/analysis/problem.h"
#include "isolab/analysis/solve.h"

namespace isolab::analysis {

void PrintPreamble(const Problem& problem, std::ostream& out);

void PrintSummary(const Problem& problem, const model::AnalysisSection& analysis,
                  const Summary& summary, std::ostream& out);

// "dt = ..., N steps (... of excitation, then ... of free vibration), D dofs" and a blank line.
void PrintGrid(const integrators::TimeGrid& grid, double excitation_end, double free_vibration,
               int dofs, const UnitSystem& units, std::ostream& out);

// The energy balance error, the integrator's statistics (Newton's iterations and step cuts, or
// IDA's steps, events and Jacobians) and the results path.
void PrintRunOutcome(const model::AnalysisSection& analysis, const integrators::RunSummary& run,
                     const std::string& output, std::ostream& out);

}  // namespace isolab::analysis
