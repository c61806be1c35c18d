#include "isolab/analysis/run_band.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

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
  std::vector<double> isolator, shear, roof, drift;
  for (int s = 0; s < samples; ++s) {
    Summary summary;
    try {
      summary = Solve(options, Prepare(draws.Next(), overrides));
    } catch (const std::exception&) {
      ++band.refused;  // a draw beyond a law's rules (k1 > k0, say) is no building
      continue;
    }
    if (!summary.ok()) {
      ++band.refused;
      continue;
    }
    isolator.push_back(summary.peaks.isolator_displacement.value);
    shear.push_back(summary.peaks.base_shear.value);
    roof.push_back(summary.peaks.roof_absolute_acceleration.value);
    drift.push_back(summary.peaks.story_drift.value);
  }
  band.samples = int(isolator.size());
  if (band.samples < 2) {
    throw InputError({model.path},
                     "fewer than two of the drawn parameter sets make a building that runs to "
                     "the end: the uncertainty is too wide to draw a band");
  }
  band.isolator_displacement = Spread(isolator);
  band.base_shear = Spread(shear);
  band.roof_absolute_acceleration = Spread(roof);
  band.story_drift = Spread(drift);
  return band;
}

nlohmann::json RunBandJson(const RunBand& band, unsigned seed) {
  const auto spread = [](const Percentiles& p) {
    return nlohmann::json{{"p5", p.p5}, {"p50", p.p50}, {"p95", p.p95}};
  };
  return {{"samples", band.samples},
          {"refused", band.refused},
          {"contents", band.contents},
          {"widening", band.widening},
          {"seed", seed},
          {"isolator_displacement", spread(band.isolator_displacement)},
          {"base_shear", spread(band.base_shear)},
          {"roof_absolute_acceleration", spread(band.roof_absolute_acceleration)},
          {"story_drift", spread(band.story_drift)}};
}

void PrintRunBand(const RunBand& band, unsigned seed, const UnitSystem& units, std::ostream& out) {
  fmt::print(out,
             "\nwith {} ({} sets drawn, seed {}; {} left out: a law's rules broken or the run "
             "stopped):\n",
             band.contents, band.samples + band.refused, seed, band.refused);
  fmt::print(out, "{:<34} {:>12} {:>12} {:>12}\n", "peak", "5 %", "50 %", "95 %");
  const auto row = [&](const char* what, const Percentiles& p, const std::string& unit) {
    fmt::print(out, "{:<34} {:>12.5g} {:>12.5g} {:>12.5g} {}\n", what, p.p5, p.p50, p.p95, unit);
  };
  row("isolator displacement", band.isolator_displacement, units.length());
  row("base shear", band.base_shear, units.force());
  row("roof absolute acceleration", band.roof_absolute_acceleration,
      DescribeUnits(units, dimension::kAcceleration));
  row("story drift", band.story_drift, units.length());
}

}  // namespace isolab::analysis
