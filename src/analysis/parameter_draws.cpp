#include "isolab/analysis/parameter_draws.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "isolab/analysis/building_parameters.h"
#include "isolab/core/errors.h"

namespace isolab::analysis {

ParameterDraws::ParameterDraws(const model::ModelFile& model, unsigned seed)
    : model_(model), random_(seed) {
  if (!model.uncertainty) {
    throw InputError({model.path},
                     "the model carries no uncertainty: section (a model written by isolab fit "
                     "--building has one), so there is nothing to draw a band from");
  }
  const model::ParameterUncertainty& u = *model.uncertainty;
  const long n = long(u.names.size());
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(u.covariance);
  root_ = eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal();
  centre_.resize(n);
  for (long p = 0; p < n; ++p) {
    const std::size_t q = std::size_t(p);
    centre_[p] = u.log[q] ? std::log(u.values[q]) : u.values[q];
  }
  for (const std::string& name : u.names) ParameterValue(model, name);
}

model::ModelFile ParameterDraws::Next() {
  const model::ParameterUncertainty& u = *model_.uncertainty;
  const long n = centre_.size();
  Eigen::VectorXd e(n);
  for (long p = 0; p < n; ++p) e[p] = normal_(random_);
  const Eigen::VectorXd z = centre_ + root_ * e;
  std::vector<double> values(static_cast<std::size_t>(n));
  for (long p = 0; p < n; ++p) {
    values[std::size_t(p)] = u.log[std::size_t(p)] ? std::exp(z[p]) : z[p];
  }
  model::ModelFile drawn = model_;
  SetParameters(&drawn, u.names, values);
  return drawn;
}

double Quantile(std::vector<double>* values, double q) {
  const std::size_t k = std::min(values->size() - 1, std::size_t(q * double(values->size())));
  std::nth_element(values->begin(), values->begin() + long(k), values->end());
  return (*values)[k];
}

Percentiles Spread(std::vector<double> values) {
  return {Quantile(&values, 0.05), Quantile(&values, 0.5), Quantile(&values, 0.95)};
}

}  // namespace isolab::analysis
