// What the commands that run a model share: the results path, and the message and exit code of a
// run that stopped early. The text and JSON summaries are analysis::PrintSummary's and
// analysis::RunReport's.
#pragma once

#include <string>

#include "isolab/integrators/response.h"
#include "isolab/model/model_file.h"
#include "run_command.h"

namespace isolab::cli {

// -o, else the model's output.file, else <model stem>.h5.
std::string ChooseResultsPath(const RunOptions& options, const std::string& model_output_file);

// The exit code: 0 when the run completed; 1 when it stopped early, after saying so on stderr.
int ExitCode(const integrators::RunSummary& summary, double dt, const std::string& output);

}  // namespace isolab::cli
