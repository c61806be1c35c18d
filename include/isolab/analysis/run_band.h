// A run of a fitted model with its parameters' uncertainty (`isolab run --samples N`): the model
// run again for parameter sets drawn from the uncertainty its fit reported (parameter_draws.h),
// under the same excitation and integrator, and the spread of the peaks an engineer designs with.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>

#include "isolab/analysis/parameter_draws.h"
#include "isolab/analysis/problem.h"
#include "isolab/analysis/solve.h"
#include "isolab/analysis/summary_peaks.h"

namespace isolab::analysis {

// One summary peak's spread over the draws.
struct BandPeak {
  const char* name;   // SummaryPeaks' (JSON's key)
  const char* label;  // SummaryPeaks' text label
  Dimension dimension;
  Percentiles spread;
};

struct RunBand {
  int samples = 0;  // parameter sets run to the end
  int refused = 0;  // drawn sets that broke a law's rules or whose run stopped early, left out
  double widening = 1.0;        // beyond the identified range (BandWidening); 1 within it
  std::string contents;         // what the draws hold (BandContents)
  std::vector<BandPeak> peaks;  // every peak of the run's summary (SummaryPeaks), in its order
};

// Checks that the model can be drawn from (ParameterDraws' InputError), before any run.
void CheckRunBand(const model::ModelFile& model);

// Runs `samples` (>= 2) drawn parameter sets with `seed`, each prepared with `overrides` and
// solved with `analysis`, no results file. Throws InputError as ParameterDraws does, and when
// fewer than two drawn sets run to the end.
RunBand PredictRunBand(const model::ModelFile& model, const RunOverrides& overrides,
                       const model::AnalysisSection& analysis, int samples, unsigned seed);

// `isolab run --json`'s "band" object, and the text table `isolab run` prints after the peaks.
nlohmann::json RunBandJson(const RunBand& band, unsigned seed);
void PrintRunBand(const RunBand& band, unsigned seed, const UnitSystem& units, std::ostream& out);

}  // namespace isolab::analysis
