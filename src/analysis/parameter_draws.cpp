#include "isolab/analysis/parameter_draws.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "isolab/analysis/building_parameters.h"
#include "isolab/analysis/model_summary.h"
#include "isolab/core/errors.h"

namespace isolab::analysis {
namespace {

// The priors' random stream: seeded from the draws' seed, apart from the fitted parameters'.
std::mt19937_64 PriorEngine(unsigned seed) {
  std::seed_seq sequence{seed, 1u};
  return std::mt19937_64(sequence);
}

}  // namespace

Eigen::MatrixXd DrawnCovariance(const model::ParameterUncertainty& u) {
  Eigen::MatrixXd covariance = u.covariance;
  const long n = long(u.names.size());
  const auto coordinates = [&](const std::vector<double>& values) {
    Eigen::VectorXd c(n);
    for (long p = 0; p < n; ++p) {
      const std::size_t q = std::size_t(p);
      c[p] = u.log[q] ? std::log(values[q]) : values[q];
    }
    return c;
  };
  // The jackknife's pseudo-values J c - (J - 1) c_j stand for what each motion alone would give;
  // their spread about c is (J - 1)^2 / J times the sum of the held-out fits' outer products.
  const Eigen::VectorXd all = coordinates(u.values);
  const double folds = double(u.model_form.size());
  for (const model::ModelFormFit& fit : u.model_form) {
    const Eigen::VectorXd offset = coordinates(fit.values) - all;
    covariance += (folds - 1.0) * (folds - 1.0) / folds * offset * offset.transpose();
  }
  return covariance;
}

double BandWidening(const model::ModelFile& model, double displacement, double velocity) {
  if (!model.identified_range) return 1.0;
  const double factor = IdentifiedRangeFactor(*model.identified_range, displacement, velocity);
  return factor > kIdentifiedRangeMargin ? factor : 1.0;
}

std::string BandContents(const model::ModelFile& model, double widening) {
  const std::size_t fits = model.uncertainty ? model.uncertainty->model_form.size() : 0;
  std::string contents = "the parameters' uncertainty";
  if (fits > 0) {
    contents += fmt::format(
        " and the spread of {} fit{} to subsets of the motions (model form, weighted alike)", fits,
        fits == 1 ? "" : "s");
  }
  if (model.uncertainty && !model.uncertainty->priors.empty()) {
    std::vector<std::string> given;
    for (const model::ParameterPrior& prior : model.uncertainty->priors) {
      given.push_back(fmt::format("{}: {}", prior.name, prior.source));
    }
    contents += fmt::format(", with {} parameter{} from a prior ({})", given.size(),
                            given.size() == 1 ? "" : "s", fmt::join(given, "; "));
  }
  if (widening > 1.0) {
    contents += fmt::format(
        ", widened {:.2f} times beyond the identified range (a stated rule: past the last "
        "measured cycle the laws are assumed, not measured)",
        widening);
  }
  return contents;
}

std::string PriorsBeyondRangeText(const model::ModelFile& model) {
  if (!model.uncertainty || model.uncertainty->priors.empty()) return "";
  std::vector<std::string> given;
  for (const model::ParameterPrior& prior : model.uncertainty->priors) {
    // The model's value as it runs (an edit may have moved it from the prior's); the prior's
    // where the model no longer has the parameter, which only a band (ParameterDraws) refuses.
    double value = prior.value;
    try {
      value = ParameterValue(model, prior.name);
    } catch (const InputError&) {
    }
    given.push_back(fmt::format("{} = {:.4g} ({})", prior.name, value, prior.source));
  }
  return fmt::format("; beyond it the response also rests on parameters given, not fitted: {}",
                     fmt::join(given, ", "));
}

ParameterDraws::ParameterDraws(const model::ModelFile& model, unsigned seed, double widening)
    : model_(model), random_(seed), prior_random_(PriorEngine(seed)) {
  if (!model.uncertainty) {
    throw InputError({model.path},
                     "the model carries no uncertainty: section (a model written by isolab fit "
                     "--building has one), so there is nothing to draw a band from");
  }
  const model::ParameterUncertainty& u = *model.uncertainty;
  const long n = long(u.names.size());
  const Eigen::MatrixXd covariance = DrawnCovariance(u);
  for (long p = 0; p < n; ++p) {
    // One standard deviation of a factor 10 or more is not a measurement: drawn from, it gives
    // bands of many decades (a variance of 1e6 in ln p: 1e-170 to 1e2).
    const double sigma = std::sqrt(covariance(p, p));
    if (u.log[std::size_t(p)] && sigma > std::log(10.0)) {
      const std::string where = u.model_form.empty()
                                    ? fmt::format("uncertainty.covariance[{}][{}]", p, p)
                                    : fmt::format(
                                          "uncertainty (covariance[{}][{}] and the "
                                          "model_form fits' spread)",
                                          p, p);
      throw InputError(
          {model.path},
          fmt::format("{}: '{}' has a standard deviation of {:.3g} in ln p, a factor {:.3g} per "
                      "sigma: implausibly wide for a band (at most a factor 10)",
                      where, u.names[std::size_t(p)], sigma, std::exp(sigma)));
    }
  }
  // The covariance is positive semi-definite (model_file.cpp checks it; the model form adds
  // outer products); eigenvalues at round-off below zero draw nothing in their direction.
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(covariance);
  root_ =
      widening * eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal();
  // Centred on the model's own values, not on those the fit wrote beside the covariance: a model
  // edited since (or set from Python) gets a band about the run it makes.
  centre_.resize(n);
  for (long p = 0; p < n; ++p) {
    const std::size_t q = std::size_t(p);
    const double value = ParameterValue(model, u.names[q]);
    if (u.log[q] && !(value > 0.0)) {
      throw InputError({model.path},
                       fmt::format("{} is {:g}, drawn log-normally by the uncertainty section: "
                                   "it must be > 0",
                                   u.names[q], value));
    }
    centre_[p] = u.log[q] ? std::log(value) : value;
  }
  for (const model::ParameterPrior& prior : u.priors) {
    const double value = ParameterValue(model, prior.name);
    if (!(value > 0.0)) {
      throw InputError({model.path},
                       fmt::format("{} is {:g}, drawn log-normally by its prior: it must be > 0",
                                   prior.name, value));
    }
    prior_names_.push_back(prior.name);
    prior_centres_.push_back(std::log(value));
    prior_sigmas_.push_back(prior.sigma);
  }
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
  if (!prior_names_.empty()) {
    std::vector<double> given(prior_names_.size());
    for (std::size_t p = 0; p < given.size(); ++p) {
      given[p] = std::exp(prior_centres_[p] + prior_sigmas_[p] * prior_normal_(prior_random_));
    }
    SetParameters(&drawn, prior_names_, given);
  }
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
