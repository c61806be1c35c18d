#include "isolab/analysis/run_report.h"

#include "isolab/analysis/run_analysis.h"

namespace isolab::analysis {
namespace {

// "index" (the DOF or story, from 0) only where the peak has one, as in the HDF5 results.
nlohmann::json PeakJson(const Peak& peak) {
  nlohmann::json json = {{"value", peak.value}, {"time", peak.time}};
  if (peak.index >= 0) json["index"] = peak.index;
  return json;
}

nlohmann::json IntegratorStatistics(const model::AnalysisSection& analysis,
                                    const integrators::RunSummary& summary) {
  if (analysis.integrator == model::AnalysisSection::Integrator::kIda) {
    return {{"steps", summary.ida_steps},
            {"events", summary.events},
            {"jacobian_evaluations", summary.jacobian_evaluations},
            {"error_test_failures", summary.error_test_failures}};
  }
  return {{"iterations", summary.newton_iterations},
          {"solves_per_step", summary.SolvesPerStep()},
          {"max_iterations_in_a_step", summary.max_iterations_in_a_step},
          {"factorisations", summary.factorisations},
          {"step_cuts", summary.step_cuts}};
}

}  // namespace

void AddRunOutcome(const model::AnalysisSection& analysis, double dt,
                   const integrators::RunSummary& summary, const std::string& output,
                   nlohmann::json* json) {
  nlohmann::json& j = *json;
  j["termination"] = summary.ok() ? "completed" : "failed";
  j["message"] = summary.message;
  j["energy_balance_error"] = summary.energy_balance_error;
  j["integrator"] = DescribeIntegrator(analysis, dt);
  j[analysis.integrator == model::AnalysisSection::Integrator::kIda ? "ida" : "newton"] =
      IntegratorStatistics(analysis, summary);
  j["steps_completed"] = summary.steps;
  j["wall_seconds"] = summary.wall_seconds;
  if (!output.empty()) j["results"] = output;
}

nlohmann::json RunReport(const RunDescription& run, const std::vector<std::string>& warnings,
                         const std::string& output) {
  const model::ModelFile& model = *run.model;
  const AnalysisSetup& setup = *run.setup;
  const ResponsePeaks& peaks = *run.peaks;
  const io::AppliedRecord& r = setup.record;
  const ModelSummary& m = setup.summary;
  const double g = model.units.Convert(1.0, "g", dimension::kAcceleration);
  nlohmann::json json;
  json["model"] = model.path;
  json["record"] = r.path;
  json["scale"] = r.scale;
  json["record_units"] = r.units;
  json["record_units_source"] = r.units_source;
  json["record_dt"] = r.dt;
  json["pga"] = r.pga;
  json["pga_g"] = r.pga / g;
  json["dt"] = setup.grid.dt;
  json["steps"] = setup.grid.steps;
  json["excitation_end"] = setup.excitation_end;
  json["free_vibration"] = setup.free_vibration;
  json["units"] = {{"force", model.units.force()},
                   {"length", model.units.length()},
                   {"time", model.units.time()}};
  json["model_summary"] = {{"total_mass", m.total_mass},
                           {"total_weight", m.total_weight},
                           {"fixed_base_periods", m.fixed_base_periods},
                           {"trial_displacement", m.trial_displacement},
                           {"secant_stiffness", m.secant_stiffness},
                           {"isolated_period", m.isolated_period}};
  json["warnings"] = warnings;
  json["peaks"] = {{"isolator_displacement", PeakJson(peaks.isolator_displacement)},
                   {"isolator_force", PeakJson(peaks.isolator_force)},
                   {"base_shear", PeakJson(peaks.base_shear)},
                   {"first_story_shear", PeakJson(peaks.first_story_shear)},
                   {"roof_absolute_acceleration", PeakJson(peaks.roof_absolute_acceleration)},
                   {"story_drift", PeakJson(peaks.story_drift)},
                   {"story_drift_ratio", peaks.story_drift_ratio}};
  if (setup.layout.isolation >= 0) {
    json["residual_isolator_displacement"] = peaks.residual_isolator_displacement;
    json["residual_oscillation"] = peaks.residual_oscillation;
    json["isolator_displacement_at_excitation_end"] = peaks.isolator_displacement_at_excitation_end;
  }
  if (peaks.rows > 0) {
    const integrators::Energies& e = peaks.energies;
    json["energy"] = {{"input", e.input},
                      {"kinetic", e.kinetic},
                      {"damping", e.damping},
                      {"elastic", e.elastic},
                      {"hysteretic", e.hysteretic}};
  }
  AddRunOutcome(*run.analysis, setup.grid.dt, *run.summary, output, &json);
  return json;
}

}  // namespace isolab::analysis
