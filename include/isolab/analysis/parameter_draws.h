// Parameter sets drawn from the uncertainty a fit reported (model_file.h's `uncertainty`, written
// by `isolab fit --building`): normal in the parameters' coordinates (ln p where the fit searched
// log-uniformly) about the model's own values (which an edit may have moved from the fitted
// ones), through the covariance's eigenvalues, so that a direction the data did not see
// (a zero eigenvalue) still gives the others. What a prediction band runs (prediction_band.h,
// run_band.h), and the percentiles it reports.
#pragma once

#include <Eigen/Core>
#include <random>
#include <vector>

#include "isolab/model/model_file.h"

namespace isolab::analysis {

class ParameterDraws {
 public:
  // Throws InputError when the model carries no uncertainty, names a parameter it lacks (checked
  // before any draw, so a wrong name is an error, not a band of refused sets), or gives a log
  // parameter a standard deviation above ln 10 (a factor 10 per sigma).
  ParameterDraws(const model::ModelFile& model, unsigned seed);

  // The model with the next drawn set. Throws InvalidParameter or InputError for a set that
  // breaks a law's rules (k1 > k0, say): no building, to be counted as refused.
  model::ModelFile Next();

 private:
  const model::ModelFile& model_;
  Eigen::VectorXd centre_;
  Eigen::MatrixXd root_;  // root root^T = the covariance
  std::mt19937_64 random_;
  std::normal_distribution<double> normal_;
};

struct Percentiles {
  double p5 = 0.0, p50 = 0.0, p95 = 0.0;
};
// The 5th, 50th and 95th percentiles (nearest rank) of `values`, not empty.
Percentiles Spread(std::vector<double> values);
// The q-quantile of `values` (reordered), by the nearest rank.
double Quantile(std::vector<double>* values, double q);

}  // namespace isolab::analysis
