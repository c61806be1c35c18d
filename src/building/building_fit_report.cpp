#include "isolab/building/building_fit_report.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "isolab/analysis/parameter_draws.h"

namespace isolab::building {

std::pair<double, double> Interval95(const FittedParameter& p) {
  const double half = 1.96 * p.sigma;
  return p.log ? std::pair{p.value * std::exp(-half), p.value * std::exp(half)}
               : std::pair{p.value - half, p.value + half};
}

std::string BuildingFitProgressLine(const identification::FitProgress& p) {
  if (!p.polishing) {
    return fmt::format("  CMA-ES generation {:5d}, {:8d} simulations, best mean NRMSE^2 = {:.6g}\n",
                       p.generation, p.evaluations, p.best);
  }
  const identification::RefinementOptions tolerances;
  return fmt::format(
      "  least squares {:3d}, {:8d} simulations, mean NRMSE^2 = {:.6g}, decrement {:.2g} "
      "(to {:g}), step {:.2g} (to {:g})\n",
      p.generation, p.evaluations, p.best, p.decrement, tolerances.decrement_tolerance, p.step,
      tolerances.step_tolerance);
}

std::string BuildingFitJson(const BuildingFitResult& result, bool sequential,
                            const std::string& output) {
  nlohmann::json json;
  for (const FittedParameter& p : result.parameters) {
    const auto [low, high] = Interval95(p);
    json["parameters"].push_back({{"name", p.name},
                                  {"start", p.start},
                                  {"value", p.value},
                                  {"sigma", p.sigma},
                                  {"log", p.log},
                                  {"interval_95", {low, high}},
                                  {"at_bound", p.at_bound}});
  }
  json["priors"] = nlohmann::json::array();
  const auto& uncertainty = result.fitted.uncertainty;
  for (const model::ParameterPrior& prior :
       uncertainty ? uncertainty->priors : std::vector<model::ParameterPrior>{}) {
    json["priors"].push_back({{"name", prior.name},
                              {"value", prior.value},
                              {"sigma", prior.sigma},
                              {"source", prior.source}});
  }
  for (const ChannelFit& c : result.channels) {
    json["channels"].push_back({{"motion", c.motion},
                                {"channel", c.channel},
                                {"nrmse_start", c.nrmse_start},
                                {"nrmse", c.nrmse}});
  }
  for (const CorrelatedParameters& pair : result.not_separated) {
    json["not_separated"].push_back(
        {{"a", pair.a}, {"b", pair.b}, {"correlation", pair.correlation}});
  }
  if (const auto& range = result.fitted.identified_range) {
    json["identified_range"] = {{"displacement", range->displacement},
                                {"velocity", range->velocity},
                                {"cycles", range->cycles},
                                {"data", range->data}};
  }
  json["objective_start"] = result.objective_start;
  json["objective"] = result.objective;
  json["samples"] = result.samples;
  json["effective_samples"] = result.effective_samples;
  json["correlation_time"] = result.correlation_time;
  json["evaluations"] = result.evaluations;
  json["global_evaluations"] = result.search.evaluations;
  json["iterations"] = result.refinement.iterations;
  json["stop"] = identification::RefinementStopName(result.refinement.stop);
  json["decrement"] = result.refinement.decrement;
  json["step"] = result.refinement.step;
  json["stop_reason"] = result.stop_reason;
  json["seconds"] = result.seconds;
  json["sequential"] = sequential;
  json["output"] = output;
  return json.dump(2);
}

std::string CrossValidationJson(const CrossValidation& outcome) {
  nlohmann::json json;
  json["folds"] = nlohmann::json::array();
  for (const HeldOutMotion& fold : outcome.folds) {
    nlohmann::json entry = {{"held_out", fold.motion},
                            {"fitted_on", fold.fitted_on},
                            {"objective_fitted", fold.objective_fitted},
                            {"objective_held_out", fold.objective_held_out},
                            {"stop", fold.stop},
                            {"evaluations", fold.evaluations}};
    for (const ChannelError& c : fold.channels) {
      entry["channels"].push_back({{"channel", c.channel}, {"nrmse", c.nrmse}});
    }
    if (fold.band) {
      entry["band"] = {{"samples", fold.band->samples},
                       {"widening", fold.band->widening},
                       {"coverage",
                        {{"isolator_displacement", fold.band->isolator_coverage},
                         {"roof_acceleration", fold.band->roof_coverage}}},
                       {"peak_inside",
                        {{"isolator_displacement", fold.band->isolator_peak_inside},
                         {"roof_acceleration", fold.band->roof_peak_inside}}}};
    }
    if (!fold.band_refused.empty()) entry["band_refused"] = fold.band_refused;
    json["folds"].push_back(std::move(entry));
  }
  json["seconds"] = outcome.seconds;
  return json.dump(2);
}

std::string ModelFormJson(const BuildingFitResult& fit, const CrossValidation& folds) {
  const model::ParameterUncertainty& u = *fit.fitted.uncertainty;
  const Eigen::MatrixXd drawn = analysis::DrawnCovariance(u);
  nlohmann::json json;
  for (const HeldOutMotion& fold : folds.folds) {
    nlohmann::json values;
    for (std::size_t p = 0; p < u.names.size(); ++p) values[u.names[p]] = fold.values[p];
    json["fits"].push_back({{"fitted_on", fold.fitted_on},
                            {"held_out", fold.motion},
                            {"values", values},
                            {"objective_held_out", fold.objective_held_out},
                            {"stop", fold.stop}});
  }
  for (std::size_t p = 0; p < u.names.size(); ++p) {
    const long q = long(p);
    json["parameters"].push_back({{"name", u.names[p]},
                                  {"value", u.values[p]},
                                  {"log", bool(u.log[p])},
                                  {"sigma_fit", std::sqrt(std::max(u.covariance(q, q), 0.0))},
                                  {"sigma_drawn", std::sqrt(std::max(drawn(q, q), 0.0))}});
  }
  return json.dump(2);
}

std::string ModelFormText(const BuildingFitResult& fit, const CrossValidation& folds) {
  const model::ParameterUncertainty& u = *fit.fitted.uncertainty;
  const Eigen::MatrixXd drawn = analysis::DrawnCovariance(u);
  std::vector<std::string> heads;
  for (const HeldOutMotion& fold : folds.folds) {
    heads.push_back(fmt::format("fit to {}", fmt::join(fold.fitted_on, ", ")));
  }
  std::string rule;
  for (std::size_t k = 0; k < folds.folds.size(); ++k) rule += "---|";
  std::string text = fmt::format(
      "\nModel form: the building fitted to every motion but one, each in turn ({:.1f} s). "
      "Prediction bands draw from the fit's covariance plus the spread of these fits, each "
      "weighted alike (sigma in ln p for log parameters):\n\n| parameter | all motions | {} | "
      "sigma, fit | sigma, with model form |\n|---|---|{}---|---|\n",
      folds.seconds, fmt::join(heads, " | "), rule);
  for (std::size_t p = 0; p < u.names.size(); ++p) {
    std::vector<std::string> values;
    for (const HeldOutMotion& fold : folds.folds) {
      values.push_back(fmt::format("{:.4g}", fold.values[p]));
    }
    const long q = long(p);
    text += fmt::format("| {} | {:.4g} | {} | {:.3g} | {:.3g} |\n", u.names[p], u.values[p],
                        fmt::join(values, " | "), std::sqrt(std::max(u.covariance(q, q), 0.0)),
                        std::sqrt(std::max(drawn(q, q), 0.0)));
  }
  std::vector<std::string> held;
  for (const HeldOutMotion& fold : folds.folds) {
    held.push_back(fmt::format("{} {:.4g}", fold.motion, fold.objective_held_out));
  }
  text += fmt::format("\nmean NRMSE^2 of each held-out motion, predicted by the others' fit: {}\n",
                      fmt::join(held, ", "));
  return text;
}

std::string CrossValidationText(const CrossValidation& outcome) {
  std::string text =
      "| held out | fitted on | mean NRMSE^2 fitted | mean NRMSE^2 held out | NRMSE held out, per "
      "channel | band coverage: isolator, roof (peaks inside) |\n|---|---|---|---|---|---|\n";
  for (const HeldOutMotion& fold : outcome.folds) {
    std::vector<std::string> channels, fitted_on = fold.fitted_on;
    for (const ChannelError& c : fold.channels) {
      channels.push_back(fmt::format("{} {:.3f}", c.channel, c.nrmse));
    }
    const std::string band =
        fold.band ? fmt::format("{:.0f} %, {:.0f} % ({}, {}{})", 100 * fold.band->isolator_coverage,
                                100 * fold.band->roof_coverage,
                                fold.band->isolator_peak_inside ? "yes" : "no",
                                fold.band->roof_peak_inside ? "yes" : "no",
                                fold.band->widening > 1.0
                                    ? fmt::format("; widened {:.2f} times beyond the identified "
                                                  "range",
                                                  fold.band->widening)
                                    : "")
        : fold.band_refused.empty() ? std::string("-")
                                    : std::string("none: ") + fold.band_refused;
    text += fmt::format("| {} | {} | {:.4g} ({}) | {:.4g} | {} | {} |\n", fold.motion,
                        fmt::join(fitted_on, ", "), fold.objective_fitted, fold.stop,
                        fold.objective_held_out, fmt::join(channels, ", "), band);
  }
  text += fmt::format(
      "\nEach motion predicted by the building fitted to the others ({:.1f} s): the held-out "
      "error is the one to quote for this model; where it is well above the fitted one, the "
      "parameters move with the motion and the model lacks something that changes between "
      "motions.\n",
      outcome.seconds);
  return text;
}

}  // namespace isolab::building
