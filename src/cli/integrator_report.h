// How a run's integrator statistics are shown, the same for one-direction and plan models: the
// line of the text summary and the block of the JSON summary (Newton's iterations and step cuts,
// or IDA's steps, events and Jacobians).
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>

#include "isolab/integrators/response.h"
#include "isolab/io/model_file.h"

namespace isolab::cli {

void PrintIntegratorStatistics(const io::AnalysisSection& analysis,
                               const integrators::RunSummary& summary, std::ostream& out);

// Sets json["ida"] or json["newton"].
void AddIntegratorStatistics(const io::AnalysisSection& analysis,
                             const integrators::RunSummary& summary, nlohmann::json* json);

}  // namespace isolab::cli
