// Parameter sets drawn from the uncertainty a fit reported (model_file.h's `uncertainty`, written
// by `isolab fit --building`): normal in the parameters' coordinates (ln p where the fit searched
// log-uniformly) about the model's own values (which an edit may have moved from the fitted
// ones), through the covariance's eigenvalues, so that a direction the data did not see
// (a zero eigenvalue) still gives the others. What a prediction band runs (prediction_band.h,
// run_band.h), and the percentiles it reports.
//
// Model form: where the uncertainty carries the fits with each of J motions held out in turn
// (`model_form`), the spread between motions is added to the covariance, each motion weighted
// alike. The jackknife's pseudo-values p_j = J c - (J - 1) c_j stand for what motion j alone
// would give, and their spread about c is
//   C = covariance + ((J - 1)^2 / J) sum_j (c_j - c)(c_j - c)^T,
// c_j the coordinates of fit j, c those of `values` (the fit to every motion); for two motions,
// p_j is the other fit's c_j and this is (1/2) sum_j (c_j - c)(c_j - c)^T. The fits differ where
// the data cannot tell the models apart (a damping traded for a stiffness between two motions),
// which the covariance of one fit, a local curvature, does not hold; the normal law over C is a
// stated approximation of that spread, not a distribution the data gave.
//
// Beyond the identified range: where the model's own run goes past the range its isolation was
// identified on by more than kIdentifiedRangeMargin, by a factor r (IdentifiedRangeFactor), every
// draw's offset from the model's values is multiplied by r, so the standard deviations are r
// times the ones above. Past the last measured cycle the laws' behaviour is their form's, not
// the data's; the band widens with how far the run extrapolates. A rule the project states, not
// something the data measured: the band's text says it was applied and by how much. (The check
// that refuses an implausibly wide uncertainty, a factor 10 per sigma, reads the model's own,
// before this widening.)
//
// Priors (`priors`: parameters given from design data or a preset, not fitted) are drawn too,
// each independently, log-normally about the model's own value with its sigma; the widening
// does not apply to them, whose sigma is already what is assumed of them.
#pragma once

#include <Eigen/Core>
#include <random>
#include <string>
#include <vector>

#include "isolab/model/model_file.h"

namespace isolab::analysis {

class ParameterDraws {
 public:
  // Throws InputError when the model carries no uncertainty, names a parameter it lacks (checked
  // before any draw, so a wrong name is an error, not a band of refused sets), or gives a log
  // parameter a standard deviation above ln 10 (a factor 10 per sigma). `widening` (>= 1)
  // multiplies every draw's offset (BandWidening).
  ParameterDraws(const model::ModelFile& model, unsigned seed, double widening = 1.0);

  // The model with the next drawn set. Throws InvalidParameter or InputError for a set that
  // breaks a law's rules (k1 > k0, say): no building, to be counted as refused.
  model::ModelFile Next();

 private:
  const model::ModelFile& model_;
  Eigen::VectorXd centre_;
  Eigen::MatrixXd root_;  // root root^T = the covariance
  // The priors' names and ln of the model's values, drawn independently (not widened: a prior's
  // sigma is already what is assumed of it).
  std::vector<std::string> prior_names_;
  std::vector<double> prior_centres_, prior_sigmas_;
  std::mt19937_64 random_;
  // The priors' own stream, so that adding a prior leaves the fitted parameters' draws as they
  // were for the same seed.
  std::mt19937_64 prior_random_;
  std::normal_distribution<double> normal_, prior_normal_;
};

// The covariance the draws use: the parameters' own, plus the model form's spread where there is
// one (above).
Eigen::MatrixXd DrawnCovariance(const model::ParameterUncertainty& uncertainty);

// The widening of a band whose model, run itself, reaches `displacement` and `velocity` at its
// isolator: the factor past the identified range beyond kIdentifiedRangeMargin, else 1 (and 1
// for a model without an identified range).
double BandWidening(const model::ModelFile& model, double displacement, double velocity);

// What a band drawn from `model` with `widening` holds, for the text beside it: "the parameters'
// uncertainty", "... and the spread of 2 fits to subsets of the motions (model form, weighted
// alike)", "..., with 1 parameter from a prior (isolation.s.k2: design data)", and with a
// widening "..., widened 2.3 times beyond the identified range (a stated rule: past the last
// measured cycle the laws are assumed, not measured)".
std::string BandContents(const model::ModelFile& model, double widening = 1.0);

// What a run beyond the identified range rests on besides the fit, for its warning: "; beyond it
// the response also rests on parameters given, not fitted: isolation.s.k2 = 0.8 (design data)",
// or empty for a model without priors (model_file.h's ParameterPrior).
std::string PriorsBeyondRangeText(const model::ModelFile& model);

struct Percentiles {
  double p5 = 0.0, p50 = 0.0, p95 = 0.0;
};
// The 5th, 50th and 95th percentiles (nearest rank) of `values`, not empty.
Percentiles Spread(std::vector<double> values);
// The q-quantile of `values` (reordered), by the nearest rank.
double Quantile(std::vector<double>* values, double q);

}  // namespace isolab::analysis
