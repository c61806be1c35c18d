// Runs the integrator a model's analysis section chooses (Newmark or IDA) on a prepared setup, and
// names it with its options for results files and summaries.
#pragma once

#include <string>
#include <vector>

#include "isolab/integrators/response.h"
#include "isolab/io/analysis_setup.h"
#include "isolab/io/model_file.h"
#include "isolab/io/output_selection.h"
#include "isolab/io/response_peaks.h"

namespace isolab::io {

// The observer sees the setup's grid (integrators/response.h).
integrators::RunSummary RunAnalysis(const AnalysisSection& analysis, const AnalysisSetup& setup,
                                    integrators::ResponseObserver& observer);
// The same, keeping the history in memory.
integrators::RunSummary RunAnalysis(const AnalysisSection& analysis, const AnalysisSetup& setup,
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
RecordedRun RunAndRecord(const ModelFile& model, const AnalysisSection& analysis,
                         const AnalysisSetup& setup, const OutputSelection& selection,
                         const std::string& results_path, const std::string& version,
                         std::size_t buffer_rows = 0);

// e.g. "newmark beta=0.25 gamma=0.5 newton=full ... dt=0.005" or "ida rtol=1e-06 atol=1e-09 ...".
std::string DescribeIntegrator(const AnalysisSection& analysis, double dt);

}  // namespace isolab::io
