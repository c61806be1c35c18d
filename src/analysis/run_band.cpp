#include "isolab/analysis/run_band.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <string_view>

#include "isolab/core/errors.h"

namespace isolab::analysis {

void CheckRunBand(const model::ModelFile& model) { ParameterDraws(model, 0); }

RunBand PredictRunBand(const model::ModelFile& model, const RunOverrides& overrides,
                       const model::AnalysisSection& analysis, int samples, unsigned seed) {
  SolveOptions options;
  options.analysis = analysis;
  options.output.summary_only = true;
  RunBand band;
  if (model.identified_range) {  // how far the model's own run goes past it (parameter_draws.h)
    const Summary own = Solve(options, Prepare(model, overrides));
    // A run that stopped early has no peaks to go by; the run itself says why.
    if (own.ok()) {
      band.widening = BandWidening(model, own.peaks.isolator_displacement.value,
                                   own.peaks.isolator_velocity.value);
    }
  }
  ParameterDraws draws(model, seed, band.widening);
  band.contents = BandContents(model, band.widening);
  // Per summary peak, its value in each draw that ran to the end.
  std::vector<std::vector<double>> values;
  for (int s = 0; s < samples; ++s) {
    Summary summary;
    std::vector<NamedPeak> peaks;
    try {
      const Problem problem = Prepare(draws.Next(), overrides);
      summary = Solve(options, problem);
      peaks = SummaryPeaks(problem.layout, summary.peaks);
    } catch (const std::exception&) {
      ++band.refused;  // a draw beyond a law's rules (k1 > k0, say) is no building
      continue;
    }
    if (!summary.ok()) {
      ++band.refused;
      continue;
    }
    if (band.peaks.empty()) {
      for (const NamedPeak& peak : peaks) {
        band.peaks.push_back({peak.name, peak.label, peak.dimension, {}});
      }
      values.resize(peaks.size());
    }
    for (std::size_t p = 0; p < peaks.size(); ++p) values[p].push_back(peaks[p].peak->value);
  }
  band.samples = values.empty() ? 0 : static_cast<int>(values.front().size());
  if (band.samples < 2) {
    throw InputError({model.path},
                     "fewer than two of the drawn parameter sets make a building that runs to "
                     "the end: the uncertainty is too wide to draw a band");
  }
  for (std::size_t p = 0; p < values.size(); ++p) band.peaks[p].spread = Spread(values[p]);
  return band;
}

nlohmann::json RunBandJson(const RunBand& band, unsigned seed) {
  const auto spread = [](const Percentiles& p) {
    return nlohmann::json{{"p5", p.p5}, {"p50", p.p50}, {"p95", p.p95}};
  };
  nlohmann::json json{{"samples", band.samples},
                      {"refused", band.refused},
                      {"contents", band.contents},
                      {"widening", band.widening},
                      {"seed", seed}};
  for (const BandPeak& peak : band.peaks) json[peak.name] = spread(peak.spread);
  return json;
}

void PrintRunBand(const RunBand& band, unsigned seed, const UnitSystem& units, std::ostream& out) {
  fmt::print(out,
             "\nwith {} ({} sets drawn, seed {}; {} left out: a law's rules broken or the run "
             "stopped):\n",
             band.contents, band.samples + band.refused, seed, band.refused);
  fmt::print(out, "{:<34} {:>12} {:>12} {:>12}\n", "peak", "5 %", "50 %", "95 %");
  for (const BandPeak& peak : band.peaks) {
    // The table's column says "peak": the label without it.
    std::string_view what = peak.label;
    if (what.starts_with("peak ")) what.remove_prefix(5);
    fmt::print(out, "{:<34} {:>12.5g} {:>12.5g} {:>12.5g} {}\n", what, peak.spread.p5,
               peak.spread.p50, peak.spread.p95, PeakUnit(units, peak.dimension));
  }
}

}  // namespace isolab::analysis
