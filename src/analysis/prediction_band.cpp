#include "isolab/analysis/prediction_band.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <random>

#include "isolab/analysis/building_parameters.h"
#include "isolab/core/errors.h"

namespace isolab::analysis {
namespace {

// The q-quantile of `values` (reordered), by the nearest rank.
double Quantile(std::vector<double>* values, double q) {
  const std::size_t k = std::min(values->size() - 1, std::size_t(q * double(values->size())));
  std::nth_element(values->begin(), values->begin() + long(k), values->end());
  return (*values)[k];
}

Percentiles Spread(std::vector<double> values) {
  return {Quantile(&values, 0.05), Quantile(&values, 0.5), Quantile(&values, 0.95)};
}

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
  if (!model.uncertainty) {
    throw InputError({model.path},
                     "the model carries no uncertainty: section (a model written by isolab fit "
                     "--building has one), so there is nothing to draw a band from");
  }
  const model::ParameterUncertainty& u = *model.uncertainty;
  const long n = long(u.names.size());
  // Draws z + L e with L L^T the covariance; through its eigenvalues, so that a covariance with a
  // direction the data did not see (a zero eigenvalue) still gives the others.
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(u.covariance);
  const Eigen::MatrixXd root =
      eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal();
  Eigen::VectorXd centre(n);
  for (long p = 0; p < n; ++p) {
    centre[p] =
        u.log[std::size_t(p)] ? std::log(u.values[std::size_t(p)]) : u.values[std::size_t(p)];
  }
  // The names must be the model's: checked before any draw, so a wrong name is an error, not a
  // band of refused sets.
  for (const std::string& name : u.names) ParameterValue(model, name);

  const std::vector<BuildingChannel> channels = {
      {BuildingChannel::Kind::kDisplacement, 1},
      {BuildingChannel::Kind::kAcceleration, int(motion.measured.acceleration.size())}};
  std::mt19937_64 random(seed);
  std::normal_distribution<double> normal;
  PredictionBand band;
  std::vector<Signal> isolator, roof;
  std::vector<double> peak_u, peak_a, nrmse_u, nrmse_a;
  for (int s = 0; s < samples; ++s) {
    Eigen::VectorXd e(n);
    for (long p = 0; p < n; ++p) e[p] = normal(random);
    const Eigen::VectorXd z = centre + root * e;
    std::vector<double> values(static_cast<std::size_t>(n));
    for (long p = 0; p < n; ++p) {
      values[std::size_t(p)] = u.log[std::size_t(p)] ? std::exp(z[p]) : z[p];
    }
    ChannelHistories run;
    try {
      model::ModelFile drawn = model;
      SetParameters(&drawn, u.names, values);
      run = SimulateChannels(drawn, {motion}, channels, false, 0.0);
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
