#include "isolab/diagnosis/diagnose.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "isolab/core/errors.h"

namespace isolab::diagnosis {
namespace {

using identification::ComponentSpec;
using identification::ModelParametrisation;

// Fits `components`, starting every coordinate that a previous fit knows from its value there;
// drops the components the fit gave no stiffness; returns the model and its residual.
struct Fitted {
  FittedModel model;
  hysteresis::ParallelAssembly assembly;
};
Fitted FitModel(std::vector<ComponentSpec> components, const identification::FitData& data,
                const identification::DataScales& scales, unsigned seed,
                const DiagnoseOptions& options) {
  Fitted result;
  FittedModel& model = result.model;
  const ModelParametrisation parametrisation(components, scales);
  identification::FitOptions fit;
  fit.seed = seed;
  fit.budget = options.budget;
  fit.threads = options.threads;
  fit.spread = options.spread;
  model.fit = identification::Fit(parametrisation, data, fit);
  // A component the fit gave no stiffness carries no force: dropped, e^2 unchanged. The base's
  // last component stays, so a model is never empty.
  std::vector<std::size_t> zero =
      identification::ZeroComponents(parametrisation, model.fit.amplitudes);
  if (zero.size() == components.size()) zero.pop_back();
  for (const std::size_t c : zero) {
    model.dropped.push_back(fmt::format(
        "{} ({}) was dropped: the fit gave it no stiffness, so the data need no such component",
        components[c].name, hysteresis::LawName(components[c].type)));
  }
  if (!zero.empty()) {
    components = identification::DropComponents(parametrisation, zero, &model.fit);
  }
  const ModelParametrisation kept(components, scales);
  model.parameters = kept.dimension() + kept.amplitude_count();
  // Record the fitted shape as start values, so a refit with one more component begins here.
  const auto shapes = kept.ShapeValues(model.fit.point);
  for (std::size_t c = 0; c < components.size(); ++c) {
    const auto names = identification::CoordinateNames(components[c].type);
    for (std::size_t k = 0; k < names.size(); ++k) {
      if (!components[c].fixed.count(names[k])) components[c].start[names[k]] = shapes[c][k];
    }
  }
  model.components = std::move(components);
  result.assembly = kept.Assembly(model.fit.point, model.fit.amplitudes);
  return result;
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

void DiagnoseOptions::Validate() const {
  if (budget < 100) throw InvalidParameter({"budget", double(budget), "must be >= 100"});
  if (threads < 0 || threads > 1024) {
    throw InvalidParameter({"threads", double(threads),
                            "must be 0 (every hardware thread) or "
                            "in [1, 1024]"});
  }
  if (!(bic_margin > 0.0)) throw InvalidParameter({"bic_margin", bic_margin, "must be > 0"});
  if (!(noise_margin >= 1.0)) {
    throw InvalidParameter({"noise_margin", noise_margin, "must be >= 1"});
  }
  if (!(equal_bic >= 0.0)) throw InvalidParameter({"equal_bic", equal_bic, "must be >= 0"});
  if (!(min_closure >= 0.0 && min_closure < 1.0)) {
    throw InvalidParameter({"min_closure", min_closure, "must be in [0, 1)"});
  }
  const int catalogue = static_cast<int>(AllEffects().size());
  if (max_steps < 0 || max_steps > catalogue) {
    throw InvalidParameter({"max_steps", double(max_steps),
                            fmt::format("must be in [0, {}] (the catalogue's size)", catalogue)});
  }
}

std::string_view StopReasonName(StopReason reason) {
  switch (reason) {
    case StopReason::kAtNoiseFloor:
      return "at_noise_floor";
    case StopReason::kMaxSteps:
      return "max_steps";
    case StopReason::kNoEvidence:
      return "no_evidence";
    case StopReason::kNoBicGain:
      return "no_bic_gain";
    case StopReason::kRefused:
      return "refused";
  }
  return "?";
}

hysteresis::ParallelAssembly AssemblyOf(const FittedModel& model,
                                        const identification::FitData& data) {
  return ModelParametrisation(model.components, identification::ScalesOf(data))
      .Assembly(model.fit.point, model.fit.amplitudes);
}

double InformationCriterion(double e2, double samples, int parameters) {
  const double n = std::max(samples, 2.0);
  return n * std::log(std::max(e2, 1e-300) / n) + parameters * std::log(n);
}

namespace {

void Say(const DiagnoseOptions& options, const std::string& line) {
  if (options.progress) options.progress(line);
}

// The residual of a fitted model, and from it the model's effective samples and BIC.
Discrepancy Evaluate(Fitted* fitted, const identification::FitData& data,
                     const std::vector<NoiseEstimate>& force_noise) {
  const Discrepancy d = Discrepancy::Of(fitted->assembly, data, &force_noise);
  fitted->model.effective_samples = EffectiveSamples(d);
  fitted->model.bic = InformationCriterion(
      fitted->model.fit.error.total, fitted->model.effective_samples, fitted->model.parameters);
  return d;
}

// The current model refitted with a candidate's component added, the candidate judged: refused
// where the fit gave its component no stiffness, the component cancels one already there, or it
// closes too little of the excess of e^2 over the noise floor.
Fitted RefitCandidate(Candidate& candidate, const Fitted& current, double noise_floor,
                      const identification::FitData& data, const identification::DataScales& scales,
                      const std::vector<NoiseEstimate>& force_noise, unsigned seed,
                      const DiagnoseOptions& options) {
  const double e2 = current.model.fit.error.total;
  std::vector<ComponentSpec> components = current.model.components;
  ComponentSpec added = EffectComponent(candidate.evidence.effect);
  added.name = UniqueName(components, added.name);
  for (const auto& [coordinate, value] : candidate.evidence.start) {
    if (!added.fixed.count(coordinate)) added.start[coordinate] = value;
  }
  components.push_back(added);
  Fitted refit = FitModel(std::move(components), data, scales, seed, options);
  Evaluate(&refit, data, force_noise);
  candidate.refitted = true;
  candidate.e2 = refit.model.fit.error.total;
  candidate.bic = refit.model.bic;
  candidate.bic_current =
      InformationCriterion(e2, refit.model.effective_samples, current.model.parameters);
  candidate.parameters = refit.model.parameters;
  // The added component, if the fit kept it, against the ones already there.
  const bool kept = refit.model.components.back().name == added.name;
  if (kept && candidate.Gain() >= options.bic_margin) {
    const ModelParametrisation parametrisation(refit.model.components, scales);
    const auto identifiability =
        identification::AssessIdentifiability(parametrisation, data, refit.model.fit);
    for (const auto& pair : identifiability.cancelling) {
      if (pair.b == refit.model.components.size() - 1) candidate.refused = pair.finding;
    }
  } else if (!kept) {
    candidate.refused =
        fmt::format("the refit gave the added {} no stiffness", hysteresis::LawName(added.type));
  }
  const double excess = e2 - noise_floor;
  const double closure = excess > 0.0 ? (e2 - candidate.e2) / excess : 1.0;
  if (candidate.refused.empty() && candidate.Gain() >= options.bic_margin &&
      closure < options.min_closure) {
    candidate.refused = fmt::format(
        "it closes {:.1f} % of the excess of e^2 over the noise floor (less than {:g} %): "
        "the component fits a sliver of a residual it does not explain",
        100 * closure, 100 * options.min_closure);
  }
  Say(options,
      fmt::format(
          "  + {:<32} evidence {:.3g} (threshold {:.3g}): e^2 = {:.4g} %, BIC gain {:.1f}{}",
          EffectName(candidate.evidence.effect), candidate.evidence.value,
          candidate.evidence.threshold, 100 * candidate.e2, candidate.Gain(),
          candidate.refused.empty() ? "" : " (refused: " + candidate.refused + ")"));
  return refit;
}

// Why no candidate was kept: refused, no gain in BIC, or no evidence.
std::pair<StopReason, std::string> WhyNoCandidate(const std::vector<Candidate>& candidates,
                                                  const DiagnoseOptions& options) {
  const bool any_supported = std::any_of(candidates.begin(), candidates.end(),
                                         [](const auto& c) { return c.evidence.Supported(); });
  const bool any_refused = std::any_of(candidates.begin(), candidates.end(), [&](const auto& c) {
    return !c.refused.empty() && c.Gain() >= options.bic_margin;
  });
  if (any_refused) {
    return {StopReason::kRefused,
            fmt::format("every candidate that lowered BIC by {:g} or more was refused (its "
                        "component cancels one already there, or it closes too little of what "
                        "noise does not explain)",
                        options.bic_margin)};
  }
  if (any_supported) {
    return {StopReason::kNoBicGain,
            fmt::format("no candidate lowers BIC by {:g} or more", options.bic_margin)};
  }
  return {StopReason::kNoEvidence, "no detector finds evidence of a missing effect"};
}

}  // namespace

Diagnosis Diagnose(std::vector<ComponentSpec> base, const identification::FitData& data,
                   const DiagnoseOptions& options) {
  options.Validate();
  if (base.empty()) throw std::invalid_argument("the base model has no components");
  const auto start = std::chrono::steady_clock::now();
  const identification::DataScales scales = identification::ScalesOf(data);

  Diagnosis diagnosis;
  diagnosis.samples = SampleCount(data);
  // Each test's noise: the lower of the estimates from its force and from the current model's
  // residual (discrepancy.h). Not the lowest over every fit: each estimate scatters, and the
  // least of many would read below the noise.
  std::vector<NoiseEstimate> force_noise;
  for (const auto& test : data.tests) force_noise.push_back(EstimateForceNoise(test));
  const auto residual_of = [&](const hysteresis::ParallelAssembly& assembly) {
    return Discrepancy::Of(assembly, data, &force_noise);
  };
  const auto set_floor = [&](const Discrepancy& d) {
    diagnosis.noise = d.noise;
    std::vector<double> sigma;
    for (const NoiseEstimate& n : diagnosis.noise) sigma.push_back(n.sigma);
    diagnosis.noise_floor = NoiseFloor(data, sigma);
  };

  unsigned seed = options.seed;
  Fitted current = FitModel(std::move(base), data, scales, seed, options);
  set_floor(Evaluate(&current, data, force_noise));
  diagnosis.base = current.model;
  Say(options, fmt::format("base model: e^2 = {:.4g} %, BIC = {:.1f}, {}",
                           100 * diagnosis.base.fit.error.total, diagnosis.base.bic,
                           diagnosis.base.fit.stop_reason));
  std::vector<Effect> remaining(AllEffects().begin(), AllEffects().end());

  while (true) {
    const Discrepancy discrepancy = residual_of(current.assembly);
    set_floor(discrepancy);
    std::vector<Candidate> candidates;
    for (const Effect effect : remaining) candidates.push_back({Detect(effect, discrepancy)});
    std::stable_sort(candidates.begin(), candidates.end(), [](const auto& a, const auto& b) {
      return a.evidence.Strength() > b.evidence.Strength();
    });
    const double e2 = current.model.fit.error.total;
    const auto stop = [&](StopReason reason, std::string why) {
      diagnosis.stop = reason;
      diagnosis.stop_reason = std::move(why);
      diagnosis.last_candidates = std::move(candidates);
    };
    if (e2 <= options.noise_margin * diagnosis.noise_floor) {
      stop(StopReason::kAtNoiseFloor,
           fmt::format("e^2 = {:.4g} % is within {:g} x the noise floor ({:.4g} %): nothing left "
                       "that the measurement noise does not explain",
                       100 * e2, options.noise_margin, 100 * diagnosis.noise_floor));
      break;
    }
    if (static_cast<int>(diagnosis.steps.size()) >= options.max_steps) {
      stop(StopReason::kMaxSteps, fmt::format("{} effects added, the limit", options.max_steps));
      break;
    }
    // Refit every candidate the evidence supports; keep the one that lowers BIC most, the
    // smaller model among gains equal within equal_bic, and none whose component cancels
    // another.
    int best = -1;
    Fitted best_model;
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      Candidate& candidate = candidates[c];
      if (!candidate.evidence.Supported()) continue;
      seed += 1;
      Fitted refit = RefitCandidate(candidate, current, diagnosis.noise_floor, data, scales,
                                    force_noise, seed, options);
      if (candidate.Gain() < options.bic_margin || !candidate.refused.empty()) continue;
      const bool better = best < 0 ||
                          candidate.Gain() > candidates[best].Gain() + options.equal_bic ||
                          (candidate.Gain() >= candidates[best].Gain() - options.equal_bic &&
                           candidate.parameters < candidates[best].parameters);
      if (better) {
        best = static_cast<int>(c);
        best_model = std::move(refit);
      }
    }
    if (best < 0) {
      const auto [reason, why] = WhyNoCandidate(candidates, options);
      stop(reason, why);
      break;
    }
    DiagnosisStep step;
    step.effect = candidates[best].evidence.effect;
    step.evidence = candidates[best].evidence;
    step.e2_before = e2;
    step.e2_after = best_model.model.fit.error.total;
    step.bic_before = candidates[best].bic_current;
    step.bic_after = best_model.model.bic;
    step.added = best_model.model.components.back();
    step.added_parameters = best_model.model.fit.mathematical.back();
    step.candidates = std::move(candidates);
    Say(options, fmt::format("step {}: {} (e^2 {:.4g} % -> {:.4g} %)", diagnosis.steps.size() + 1,
                             EffectName(step.effect), 100 * step.e2_before, 100 * step.e2_after));
    remaining.erase(std::find(remaining.begin(), remaining.end(), step.effect));
    diagnosis.steps.push_back(std::move(step));
    current = std::move(best_model);
  }
  diagnosis.final_model = current.model;
  // The verdict and identifiability on the final model, with its own floor.
  const Discrepancy final_residual = residual_of(current.assembly);
  set_floor(final_residual);
  diagnosis.verdict = JudgeResidual(final_residual, current.model.fit.error.total,
                                    diagnosis.noise_floor, {options.noise_margin});
  diagnosis.identifiability = identification::AssessIdentifiability(
      ModelParametrisation(current.model.components, scales), data, current.model.fit);
  diagnosis.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return diagnosis;
}

}  // namespace isolab::diagnosis
