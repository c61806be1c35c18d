#include "isolab/analysis/run_report.h"

#include <algorithm>
#include <array>

#include "isolab/analysis/summary_peaks.h"

namespace isolab::analysis {
namespace {

// "index" (the isolator, story or level, from 0) only where the peak has one, as in the HDF5
// results.
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

nlohmann::json ModesJson(const std::vector<Mode>& modes) {
  nlohmann::json json = nlohmann::json::array();
  for (const Mode& mode : modes) {
    json.push_back({{"period", mode.period}, {"direction", mode.direction}});
  }
  return json;
}

nlohmann::json RecordJson(const io::AppliedRecord& r, double g) {
  return {{"record", r.path},
          {"scale", r.scale},
          {"scaled_to", r.scaled_to},
          {"record_units", r.units},
          {"record_units_source", r.units_source},
          {"record_dt", r.dt},
          {"pga", r.pga},
          {"pga_g", r.pga / g}};
}

}  // namespace

nlohmann::json RunReport(const Problem& problem, const model::AnalysisSection& analysis,
                         const Summary& summary) {
  const UnitSystem& units = problem.units();
  const ResponsePeaks& peaks = summary.peaks;
  const ModelSummary& m = problem.summary;
  const structure::Layout& layout = problem.layout;
  const double g = units.Convert(1.0, "g", dimension::kAcceleration);
  nlohmann::json json;
  json["model"] = problem.model.path;
  json.update(RecordJson(problem.records.empty() ? io::AppliedRecord{} : problem.records[0], g));
  if (problem.records.size() > 1) json["h2"] = RecordJson(problem.records[1], g);
  if (problem.vertical_record) json["v"] = RecordJson(*problem.vertical_record, g);
  if (const std::optional<double> angle = problem.IncidenceAngle()) json["angle"] = *angle;
  json["dt"] = problem.grid.dt;
  json["steps"] = problem.grid.steps;
  json["excitation_end"] = problem.excitation_end;
  json["free_vibration"] = problem.free_vibration;
  json["units"] = {{"force", units.force()}, {"length", units.length()}, {"time", units.time()}};
  json["model_summary"] = {{"total_mass", m.total_mass},
                           {"total_weight", m.total_weight},
                           {"fixed_base_periods", m.FixedBasePeriods()},
                           {"fixed_base_modes", ModesJson(m.fixed_base_modes)}};
  json["warnings"] = summary.warnings;
  json["peaks"] = nlohmann::json::object();
  for (const NamedPeak& p : SummaryPeaks(layout, peaks)) json["peaks"][p.name] = PeakJson(*p.peak);
  if (!layout.stories.empty()) {
    json["peaks"]["story_drift_ratio"] = peaks.story_drift_ratio;
    json["peaks"]["largest_drift_ratio"] = peaks.largest_drift_ratio;
  }
  if (layout.isolated()) {  // a fixed base has no isolators, and no isolated modes
    json["model_summary"].update({{"trial_displacement", m.trial_displacement},
                                  {"secant_stiffness", m.secant_stiffness},
                                  {"isolated_period", m.isolated_period},
                                  {"rigid_modes", ModesJson(m.rigid_modes)},
                                  {"isolated_modes", ModesJson(m.isolated_modes)}});
    if (const std::optional<SecantIsolation> at = IsolationAtPeak(problem, peaks)) {
      json["at_peak_displacement"] = {{"secant_stiffness", at->stiffness}, {"period", at->period}};
    }
  }
  if (layout.rotations && layout.isolated()) {
    json["torsional_amplification"] = peaks.torsional_amplification;
  }
  if (layout.isolated()) {
    json["residual_isolator_displacement"] = peaks.residual_isolator_displacement;
    json["residual_oscillation"] = peaks.residual_oscillation;
    json["isolator_displacement_at_excitation_end"] = peaks.isolator_displacement_at_excitation_end;
    nlohmann::json isolators = nlohmann::json::object();
    for (std::size_t i = 0; i < layout.isolators.size(); ++i) {
      isolators[layout.isolators[i].name] = {
          {"displacement", PeakJson(peaks.isolator_displacements[i])},
          {"force", PeakJson(peaks.isolator_forces[i])},
          {"residual", peaks.isolator_residuals[i]}};
    }
    json["isolators"] = isolators;
  }
  for (std::size_t i = 0; i < peaks.capacity_used.size(); ++i) {
    const std::array<double, 4>& used = peaks.capacity_used[i];
    if (std::all_of(used.begin(), used.end(), [](double x) { return x == 0.0; })) continue;
    json["isolators"][layout.isolators[i].name]["capacity_used"] = used;
    json["isolators"][layout.isolators[i].name]["first_stop"] = peaks.first_stop_times[i];
  }
  for (std::size_t i = 0; i < peaks.regimes_at_peak.size(); ++i) {
    if (!peaks.regimes_at_peak[i]) continue;
    json["isolators"][layout.isolators[i].name]["regime_at_peak"] =
        std::string(hysteresis::PendulumRegimeName(*peaks.regimes_at_peak[i]));
  }
  const structure::AxialLoads& axial = problem.structure.axial_loads();
  for (std::size_t j = 0; j < peaks.axial_load_minima.size(); ++j) {
    json["axial_loads"][axial.bearings[j].name] = {
        {"static", axial.bearings[j].static_load},
        {"minimum", PeakJson(peaks.axial_load_minima[j])},
        {"maximum", PeakJson(peaks.axial_load_maxima[j])},
        {"uplift_duration", peaks.uplift_durations[j]},
        {"first_uplift", peaks.first_uplift_times[j]}};
  }
  if (peaks.rows > 0) {
    const integrators::Energies& e = peaks.energies;
    json["energy"] = {{"input", e.input},
                      {"kinetic", e.kinetic},
                      {"damping", e.damping},
                      {"elastic", e.elastic},
                      {"hysteretic", e.hysteretic}};
    if (!axial.empty()) json["energy"]["axial"] = e.axial;
  }
  const integrators::RunSummary& run = summary.run;
  json["termination"] = run.ok() ? "completed" : "failed";
  json["message"] = run.message;
  json["energy_balance_error"] = run.energy_balance_error;
  json["integrator"] = DescribeIntegrator(analysis, problem.grid.dt);
  json[analysis.integrator == model::AnalysisSection::Integrator::kIda ? "ida" : "newton"] =
      IntegratorStatistics(analysis, run);
  json["steps_completed"] = run.steps;
  json["wall_seconds"] = run.wall_seconds;
  if (!summary.results_path.empty()) json["results"] = summary.results_path;
  return json;
}

}  // namespace isolab::analysis
