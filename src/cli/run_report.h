// What `isolab run` does the same for one-direction and plan models: the command line's choice of
// integrator and tolerances, the results path, the outcome's lines of the text summary and the
// message and exit code of a run that stopped early. The JSON summary is analysis::RunReport's.
#pragma once

#include <ostream>
#include <string>

#include "isolab/integrators/response.h"
#include "isolab/model/model_file.h"
#include "run_command.h"

namespace isolab::cli {

// The model's analysis section with --integrator, --rtol and --atol over it.
model::AnalysisSection ChooseIntegrator(const RunOptions& options, model::AnalysisSection analysis);

// -o, else the model's output.file, else <model stem>.h5.
std::string ChooseResultsPath(const RunOptions& options, const std::string& model_output_file);

// "dt = ..., N steps (... of excitation, then ... of free vibration), D dofs" and a blank line.
void PrintGrid(const integrators::TimeGrid& grid, double excitation_end, double free_vibration,
               int dofs, const UnitSystem& units, std::ostream& out);

// The energy balance error, the integrator's statistics (Newton's iterations and step cuts, or
// IDA's steps, events and Jacobians) and the results path.
void PrintRunOutcome(const model::AnalysisSection& analysis, const integrators::RunSummary& summary,
                     const std::string& output, std::ostream& out);

// The exit code: 0 when the run completed; 1 when it stopped early, after saying so on stderr.
int ExitCode(const integrators::RunSummary& summary, double dt, const std::string& output);

}  // namespace isolab::cli
