// Output-error identification of a whole building model from shake-table motions: the isolation
// layer's parameters together with the superstructure's (story stiffnesses, modal damping, how the
// mass is distributed; building_parameters.h names them), found by simulating the model under
// each measured table motion and comparing the floor responses it predicts with those measured.
// The same for a model driven by a measured force on its lowest mass (an SDOF under a shaker, the
// Bouc-Wen benchmark's form), compared with the displacement measured there.
//
// The objective is the mean over the fitted channels (each motion's displacements relative to the
// table and absolute accelerations, any subset) of each channel's NRMSE^2, so every channel
// counts by its own scale; with a band, both histories are first restricted to it (FFT, bins
// outside zeroed), so a fit may leave out what the model is not meant to describe. Motions are
// independent tests from rest, or one specimen in the order given: each then starts from the
// state the previous one left, the building brought to rest by a pause of zero table motion
// between them (the bearings' internal state, their scragging, degradation and residual offset,
// carried). The search has two stages over the parameters' ranges (log-uniform where positive):
// the unit-cube CMA-ES every fit runs (identification/unit_cube_search.h) finds the basin, for
// FitOptions::global_budget simulations, and a Levenberg-Marquardt refinement on the residual
// (identification/least_squares.h) converges in it, with a gradient and a step criterion.
//
// Uncertainty, from the curvature at the optimum: J the Jacobian of the weighted residual vector
// (central differences in the parameters' coordinates, ln p where the range is log), the
// covariance s^2 (J^T J)^-1 with s^2 = SSR / (N - P), inflated by N / N_eff, N_eff the samples
// worth as many independent ones (each channel's samples over its residual's integrated
// correlation time): model error is correlated over a second or more, and counting every sample
// as independent would claim far more certainty than the data hold. Correlations near +-1 name
// parameters the data do not separate.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "isolab/analysis/building_parameters.h"
#include "isolab/building/building_response.h"
#include "isolab/identification/least_squares.h"
#include "isolab/identification/unit_cube_search.h"
#include "isolab/model/model_file.h"

namespace isolab::building {

struct FittedParameterSpec {
  std::string name;                     // building_parameters.h
  std::optional<double> low{}, high{};  // the range searched; default DefaultRange
  std::optional<double> start{};        // default the model's value
};

struct PriorSpec {
  std::string name;             // building_parameters.h
  std::optional<double> value;  // default the model's
  double sigma = 0.0;           // in ln p
  std::string source;
};

struct BuildingFitSpec {
  std::vector<FittedParameterSpec> parameters;
  // Held at their values through the fit and written as the fitted model's uncertainty.priors.
  std::vector<PriorSpec> priors;
  std::vector<BuildingChannel> channels;      // empty: every level's displacement and acceleration
  std::optional<double> band_low, band_high;  // (1/time) the band the residual is read in
  bool sequential = false;                    // the motions are one specimen, in the order given
  double pause = 0.0;  // (time) of rest between sequential motions; 0: 5 x longest period
  int substeps = 1;    // integration steps per measured sample (rate laws at a coarse sampling)
};

struct FittedParameter {
  std::string name;
  double start = 0.0, value = 0.0, low = 0.0, high = 0.0;
  bool log = true;
  // Standard deviation of ln(value) (log) or of the value, from the covariance.
  double sigma = 0.0;
  bool at_bound = false;  // within 1e-3 of the range's ends (unit cube): the range holds it
};

struct ChannelFit {
  std::string motion, channel;
  double nrmse_start = 0.0, nrmse = 0.0;  // in the band when one is given
};

struct CorrelatedParameters {
  std::string a, b;
  double correlation = 0.0;
};

struct BuildingFitResult {
  // The model with the fitted values and their uncertainty (model_file.h; written by
  // model::FittedBuildingText).
  model::ModelFile fitted;
  std::vector<FittedParameter> parameters;
  Eigen::MatrixXd covariance;                       // of the coordinates (ln p, or p)
  Eigen::MatrixXd correlation;                      // its unit-diagonal form
  std::vector<CorrelatedParameters> not_separated;  // |correlation| >= 0.95, strongest first
  std::vector<ChannelFit> channels;
  double objective_start = 0.0, objective = 0.0;  // mean NRMSE^2 over channels
  double samples = 0.0, effective_samples = 0.0;
  double correlation_time = 0.0;  // (time) of the residual, over channels weighted by samples
  identification::SearchOutcome search;  // the global stage
  // The least-squares stage kept (its Jacobian moved into the covariance, so left empty).
  identification::RefinementOutcome refinement;
  long evaluations = 0;     // simulations of both stages
  std::string stop_reason;  // both stages, one sentence each
  double seconds = 0.0;
};

// The channels a fit compares: the spec's, or every level's displacement and acceleration.
std::vector<BuildingChannel> FittedChannels(const model::ModelFile& model,
                                            const BuildingFitSpec& spec);

// Throws InputError for a spec that names what the model lacks, a channel beyond the levels or
// not measured in a motion, motions without samples, and FitOptions::Validate's InvalidParameter.
BuildingFitResult FitBuilding(const model::ModelFile& model,
                              const std::vector<BuildingMotion>& motions,
                              const BuildingFitSpec& spec,
                              const identification::FitOptions& options);

}  // namespace isolab::building
