#include "isolab/analysis/building_fit_report.h"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>

namespace isolab::analysis {

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

}  // namespace isolab::analysis
