#include "isolab/identification/identifiability.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "isolab/core/errors.h"

namespace isolab::identification {
namespace {

// e^2's weight of each test: 1 / <F0, F0> over its fitted samples.
std::vector<double> TestWeights(const FitData& data) {
  std::vector<double> weights;
  for (std::size_t i = 0; i < data.tests.size(); ++i) {
    double norm = 0.0;
    for (const CycleSpan& span : data.fitted[i]) {
      for (std::size_t k = span.begin; k < span.end; ++k)
        norm += std::pow(data.tests[i].force[k], 2);
    }
    weights.push_back(norm > 0.0 ? 1.0 / norm : 1.0);
  }
  return weights;
}

// Each sample of the fitted spans, in order, as (test, sample).
std::vector<std::pair<std::size_t, std::size_t>> FittedRows(const FitData& data) {
  std::vector<std::pair<std::size_t, std::size_t>> rows;
  for (std::size_t i = 0; i < data.tests.size(); ++i) {
    for (const CycleSpan& span : data.fitted[i]) {
      for (std::size_t k = span.begin; k < span.end; ++k) rows.emplace_back(i, k);
    }
  }
  return rows;
}

using Rows = std::vector<std::pair<std::size_t, std::size_t>>;

// Each component's force at every fitted sample, weighted rows (sqrt of e^2's weight), and in
// `result` each component's peak, RMS and secant stiffness, and the device's peak force.
Eigen::MatrixXd ComponentForces(const ModelParametrisation& model, const FitData& data,
                                const FitResult& fit, const Rows& rows,
                                const std::vector<double>& weights,
                                const std::vector<Eigen::MatrixXd>& bases,
                                Identifiability& result) {
  const std::size_t components = model.components().size();
  const Eigen::Index n = static_cast<Eigen::Index>(rows.size());
  Eigen::MatrixXd force(n, static_cast<Eigen::Index>(components));
  Eigen::VectorXd u(n);
  result.components.resize(components);
  for (Eigen::Index r = 0; r < n; ++r) {
    const auto [i, k] = rows[static_cast<std::size_t>(r)];
    const double w = std::sqrt(weights[i]);
    u[r] = w * data.tests[i].displacement[k];
    result.device_peak_force = std::max(result.device_peak_force, std::abs(data.tests[i].force[k]));
    for (std::size_t c = 0; c < components; ++c) {
      double f = 0.0;
      for (int a = model.first_amplitude(c); a < model.first_amplitude(c + 1); ++a) {
        f += bases[i](static_cast<Eigen::Index>(k), a) * fit.amplitudes[a];
      }
      force(r, static_cast<Eigen::Index>(c)) = w * f;
      result.components[c].peak_force = std::max(result.components[c].peak_force, std::abs(f));
    }
  }
  const double uu = u.squaredNorm();
  // The weighted RMS in force units: dividing by the mean weight undoes e^2's per-test scaling.
  double mean_weight = 0.0;
  for (const auto& [i, k] : rows) mean_weight += weights[i];
  mean_weight /= std::max<double>(1.0, static_cast<double>(rows.size()));
  for (std::size_t c = 0; c < components; ++c) {
    const auto f = force.col(static_cast<Eigen::Index>(c));
    ComponentContribution& contribution = result.components[c];
    contribution.name = model.components()[c].name;
    contribution.rms_force = std::sqrt(f.squaredNorm() / std::max<double>(1, n) / mean_weight);
    contribution.secant = uu > 0.0 ? f.dot(u) / uu : 0.0;
  }
  return force;
}

// The pairs of components whose forces cancel: opposed, and their sum a small part of either.
void FindCancellingPairs(const Eigen::MatrixXd& force, const IdentifiabilityOptions& options,
                         Identifiability& result) {
  const std::size_t components = result.components.size();
  for (std::size_t a = 0; a < components; ++a) {
    for (std::size_t b = a + 1; b < components; ++b) {
      const auto fa = force.col(static_cast<Eigen::Index>(a));
      const auto fb = force.col(static_cast<Eigen::Index>(b));
      const double na = fa.norm(), nb = fb.norm();
      if (!(na > 0.0 && nb > 0.0)) continue;
      const double opposition = -fa.dot(fb) / (na * nb);
      const double sum_share = (fa + fb).norm() / std::min(na, nb);
      if (opposition >= options.opposition && sum_share <= options.cancelled_sum) {
        const auto& ca = result.components[a];
        const auto& cb = result.components[b];
        result.cancelling.push_back(
            {a, b, opposition, sum_share,
             fmt::format("{} and {} cancel: their forces oppose (cos = {:.3f}) and their sum is "
                         "{:.0f} % of the smaller one; secant stiffnesses over the tests {:+.4g} "
                         "and {:+.4g}, peak forces {:.4g} and {:.4g}: neither is identified on "
                         "its own",
                         ca.name, cb.name, -opposition, 100 * sum_share, ca.secant, cb.secant,
                         ca.peak_force, cb.peak_force)});
      }
    }
  }
}

// The parameters at their bounds into `result`; the others, free at the fit, into free_shapes
// (coordinates) and free_amplitudes.
void FindFreeParameters(const ModelParametrisation& model, const FitResult& fit,
                        const IdentifiabilityOptions& options, Identifiability& result,
                        std::vector<int>& free_shapes, std::vector<int>& free_amplitudes) {
  const std::vector<std::string> shape_names = model.FreeNames();
  const std::vector<std::string> amplitude_names = model.AmplitudeNames();
  for (int k = 0; k < model.dimension(); ++k) {
    const double x = fit.point[static_cast<std::size_t>(k)];
    const CoordinateRange& range = model.free_range(k);
    const double value = range.At(x);
    if (x <= options.bound_margin) {
      result.at_bounds.push_back(
          {shape_names[k], value, fmt::format("lower bound ({:g})", range.low)});
    } else if (x >= 1.0 - options.bound_margin) {
      result.at_bounds.push_back(
          {shape_names[k], value, fmt::format("upper bound ({:g})", range.high)});
    } else {
      free_shapes.push_back(k);
    }
  }
  for (int a = 0; a < model.amplitude_count(); ++a) {
    if (model.nonnegative()[a] && fit.amplitudes[a] == 0.0) {
      result.at_bounds.push_back({amplitude_names[a], 0.0, "zero (its sign constraint)"});
    } else {
      free_amplitudes.push_back(a);
    }
  }
}

// The Jacobian of the weighted model force in the free parameters: the amplitudes' columns
// exactly (the force is linear in them), the shape coordinates' by central differences.
Eigen::MatrixXd FreeParameterJacobian(const ModelParametrisation& model, const FitData& data,
                                      const FitResult& fit, const Rows& rows,
                                      const std::vector<double>& weights,
                                      const std::vector<Eigen::MatrixXd>& bases,
                                      const std::vector<int>& free_shapes,
                                      const std::vector<int>& free_amplitudes) {
  const Eigen::Index n = static_cast<Eigen::Index>(rows.size());
  const Eigen::Index p = static_cast<Eigen::Index>(free_shapes.size() + free_amplitudes.size());
  Eigen::MatrixXd jacobian(n, p);
  for (std::size_t j = 0; j < free_amplitudes.size(); ++j) {
    for (Eigen::Index r = 0; r < n; ++r) {
      const auto [i, k] = rows[static_cast<std::size_t>(r)];
      jacobian(r, static_cast<Eigen::Index>(free_shapes.size() + j)) =
          std::sqrt(weights[i]) * bases[i](static_cast<Eigen::Index>(k), free_amplitudes[j]);
    }
  }
  for (std::size_t j = 0; j < free_shapes.size(); ++j) {
    const int k = free_shapes[j];
    const double h = 1e-5;
    std::vector<double> ahead = fit.point, behind = fit.point;
    ahead[static_cast<std::size_t>(k)] += h;
    behind[static_cast<std::size_t>(k)] -= h;
    std::vector<Eigen::MatrixXd> plus, minus;
    model.Basis(ahead, data.tests, data.one_specimen, &plus);
    model.Basis(behind, data.tests, data.one_specimen, &minus);
    for (Eigen::Index r = 0; r < n; ++r) {
      const auto [i, s] = rows[static_cast<std::size_t>(r)];
      const Eigen::Index row = static_cast<Eigen::Index>(s);
      jacobian(r, static_cast<Eigen::Index>(j)) =
          std::sqrt(weights[i]) *
          (plus[i].row(row).dot(fit.amplitudes) - minus[i].row(row).dot(fit.amplitudes)) / (2 * h);
    }
  }
  return jacobian;
}

// The free parameters' correlations from the Jacobian, those at or above the option's, and the
// directions the data do not see.
void FindCorrelations(Eigen::MatrixXd jacobian, const std::vector<std::string>& names,
                      const IdentifiabilityOptions& options, Identifiability& result) {
  const Eigen::Index p = jacobian.cols();
  // Columns scaled to unit length, so the normal matrix's conditioning reflects collinearity
  // alone, not the parameters' units.
  for (Eigen::Index c = 0; c < p; ++c) {
    const double norm = jacobian.col(c).norm();
    if (norm > 0.0) jacobian.col(c) /= norm;
  }
  const Eigen::MatrixXd normal = jacobian.transpose() * jacobian;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(normal);
  const double largest = eigen.eigenvalues().maxCoeff();
  result.singular = !(eigen.eigenvalues().minCoeff() > 1e-12 * largest);
  if (result.singular) {  // eigenvalues ascend: the first vector is the unseen direction
    for (Eigen::Index k = 0; k < p; ++k) {
      if (std::abs(eigen.eigenvectors()(k, 0)) > 0.3) result.unseen.push_back(names[k]);
    }
  }
  // A regularised inverse: a direction the data do not see gives correlations of +-1 instead of
  // infinities.
  Eigen::VectorXd inverse = eigen.eigenvalues();
  for (Eigen::Index k = 0; k < p; ++k)
    inverse[k] = 1.0 / (std::max(inverse[k], 0.0) + 1e-12 * largest);
  const Eigen::MatrixXd covariance =
      eigen.eigenvectors() * inverse.asDiagonal() * eigen.eigenvectors().transpose();
  for (Eigen::Index a = 0; a < p; ++a) {
    for (Eigen::Index b = a + 1; b < p; ++b) {
      const double correlation = covariance(a, b) / std::sqrt(covariance(a, a) * covariance(b, b));
      if (std::abs(correlation) >= options.correlation) {
        result.correlated.push_back({names[a], names[b], correlation});
      }
    }
  }
  std::sort(result.correlated.begin(), result.correlated.end(), [](const auto& x, const auto& y) {
    return std::abs(x.correlation) > std::abs(y.correlation);
  });
}

}  // namespace

void IdentifiabilityOptions::Validate() const {
  if (!(opposition > 0.0 && opposition <= 1.0)) {
    throw InvalidParameter({"opposition", opposition, "must be in (0, 1]"});
  }
  if (!(cancelled_sum > 0.0 && cancelled_sum <= 1.0)) {
    throw InvalidParameter({"cancelled_sum", cancelled_sum, "must be in (0, 1]"});
  }
  if (!(correlation > 0.0 && correlation <= 1.0)) {
    throw InvalidParameter({"correlation", correlation, "must be in (0, 1]"});
  }
  if (!(bound_margin >= 0.0 && bound_margin < 0.5)) {
    throw InvalidParameter({"bound_margin", bound_margin, "must be in [0, 0.5)"});
  }
}

bool Identifiability::Cancels(std::size_t component) const {
  return std::any_of(cancelling.begin(), cancelling.end(), [&](const CancellingPair& pair) {
    return pair.a == component || pair.b == component;
  });
}

std::vector<std::string> Identifiability::Findings() const {
  std::vector<std::string> findings;
  for (const CancellingPair& pair : cancelling) findings.push_back(pair.finding);
  for (const ComponentContribution& c : components) {
    if (device_peak_force > 0.0 && c.peak_force > 2.0 * device_peak_force) {
      findings.push_back(fmt::format(
          "{} carries up to {:.4g} in a device whose measured force reaches {:.4g}: a part that "
          "large is cancelled by another, not identified on its own",
          c.name, c.peak_force, device_peak_force));
    }
  }
  for (const BoundParameter& p : at_bounds) {
    findings.push_back(fmt::format("{} = {:.6g} is at its {}", p.name, p.value, p.where));
  }
  if (singular) {
    findings.push_back(
        fmt::format("the data do not see one combination of {} at all (the "
                    "Jacobian is singular there)",
                    fmt::join(unseen, ", ")));
  }
  for (std::size_t k = 0; k < correlated.size() && k < 3; ++k) {
    findings.push_back(
        fmt::format("{} and {} are correlated {:+.3f}: the data fix a combination "
                    "of the two, not each",
                    correlated[k].a, correlated[k].b, correlated[k].correlation));
  }
  if (correlated.size() > 3) {
    findings.push_back(
        fmt::format("{} more pairs are correlated beyond the threshold", correlated.size() - 3));
  }
  return findings;
}

Identifiability AssessIdentifiability(const ModelParametrisation& model, const FitData& data,
                                      const FitResult& fit, const IdentifiabilityOptions& options) {
  options.Validate();
  Identifiability result;
  const std::vector<double> weights = TestWeights(data);
  const Rows rows = FittedRows(data);
  std::vector<Eigen::MatrixXd> bases;
  model.Basis(fit.point, data.tests, data.one_specimen, &bases);
  const Eigen::MatrixXd force = ComponentForces(model, data, fit, rows, weights, bases, result);
  FindCancellingPairs(force, options, result);
  std::vector<int> free_shapes, free_amplitudes;
  FindFreeParameters(model, fit, options, result, free_shapes, free_amplitudes);
  if (free_shapes.size() + free_amplitudes.size() < 2) return result;
  const std::vector<std::string> shape_names = model.FreeNames();
  const std::vector<std::string> amplitude_names = model.AmplitudeNames();
  std::vector<std::string> names;
  for (const int k : free_shapes) names.push_back(shape_names[k]);
  for (const int a : free_amplitudes) names.push_back(amplitude_names[a]);
  FindCorrelations(
      FreeParameterJacobian(model, data, fit, rows, weights, bases, free_shapes, free_amplitudes),
      names, options, result);
  return result;
}

}  // namespace isolab::identification
