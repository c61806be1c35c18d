#include "isolab/building/building_diagnosis.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "isolab/core/errors.h"
#include "isolab/diagnosis/discrepancy.h"
#include "isolab/hysteresis/law_parameters.h"

namespace isolab::building {
namespace {

// Each motion's isolator loop: the slab's displacement relative to the table against the force
// one bearing carries, minus the sum of the fitted masses times the measured accelerations over
// the bearings.
identification::FitData Loops(const model::ModelFile& fitted,
                              const std::vector<BuildingMotion>& motions, bool sequential) {
  const std::vector<double> masses = LevelMasses(fitted);
  const double bearings = fitted.isolation_count.value_or(1);
  std::vector<identification::CyclicTestData> tests;
  for (const BuildingMotion& motion : motions) {
    const BuildingMeasurements& measured = motion.measured;
    if (!measured.applied_force.empty()) {
      throw InputError({motion.name},
                       "a force-driven test: diagnose its displacement and force as a cyclic "
                       "test (isolab diagnose --base), not as a building's motion");
    }
    for (std::size_t l = 0; l < masses.size(); ++l) {
      if (l >= measured.acceleration.size() ||
          measured.acceleration[l].size() != measured.time.size()) {
        throw InputError({motion.name},
                         fmt::format("level {} has no measured acceleration: the isolator's force "
                                     "is reconstructed from every level's",
                                     l + 1));
      }
    }
    identification::CyclicTestData& test = tests.emplace_back();
    test.name = motion.name;
    test.time = measured.time;
    test.displacement = measured.displacement.front();
    test.force = BaseShear(measured.acceleration, masses);
    for (double& f : test.force) f /= bearings;
    identification::Segment(&test);
    if (test.half_cycles.empty()) {
      throw InputError({motion.name},
                       "the slab's displacement has no half-cycle between two "
                       "reversals: no loop to diagnose");
    }
  }
  return diagnosis::AllCycles(std::move(tests), sequential);
}

std::vector<identification::ComponentSpec> ComponentsOf(const model::ModelFile& model) {
  std::vector<identification::ComponentSpec> components;
  for (const auto& component : model.isolation.components()) {
    components.push_back({component.name, component.parameters.type(), {}, {}, {}});
  }
  return components;
}

// The parameters of the refit: the specification's (an isolation key started where the loops'
// diagnosis left it, in the default range about it) and every non-zero key of the added
// components.
std::vector<FittedParameterSpec> RefitParameters(const model::ModelFile& diagnosed,
                                                 const BuildingFitSpec& spec,
                                                 const std::vector<std::string>& added) {
  std::vector<FittedParameterSpec> parameters;
  for (const FittedParameterSpec& p : spec.parameters) {
    if (p.name.rfind("isolation.", 0) != 0) {
      parameters.push_back({p.name, p.low, p.high, {}});
      continue;
    }
    try {
      analysis::ParameterValue(diagnosed,
                               p.name);  // a component the diagnosis simplified may lack it
      parameters.push_back({p.name, {}, {}, {}});
    } catch (const InputError&) {
    }
  }
  for (const auto& component : diagnosed.isolation.components()) {
    if (std::find(added.begin(), added.end(), component.name) == added.end()) continue;
    const auto form = hysteresis::ParameterForm::kMathematical;
    const auto keys = hysteresis::ParameterKeys(component.parameters.type(), form);
    const std::vector<double> values = component.parameters.Values(form);
    for (std::size_t k = 0; k < keys.size(); ++k) {
      if (!(std::abs(values[k]) > 0.0)) continue;  // omitted, or a zero no range scales
      parameters.push_back({fmt::format("isolation.{}.{}", component.name, keys[k]), {}, {}, {}});
    }
  }
  return parameters;
}

}  // namespace

BuildingDiagnosis DiagnoseBuilding(const model::ModelFile& model,
                                   const std::vector<BuildingMotion>& motions,
                                   const BuildingFitSpec& spec,
                                   const identification::FitOptions& fit,
                                   const diagnosis::DiagnoseOptions& options) {
  options.Validate();
  const auto say = [&](const std::string& line) {
    if (options.progress) options.progress(line);
  };
  // The isolation is derived again from its loops, every component refitted there: a value
  // given from outside the data could not be held through that. The structure's priors hold in
  // both building fits.
  for (const PriorSpec& prior : spec.priors) {
    if (prior.name.rfind("isolation.", 0) == 0) {
      throw InputError({model.path},
                       fmt::format("prior '{}': the building's diagnosis derives the isolation "
                                   "again from its loops, refitting every component, so a value "
                                   "given for one cannot be held; give priors on the structure "
                                   "only, or fit the building (isolab fit --building) with it",
                                   prior.name));
    }
  }
  BuildingDiagnosis result;
  result.base = FitBuilding(model, motions, spec, fit);
  result.base_parameters = int(spec.parameters.size());
  say(fmt::format("building fitted with its own isolation: mean NRMSE^2 {:.4g} -> {:.4g}",
                  result.base.objective_start, result.base.objective));
  result.loops = Loops(result.base.fitted, motions, spec.sequential);
  try {
    result.isolator = diagnosis::Diagnose(ComponentsOf(result.base.fitted), result.loops, options);
  } catch (const std::invalid_argument& error) {
    throw InputError({model.path}, error.what());
  }
  for (const diagnosis::DiagnosisStep& step : result.isolator.steps) {
    result.added.push_back(step.added.name);
  }
  if (result.added.empty()) {
    result.conclusion = fmt::format(
        "the isolator's loops, reconstructed with the fitted masses, name no effect ({}); the "
        "building keeps its isolation",
        result.isolator.stop_reason);
    return result;
  }

  model::ModelFile diagnosed = result.base.fitted;
  diagnosed.isolation = diagnosis::AssemblyOf(result.isolator.final_model, result.loops);
  BuildingFitSpec refit = spec;
  refit.parameters = RefitParameters(diagnosed, spec, result.added);
  result.refit_parameters = int(refit.parameters.size());
  std::vector<std::string> effects;
  for (const diagnosis::DiagnosisStep& step : result.isolator.steps) {
    effects.push_back(fmt::format("{} ({})", diagnosis::EffectName(step.effect), step.added.name));
  }
  say(
      fmt::format("the loops name {}; the building refitted with the diagnosed isolation ({} "
                  "parameters)",
                  fmt::join(effects, ", "), refit.parameters.size()));
  result.refit = FitBuilding(diagnosed, motions, refit, fit);

  result.samples = std::min(result.base.effective_samples, result.refit->effective_samples);
  const double n = std::max(result.samples, 2.0), ln_n = std::log(n);
  result.bic_base = n * std::log(result.base.objective) + result.base_parameters * ln_n;
  result.bic_refit = n * std::log(result.refit->objective) + result.refit_parameters * ln_n;
  const double gain = result.bic_base - result.bic_refit;
  result.confirmed = gain >= options.bic_margin;
  result.conclusion =
      result.confirmed
          ? fmt::format(
                "the building confirms it: mean NRMSE^2 {:.4g} -> {:.4g}, BIC lower by "
                "{:.1f} (margin {:g}) at {:.0f} effective samples",
                result.base.objective, result.refit->objective, gain, options.bic_margin, n)
          : fmt::format(
                "the building does not confirm it: mean NRMSE^2 {:.4g} -> {:.4g}, BIC "
                "lower by {:.1f} against the margin {:g} at {:.0f} effective samples; "
                "what the loops show is not an effect of the device the floor responses "
                "bear out, and the building keeps its isolation",
                result.base.objective, result.refit->objective, gain, options.bic_margin, n);
  return result;
}

}  // namespace isolab::building
