#include "isolab/analysis/prediction_band.h"

#include <algorithm>
#include <cmath>

#include "isolab/core/errors.h"

namespace isolab::analysis {
namespace {

// The 5th and 95th percentiles at every sample of the runs' histories.
void Band(const std::vector<Signal>& runs, Signal* low, Signal* high) {
  const std::size_t n = runs.front().size();
  low->resize(n);
  high->resize(n);
  std::vector<double> at(runs.size());
  for (std::size_t k = 0; k < n; ++k) {
    for (std::size_t r = 0; r < runs.size(); ++r) at[r] = runs[r][k];
    (*low)[k] = Quantile(&at, 0.05);
    (*high)[k] = Quantile(&at, 0.95);
  }
}

}  // namespace

PredictionBand PredictBand(const model::ModelFile& model, const BuildingMotion& motion, int samples,
                           unsigned seed) {
  ParameterDraws draws(model, seed);
  const std::vector<BuildingChannel> channels = {
      {BuildingChannel::Kind::kDisplacement, 1},
      {BuildingChannel::Kind::kAcceleration, int(motion.measured.acceleration.size())}};
  PredictionBand band;
  std::vector<Signal> isolator, roof;
  std::vector<double> peak_u, peak_a, nrmse_u, nrmse_a;
  for (int s = 0; s < samples; ++s) {
    ChannelHistories run;
    try {
      run = SimulateChannels(draws.Next(), {motion}, channels, false, 0.0);
    } catch (const std::exception&) {
      ++band.refused;  // a draw beyond a law's rules (k1 > k0, say) is no building
      continue;
    }
    isolator.push_back(std::move(run[0][0]));
    roof.push_back(std::move(run[0][1]));
    peak_u.push_back(PeakAbs(isolator.back()));
    peak_a.push_back(PeakAbs(roof.back()));
    nrmse_u.push_back(Nrmse(motion.measured.displacement.front(), isolator.back()));
    nrmse_a.push_back(Nrmse(motion.measured.acceleration.back(), roof.back()));
  }
  band.samples = int(isolator.size());
  if (band.samples < 2) {
    throw InputError({model.path},
                     "fewer than two of the drawn parameter sets make a building "
                     "that runs: the uncertainty is too wide to draw a band");
  }
  Band(isolator, &band.isolator_p5, &band.isolator_p95);
  Band(roof, &band.roof_p5, &band.roof_p95);
  band.peak_isolator_displacement = Spread(peak_u);
  band.peak_roof_acceleration = Spread(peak_a);
  band.nrmse_isolator_displacement = Spread(nrmse_u);
  band.nrmse_roof_acceleration = Spread(nrmse_a);
  return band;
}

}  // namespace isolab::analysis
