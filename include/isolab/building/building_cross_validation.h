// Cross-validation of a building fit: with two or more motions, each is held out in turn, the
// building fitted to the others (building/building_fit.h, the same specification and search) and
// its prediction of the held-out motion compared with the measurements: the NRMSE of every fitted
// channel (RMS-normalised, over the whole history) and, for shake-table motions, the coverage of
// the band drawn from the fit's uncertainty (prediction_band.h). The held-out error is the number
// to quote for a model: a fit's own residual says how well it describes the data it saw, not how
// well it predicts a motion it did not.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "isolab/building/building_fit.h"
#include "isolab/building/prediction_band.h"

namespace isolab::building {

struct ChannelError {
  std::string channel;
  double nrmse = 0.0;  // RMS(predicted - measured) / RMS(measured)
};

struct HeldOutMotion {
  std::string motion;                  // held out
  std::vector<std::string> fitted_on;  // the others
  double objective_fitted = 0.0;       // the fit's mean NRMSE^2 on the motions it saw
  double objective_held_out = 0.0;     // mean NRMSE^2 of the held-out motion's channels
  std::vector<ChannelError> channels;  // held out
  std::vector<double> values;          // the fit's parameters, in the spec's order (model units)
  std::string stop;                    // the fit's refinement stop ("converged", ...)
  long evaluations = 0;
  std::optional<PredictionBand> band;  // shake-table motions, with band draws asked for
  std::string band_refused;            // why no band could be drawn (a fold's wide uncertainty)
};

// Parameter sets drawn for each held-out motion's band by the command line and Python: enough for
// its 5-95 % range to be more than the extreme draws, few beside the fits.
inline constexpr int kCrossValidationDraws = 20;

struct CrossValidation {
  std::vector<HeldOutMotion> folds;  // one per motion, in order
  double seconds = 0.0;
};

// Throws InputError for fewer than two motions, for motions of one specimen (a held-out motion's
// start is the state the others left, which a fit without it cannot give) and for a spec with a
// band (the held-out error is over the whole history): `why` names what holds the motions out.
void CheckCrossValidation(const model::ModelFile& model, const std::vector<BuildingMotion>& motions,
                          const BuildingFitSpec& spec, const std::string& why);

// Throws as CheckCrossValidation, and what FitBuilding throws. A fold whose fit gives no band (an
// uncertainty too wide to draw from) says why and the others go on. `band_samples` parameter sets
// (0: none; else >= 2) drawn with `seed`.
CrossValidation CrossValidate(const model::ModelFile& model,
                              const std::vector<BuildingMotion>& motions,
                              const BuildingFitSpec& spec,
                              const identification::FitOptions& options, int band_samples,
                              unsigned seed);

// The folds' fits as the model form of `fitted` (a fit to every motion, with its uncertainty):
// fitted->uncertainty->model_form, one entry per fold (model_file.h, parameter_draws.h).
void AddModelForm(const CrossValidation& folds, model::ModelFile* fitted);

}  // namespace isolab::building
