// A run's summary as data: what `isolab run --json` prints and the Python module's
// Result.summary returns, built once for both (docs/results.md, "JSON summary").
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "isolab/analysis/results_file.h"
#include "isolab/integrators/response.h"
#include "isolab/model/model_file.h"

namespace isolab::analysis {

// The one-direction run: the record as applied, the model summary, the peaks, the energies and
// the outcome (AddRunOutcome). `output`: the results file, "" for none (then no "results" key).
nlohmann::json RunReport(const RunDescription& run, const std::vector<std::string>& warnings,
                         const std::string& output);

// What every run reports, one-direction or plan: termination ("completed" or "failed"), message,
// energy_balance_error, integrator, its statistics ("newton": iterations, solves per step, ...;
// or "ida": steps, events, ...), steps_completed, wall_seconds and results (when `output` is
// not empty).
void AddRunOutcome(const model::AnalysisSection& analysis, double dt,
                   const integrators::RunSummary& summary, const std::string& output,
                   nlohmann::json* json);

}  // namespace isolab::analysis
