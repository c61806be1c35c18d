#include "isolab/building/prediction_band.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "isolab/building/shake_table_prediction.h"
#include "isolab/core/errors.h"

namespace isolab::building {
namespace {

// The 5th and 95th percentiles at every sample of the runs' histories.
void Band(const std::vector<Signal>& runs, Signal* low, Signal* high) {
  const std::size_t n = runs.front().size();
  low->resize(n);
  high->resize(n);
  std::vector<double> at(runs.size());
  for (std::size_t k = 0; k < n; ++k) {
    for (std::size_t r = 0; r < runs.size(); ++r) at[r] = runs[r][k];
    (*low)[k] = analysis::Quantile(&at, 0.05);
    (*high)[k] = analysis::Quantile(&at, 0.95);
  }
}

// The peak |u| and |du/dt| of the isolator's displacement history, the rate by backward
// differences, as the identified range reads the data's (identification::RangeOf).
std::pair<double, double> Peaks(const Signal& u, const Signal& time) {
  double velocity = 0.0;
  for (std::size_t k = 1; k < u.size(); ++k) {
    velocity = std::max(velocity, std::abs(u[k] - u[k - 1]) / (time[k] - time[k - 1]));
  }
  return {PeakAbs(u), velocity};
}

}  // namespace

PredictionBand PredictBand(const model::ModelFile& model, const BuildingMotion& motion, int samples,
                           unsigned seed, int substeps) {
  const std::vector<BuildingChannel> channels = {
      {BuildingChannel::Kind::kDisplacement, 1},
      {BuildingChannel::Kind::kAcceleration, int(motion.measured.acceleration.size())}};
  PredictionBand band;
  if (model.identified_range) {  // how far the model's own run goes past it (parameter_draws.h)
    const ChannelHistories own =
        SimulateChannels(model, {motion}, {channels[0]}, false, 0.0, substeps);
    const auto [displacement, velocity] = Peaks(own[0][0], motion.measured.time);
    band.widening = analysis::BandWidening(model, displacement, velocity);
  }
  analysis::ParameterDraws draws(model, seed, band.widening);
  band.contents = analysis::BandContents(model, band.widening);
  std::vector<Signal> isolator, roof;
  std::vector<double> peak_u, peak_a, nrmse_u, nrmse_a;
  for (int s = 0; s < samples; ++s) {
    ChannelHistories run;
    try {
      run = SimulateChannels(draws.Next(), {motion}, channels, false, 0.0, substeps);
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
  band.peak_isolator_displacement = analysis::Spread(peak_u);
  band.peak_roof_acceleration = analysis::Spread(peak_a);
  band.nrmse_isolator_displacement = analysis::Spread(nrmse_u);
  band.nrmse_roof_acceleration = analysis::Spread(nrmse_a);
  // Inside within 1e-4 of the measured history's RMS: a fit to data with no model error gives a
  // band narrower than the data's own digits, which a measurement on its edge must not leave.
  const auto covered = [](const Signal& measured, const Signal& low, const Signal& high) {
    const double tolerance = 1e-4 * Rms(measured);
    std::size_t inside = 0;
    for (std::size_t k = 0; k < measured.size(); ++k) {
      inside += measured[k] >= low[k] - tolerance && measured[k] <= high[k] + tolerance;
    }
    return measured.empty() ? 0.0 : double(inside) / double(measured.size());
  };
  const Signal& u = motion.measured.displacement.front();
  const Signal& a = motion.measured.acceleration.back();
  band.isolator_coverage = covered(u, band.isolator_p5, band.isolator_p95);
  band.roof_coverage = covered(a, band.roof_p5, band.roof_p95);
  band.measured_peak_isolator = PeakAbs(u);
  band.measured_peak_roof = PeakAbs(a);
  const auto within = [](double value, const analysis::Percentiles& p, const Signal& measured) {
    const double tolerance = 1e-4 * Rms(measured);
    return value >= p.p5 - tolerance && value <= p.p95 + tolerance;
  };
  band.isolator_peak_inside =
      within(band.measured_peak_isolator, band.peak_isolator_displacement, u);
  band.roof_peak_inside = within(band.measured_peak_roof, band.peak_roof_acceleration, a);
  return band;
}

std::string CoverageSentence(const PredictionBand& band, const std::string& length_unit,
                             const std::string& acceleration_unit) {
  const auto peak = [](const char* what, double measured, const analysis::Percentiles& p,
                       bool inside, const std::string& unit) {
    return fmt::format("the measured peak {} ({:.4g} {}) is {} it ({:.4g} to {:.4g})", what,
                       measured, unit, inside ? "inside" : "OUTSIDE", p.p5, p.p95);
  };
  std::string sentence = fmt::format(
      "band coverage: the 5-95 % band of {} parameter sets ({}) holds {:.1f} % of the measured "
      "isolator displacement history and {:.1f} % of the roof acceleration's; {}; {}",
      band.samples, band.contents, 100 * band.isolator_coverage, 100 * band.roof_coverage,
      peak("isolator displacement", band.measured_peak_isolator, band.peak_isolator_displacement,
           band.isolator_peak_inside, length_unit),
      peak("roof acceleration", band.measured_peak_roof, band.peak_roof_acceleration,
           band.roof_peak_inside, acceleration_unit));
  if (band.isolator_coverage < 0.9 || band.roof_coverage < 0.9 || !band.isolator_peak_inside ||
      !band.roof_peak_inside) {
    sentence += fmt::format(
        ". The band holds {} only: where it misses the measurements, the model lacks something "
        "the data show, and the band understates the prediction's error",
        band.contents);
  }
  return sentence;
}

}  // namespace isolab::building
