// A run's summary as data: what `isolab run --json` prints and the Python module's
// Result.summary returns, built once for both and for every structure (docs/results.md, "JSON
// summary").
#pragma once

#include <nlohmann/json.hpp>

#include "isolab/analysis/problem.h"
#include "isolab/analysis/solve.h"
#include "isolab/model/model_file.h"

namespace isolab::analysis {

// The record as applied (H1's at the top level; a pair's H2 under "h2", with the angle), the
// model summary, the peaks (and each isolator's under "isolators"), the energies and the
// outcome: termination ("completed" or "failed"), message, energy_balance_error, integrator,
// its statistics ("newton": iterations, solves per step, ...; or "ida": steps, events, ...),
// steps_completed, wall_seconds and results (when a file was written).
nlohmann::json RunReport(const Problem& problem, const model::AnalysisSection& analysis,
                         const Summary& summary);

}  // namespace isolab::analysis
