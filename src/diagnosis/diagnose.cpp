#include "isolab/diagnosis/diagnose.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace isolab::diagnosis {
namespace {

using identification::ComponentSpec;
using identification::ModelParametrisation;

// Fits `components`, starting every coordinate that a previous fit knows from its value there.
FittedModel FitModel(std::vector<ComponentSpec> components, const identification::FitData& data,
                     const identification::DataScales& scales, unsigned seed, long budget) {
  FittedModel model;
  const ModelParametrisation parametrisation(components, scales);
  identification::FitOptions options;
  options.seed = seed;
  options.budget = budget;
  model.fit = identification::Fit(parametrisation, data, options);
  model.parameters = parametrisation.dimension() + parametrisation.amplitude_count();
  const Discrepancy residual =
      Discrepancy::Of(parametrisation.Assembly(model.fit.point, model.fit.amplitudes), data);
  model.effective_samples = EffectiveSamples(SampleCount(data), ResidualCorrelation(residual));
  model.bic =
      InformationCriterion(model.fit.error.total, model.effective_samples, model.parameters);
  // Record the fitted shape as start values, so a refit with one more component begins here.
  const auto shapes = parametrisation.ShapeValues(model.fit.point);
  for (std::size_t c = 0; c < components.size(); ++c) {
    const auto names = identification::CoordinateNames(components[c].type);
    for (std::size_t k = 0; k < names.size(); ++k) {
      if (!components[c].fixed.count(names[k])) components[c].start[names[k]] = shapes[c][k];
    }
  }
  model.components = std::move(components);
  return model;
}

// A name not yet used in the model ("hardening", then "hardening_2", ...).
std::string UniqueName(const std::vector<ComponentSpec>& components, const std::string& name) {
  const auto used = [&](const std::string& candidate) {
    return std::any_of(components.begin(), components.end(),
                       [&](const ComponentSpec& c) { return c.name == candidate; });
  };
  if (!used(name)) return name;
  for (int k = 2;; ++k) {
    if (!used(fmt::format("{}_{}", name, k))) return fmt::format("{}_{}", name, k);
  }
}

}  // namespace

hysteresis::ParallelAssembly AssemblyOf(const FittedModel& model,
                                        const identification::FitData& data) {
  return ModelParametrisation(model.components, identification::ScalesOf(data))
      .Assembly(model.fit.point, model.fit.amplitudes);
}

double InformationCriterion(double e2, double samples, int parameters) {
  const double n = std::max(samples, 2.0);
  return n * std::log(std::max(e2, 1e-300) / n) + parameters * std::log(n);
}

Diagnosis Diagnose(std::vector<ComponentSpec> base, const identification::FitData& data,
                   const DiagnoseOptions& options) {
  if (base.empty()) throw std::invalid_argument("the base model has no components");
  if (options.budget < 100) throw std::invalid_argument("budget must be >= 100 evaluations");
  if (!(options.bic_margin > 0.0)) throw std::invalid_argument("bic_margin must be > 0");
  if (!(options.noise_margin >= 1.0)) throw std::invalid_argument("noise_margin must be >= 1");
  const auto start = std::chrono::steady_clock::now();
  const auto say = [&](const std::string& line) {
    if (options.progress) options.progress(line);
  };
  const identification::DataScales scales = identification::ScalesOf(data);

  Diagnosis diagnosis;
  diagnosis.samples = SampleCount(data);
  unsigned seed = options.seed;
  diagnosis.base = FitModel(std::move(base), data, scales, seed, options.budget);
  say(fmt::format("base model: e^2 = {:.4g} %, BIC = {:.1f}", 100 * diagnosis.base.fit.error.total,
                  diagnosis.base.bic));
  FittedModel current = diagnosis.base;
  {
    const Discrepancy discrepancy = Discrepancy::Of(AssemblyOf(current, data), data);
    diagnosis.noise_floor = NoiseFloor(data, discrepancy.force_noise);
  }
  std::vector<Effect> remaining(AllEffects().begin(), AllEffects().end());

  while (true) {
    const Discrepancy discrepancy = Discrepancy::Of(AssemblyOf(current, data), data);
    std::vector<Candidate> candidates;
    for (const Effect effect : remaining) candidates.push_back({Detect(effect, discrepancy)});
    std::stable_sort(candidates.begin(), candidates.end(), [](const auto& a, const auto& b) {
      return a.evidence.Strength() > b.evidence.Strength();
    });
    const double e2 = current.fit.error.total;
    if (e2 <= options.noise_margin * diagnosis.noise_floor) {
      diagnosis.stop_reason = fmt::format(
          "e^2 = {:.4g} % is within {:g} x the noise floor ({:.4g} %): nothing left that the "
          "measurement noise does not explain",
          100 * e2, options.noise_margin, 100 * diagnosis.noise_floor);
      diagnosis.last_candidates = std::move(candidates);
      break;
    }
    if (static_cast<int>(diagnosis.steps.size()) >= options.max_steps) {
      diagnosis.stop_reason = fmt::format("{} effects added, the limit", options.max_steps);
      diagnosis.last_candidates = std::move(candidates);
      break;
    }
    // Refit every candidate the evidence supports; keep the one with the lowest BIC.
    int best = -1;
    FittedModel best_model;
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      Candidate& candidate = candidates[c];
      if (!candidate.evidence.Supported()) continue;
      std::vector<ComponentSpec> components = current.components;
      ComponentSpec added = EffectComponent(candidate.evidence.effect);
      added.name = UniqueName(components, added.name);
      components.push_back(added);
      seed += 1;
      FittedModel refit = FitModel(std::move(components), data, scales, seed, options.budget);
      candidate.refitted = true;
      candidate.e2 = refit.fit.error.total;
      candidate.bic = refit.bic;
      candidate.bic_current = InformationCriterion(current.fit.error.total, refit.effective_samples,
                                                   current.parameters);
      candidate.parameters = refit.parameters;
      say(fmt::format(
          "  + {:<32} evidence {:.3g} (threshold {:.3g}): e^2 = {:.4g} %, BIC gain {:.1f}",
          EffectName(candidate.evidence.effect), candidate.evidence.value,
          candidate.evidence.threshold, 100 * refit.fit.error.total,
          candidate.bic_current - refit.bic));
      // Against the current model at the refit's effective sample count; the best is the one
      // that lowers BIC most.
      const double gain = candidate.bic_current - refit.bic;
      if (gain >= options.bic_margin &&
          (best < 0 || gain > candidates[best].bic_current - candidates[best].bic)) {
        best = static_cast<int>(c);
        best_model = std::move(refit);
      }
    }
    if (best < 0) {
      const bool any_supported = std::any_of(candidates.begin(), candidates.end(),
                                             [](const auto& c) { return c.evidence.Supported(); });
      diagnosis.stop_reason =
          any_supported ? fmt::format("no candidate lowers BIC by {:g} or more", options.bic_margin)
                        : "no detector finds evidence of a missing effect";
      diagnosis.last_candidates = std::move(candidates);
      break;
    }
    DiagnosisStep step;
    step.effect = candidates[best].evidence.effect;
    step.evidence = candidates[best].evidence;
    step.e2_before = e2;
    step.e2_after = best_model.fit.error.total;
    step.bic_before = candidates[best].bic_current;
    step.bic_after = best_model.bic;
    step.added = best_model.components.back();
    step.added_parameters = best_model.fit.mathematical.back();
    step.candidates = std::move(candidates);
    say(fmt::format("step {}: {} (e^2 {:.4g} % -> {:.4g} %)", diagnosis.steps.size() + 1,
                    EffectName(step.effect), 100 * step.e2_before, 100 * step.e2_after));
    remaining.erase(std::find(remaining.begin(), remaining.end(), step.effect));
    diagnosis.steps.push_back(std::move(step));
    current = std::move(best_model);
  }
  diagnosis.final_model = std::move(current);
  diagnosis.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return diagnosis;
}

}  // namespace isolab::diagnosis
