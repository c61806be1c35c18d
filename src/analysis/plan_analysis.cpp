#include "isolab/analysis/plan_analysis.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "isolab/analysis/analysis_setup.h"
#include "isolab/analysis/model_summary.h"
#include "isolab/core/errors.h"
#include "isolab/hysteresis/plan_rate_form.h"
#include "isolab/hysteresis/rate_form.h"
#include "isolab/integrators/ida.h"

namespace isolab::analysis {
namespace {

using hysteresis::Vec2;

// One component read in the model's units, its file relative to the model's folder.
io::AppliedRecord ReadComponent(const model::PlanModelFile& model,
                                model::GroundMotionSection motion, const std::string& key,
                                std::optional<double> scale,
                                integrators::SampledHistory* acceleration) {
  if (std::filesystem::path(motion.file).is_relative()) {
    motion.file =
        (std::filesystem::path(model.path).parent_path() / motion.file).lexically_normal().string();
  }
  if (scale) motion.scale = *scale;
  const std::string where = fmt::format(" in {}", model.path);
  return ApplyRecord(motion, "excitation.ground_motion." + key + ".units" + where,
                     "excitation.ground_motion." + key + ".dt" + where, model.units, acceleration);
}

// IDA integrates the laws' rate forms: a law without one (a degrading BHM2, alone or in an
// uncoupled pair) is refused before the run, naming where it is.
void RequireRateForms(const structure::PlanStructure& structure) {
  const auto refuse = [](const std::string& where) {
    throw InputError({"integrator ida"},
                     fmt::format("cannot run {} (a degrading_bhm2 component: the law has no rate "
                                 "form yet); run it with Newmark (analysis.integrator: newmark, or "
                                 "--integrator newmark)",
                                 where));
  };
  for (const structure::PlanMember& member : structure.members()) {
    for (const auto& kernel : member.assembly.kernels()) {
      if (!hysteresis::HasRateForm(kernel)) refuse("member '" + member.name + "'");
    }
  }
  for (const structure::PlanIsolator& isolator : structure.isolators()) {
    for (const auto& kernel : isolator.assembly.kernels()) {
      if (!hysteresis::HasPlanRateForm(kernel)) refuse("isolator '" + isolator.name + "'");
    }
  }
}

}  // namespace

PlanAnalysisSetup PreparePlanAnalysis(const model::PlanModelFile& model,
                                      const PlanOverrides& overrides) {
  if (!model.ground_motion) {
    throw InputError({model.path}, "no excitation: give excitation.ground_motion.h1 (and h2)");
  }
  std::optional<structure::PlanStructure> structure;
  try {
    structure = structure::BuildPlanBuilding(model.building);
  } catch (const std::invalid_argument& error) {
    throw InputError({model.path}, fmt::format("plan.{}", error.what()));
  }
  PlanAnalysisSetup setup{std::move(*structure), {}, {}, {}, {}, model.ground_motion->angle};
  const model::PlanGroundMotion& motion = *model.ground_motion;

  integrators::SampledHistory h1, h2;
  setup.h1 = ReadComponent(model, motion.h1, "h1", overrides.scale, &h1);
  if (motion.h2) {
    setup.h2 = ReadComponent(model, *motion.h2, "h2", overrides.scale, &h2);
    if (std::abs(h2.dt - h1.dt) > 1e-9 * h1.dt) {
      throw InputError(motion.h2_location,
                       fmt::format("excitation.ground_motion.h2: its step {:g} differs from "
                                   "h1's {:g}; a pair must share one step",
                                   h2.dt, h1.dt));
    }
    if (h2.values.size() != h1.values.size()) {
      throw InputError(motion.h2_location,
                       fmt::format("excitation.ground_motion.h2: {} samples, h1 has {}; a pair "
                                   "must have the same length",
                                   h2.values.size(), h1.values.size()));
    }
  } else {
    h2 = {h1.dt, std::vector<double>(h1.values.size(), 0.0)};
  }
  const double angle = motion.angle * std::numbers::pi / 180.0;
  const double c = std::cos(angle), s = std::sin(angle);
  setup.excitation.x = {h1.dt, {}};
  setup.excitation.y = {h1.dt, {}};
  for (std::size_t k = 0; k < h1.values.size(); ++k) {
    setup.excitation.x.values.push_back(c * h1.values[k] - s * h2.values[k]);
    setup.excitation.y.values.push_back(s * h1.values[k] + c * h2.values[k]);
  }

  const double record_dt = h1.dt;
  const double dt = overrides.dt.value_or(model.analysis.dt > 0.0 ? model.analysis.dt : record_dt);
  if (!(dt > 0.0)) throw InputError({"command line"}, fmt::format("--dt {:g} must be > 0", dt));
  if (dt > record_dt * (1.0 + 1e-9)) {
    throw InputError({overrides.dt ? "command line" : model.path},
                     fmt::format("dt = {:g} is coarser than the records' {:g}; the analysis step "
                                 "may only refine it",
                                 dt, record_dt));
  }

  // The isolated period: the whole mass as a rigid block on every isolator pushed along x.
  const Eigen::VectorXd& mass = setup.structure.mass();
  for (Eigen::Index i = 0; i < mass.size(); i += structure::kPlanDofsPerFloor) {
    setup.total_mass += mass[i];
  }
  setup.trial_displacement = overrides.trial_displacement.value_or(
      model.units.Convert(kDefaultTrialDisplacement, "m", dimension::kLength));
  const double k = SecantStiffness(model.isolation_along_x, setup.trial_displacement);
  setup.isolated_period = k > 0.0 ? 2.0 * std::numbers::pi * std::sqrt(setup.total_mass / k) : 0.0;

  setup.excitation_end = setup.excitation.duration();
  const model::FreeVibration choice =
      overrides.free_vibration.value_or(model.analysis.free_vibration);
  double duration = model.analysis.duration;
  if (duration > 0.0) {
    setup.free_vibration = std::max(0.0, duration - setup.excitation_end);
  } else {
    setup.free_vibration =
        choice.automatic ? kAutomaticFreeVibrationPeriods * setup.isolated_period : choice.duration;
    duration = setup.excitation_end + setup.free_vibration;
  }
  setup.grid = StepGrid(dt, duration, overrides.max_steps, overrides.dt ? "--dt" : model.path);
  return setup;
}

integrators::RunSummary RunPlanAnalysis(const model::AnalysisSection& analysis,
                                        const PlanAnalysisSetup& setup,
                                        integrators::ResponseHistory* response) {
  if (analysis.integrator == model::AnalysisSection::Integrator::kIda) {
    RequireRateForms(setup.structure);
    return integrators::RunIda(setup.structure, setup.excitation, setup.grid, analysis.ida,
                               response);
  }
  return integrators::RunNewmark(setup.structure, setup.excitation, setup.grid, analysis.newmark,
                                 response);
}

PlanPeaks ComputePlanPeaks(const PlanAnalysisSetup& setup,
                           const integrators::ResponseHistory& response) {
  const structure::PlanStructure& s = setup.structure;
  const std::size_t isolators = s.isolators().size();
  PlanPeaks peaks;
  // Indices set before any peak: a response that stays at rest still names its isolators.
  for (std::size_t i = 0; i < isolators; ++i) {
    peaks.isolator_resultant.push_back({0.0, 0.0, static_cast<int>(i)});
  }
  for (int f = 0; f < s.floors(); ++f) peaks.floor_rotation.push_back({0.0, 0.0, f});
  const auto consider = [](Peak* peak, double value, double t, int index) {
    if (std::abs(value) > peak->value) *peak = {std::abs(value), t, index};
  };
  for (int row = 0; row < response.rows_written; ++row) {
    const double t = response.time[row];
    const std::span<const double> u(response.displacement.row(row).data(), s.dofs());
    for (std::size_t i = 0; i < isolators; ++i) {
      consider(&peaks.isolator_resultant[i], Norm(s.IsolatorDeformation(i, u)), t,
               static_cast<int>(i));
    }
    consider(&peaks.centre_resultant, Norm(Vec2{u[0], u[1]}), t, 0);
    for (int f = 0; f < s.floors(); ++f) {
      consider(&peaks.floor_rotation[f], u[structure::kPlanDofsPerFloor * f + 2], t, f);
    }
    Vec2 shear;
    for (std::size_t i = 0; i < isolators; ++i) {
      const std::size_t column = s.isolator_force_column(i);
      shear = shear + Vec2{response.connection_force(row, column),
                           response.connection_force(row, column + 1)};
    }
    consider(&peaks.base_shear, Norm(shear), t, 0);
  }
  for (const Peak& peak : peaks.isolator_resultant) {
    if (peak.value >= peaks.largest_resultant.value) peaks.largest_resultant = peak;
  }
  // The first floor of the largest: a building at rest names its base.
  for (const Peak& peak : peaks.floor_rotation) {
    if (peak.value > peaks.largest_floor_rotation.value) peaks.largest_floor_rotation = peak;
  }
  if (peaks.centre_resultant.value > 0.0) {
    peaks.torsional_amplification = peaks.largest_resultant.value / peaks.centre_resultant.value;
  }
  return peaks;
}

}  // namespace isolab::analysis
