// Runs the integrator a model's analysis section chooses (Newmark or IDA) on a prepared setup, and
// names it with its options for results files and summaries.
#pragma once

#include <string>
#include <vector>

#include "isolab/analysis/analysis_setup.h"
#include "isolab/analysis/response_peaks.h"
#include "isolab/integrators/response.h"
#include "isolab/model/model_file.h"
#include "isolab/model/output_selection.h"

namespace isolab::analysis {

// The observer sees the setup's grid (integrators/response.h).
integrators::RunSummary RunAnalysis(const model::AnalysisSection& analysis,
                                    const AnalysisSetup& setup,
                                    integrators::ResponseObserver& observer);
// The same, keeping the history in memory.
integrators::RunSummary RunAnalysis(const model::AnalysisSection& analysis,
                                    const AnalysisSetup& setup,
                                    integrators::ResponseHistory* response);

// A run as `isolab run` does it, for any caller: peaks, the residual displacement and the
// energies from every step, and, when `results_path` is not empty, the histories `selection`
// records streamed to that file (results_writer.h; bounded memory, the file appears whole at the
// end, also for a run that stopped early). `version` goes into the file.
struct RecordedRun {
  integrators::RunSummary summary;
  ResponsePeaks peaks;
  std::vector<std::string> warnings;  // RunWarnings (results_file.h)
};
RecordedRun RunAndRecord(const model::ModelFile& model, const model::AnalysisSection& analysis,
                         const AnalysisSetup& setup, const model::OutputSelection& selection,
                         const std::string& results_path, const std::string& version,
                         std::size_t buffer_rows = 0);

// e.g. "newmark beta=0.25 gamma=0.5 newton=full ... dt=0.005" or "ida rtol=1e-06 atol=1e-09 ...".
std::string DescribeIntegrator(const model::AnalysisSection& analysis, double dt);

}  // namespace isolab::analysis
