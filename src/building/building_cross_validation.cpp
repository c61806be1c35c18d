#include "isolab/building/building_cross_validation.h"

#include <fmt/format.h>

#include <chrono>

#include "isolab/building/shake_table_prediction.h"
#include "isolab/core/errors.h"

namespace isolab::building {

void CheckCrossValidation(const model::ModelFile& model, const std::vector<BuildingMotion>& motions,
                          const BuildingFitSpec& spec, const std::string& why) {
  if (motions.size() < 2) {
    throw InputError({model.path}, fmt::format("{} holds one motion out and fits the others: it "
                                               "needs two motions or more ({} given)",
                                               why, motions.size()));
  }
  if (spec.sequential) {
    throw InputError({model.path},
                     fmt::format("{} of one specimen's motions: a held-out motion starts from "
                                 "the state the motions before it left, which a fit without it "
                                 "cannot give; give the motions as independent tests",
                                 why));
  }
  if (spec.band_low || spec.band_high) {
    throw InputError({model.path},
                     fmt::format("{} compares whole histories: with the specification's band "
                                 "the fitted and held-out errors would be different quantities; "
                                 "leave band: out for it",
                                 why));
  }
}

CrossValidation CrossValidate(const model::ModelFile& model,
                              const std::vector<BuildingMotion>& motions,
                              const BuildingFitSpec& spec,
                              const identification::FitOptions& options, int band_samples,
                              unsigned seed) {
  const auto clock = std::chrono::steady_clock::now();
  CheckCrossValidation(model, motions, spec, "cross-validation");
  const std::vector<BuildingChannel> channels = FittedChannels(model, spec);
  CrossValidation out;
  for (std::size_t held = 0; held < motions.size(); ++held) {
    HeldOutMotion& fold = out.folds.emplace_back();
    fold.motion = motions[held].name;
    std::vector<BuildingMotion> others;
    for (std::size_t m = 0; m < motions.size(); ++m) {
      if (m == held) continue;
      others.push_back(motions[m]);
      fold.fitted_on.push_back(motions[m].name);
    }
    const BuildingFitResult fit = FitBuilding(model, others, spec, options);
    fold.objective_fitted = fit.objective;
    fold.stop = identification::RefinementStopName(fit.refinement.stop);
    fold.evaluations = fit.evaluations;
    fold.values = fit.fitted.uncertainty->values;
    const ChannelHistories predicted =
        SimulateChannels(fit.fitted, {motions[held]}, channels, false, 0.0, spec.substeps);
    const BuildingMeasurements& measured = motions[held].measured;
    for (std::size_t c = 0; c < channels.size(); ++c) {
      const std::size_t level = std::size_t(channels[c].level - 1);
      const Signal& data = channels[c].kind == BuildingChannel::Kind::kDisplacement
                               ? measured.displacement[level]
                               : measured.acceleration[level];
      const double nrmse = Nrmse(data, predicted[0][c]);
      fold.channels.push_back({channels[c].Name(), nrmse});
      fold.objective_held_out += nrmse * nrmse / double(channels.size());
    }
    if (band_samples > 0 && !measured.table_acceleration.empty()) {
      try {
        fold.band = PredictBand(fit.fitted, motions[held], band_samples, seed, spec.substeps);
      } catch (const InputError& error) {
        fold.band_refused = error.what();
      }
    }
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock).count();
  return out;
}

void AddModelForm(const CrossValidation& folds, model::ModelFile* fitted) {
  for (const HeldOutMotion& fold : folds.folds) {
    fitted->uncertainty->model_form.push_back({fold.fitted_on, fold.values});
  }
}

}  // namespace isolab::building
