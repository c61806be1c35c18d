// Runs the integrator a model's analysis section chooses (Newmark or IDA) on a prepared setup, and
// names it with its options for results files and summaries.
#pragma once

#include <string>

#include "isolab/integrators/response.h"
#include "isolab/io/analysis_setup.h"
#include "isolab/io/model_file.h"

namespace isolab::io {

integrators::RunSummary RunAnalysis(const AnalysisSection& analysis, const AnalysisSetup& setup,
                                    integrators::ResponseHistory* response);

// e.g. "newmark beta=0.25 gamma=0.5 newton=full ... dt=0.005" or "ida rtol=1e-06 atol=1e-09 ...".
std::string DescribeIntegrator(const AnalysisSection& analysis, double dt);

}  // namespace isolab::io
