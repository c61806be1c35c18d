#include "isolab/analysis/run_text.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "isolab/analysis/summary_peaks.h"

namespace isolab::analysis {
namespace {

// The first `count` periods, with their directions where the structure moves in more than one.
std::string JoinModes(const std::vector<Mode>& modes, std::size_t count, bool directions) {
  std::string text;
  for (std::size_t i = 0; i < std::min(count, modes.size()); ++i) {
    text += (i > 0 ? ", " : "") + fmt::format("{:.4g}", modes[i].period);
    if (directions) text += fmt::format(" ({})", modes[i].direction);
  }
  return text;
}

void PrintRecord(const io::AppliedRecord& r, const std::string& label, const UnitSystem& u,
                 std::ostream& out) {
  const double g = u.Convert(1.0, "g", dimension::kAcceleration);
  fmt::print(out, "{}: {} ({}, dt = {:g} s, in {} from {}), {}: PGA {:.4g} g ({:.5g} {})\n", label,
             r.path, r.format, r.dt, r.units,
             r.units_source == "header" ? "its header" : r.units_source, io::DescribeScale(r),
             r.pga / g, r.pga, DescribeUnits(u, dimension::kAcceleration));
}

}  // namespace

void PrintGrid(const integrators::TimeGrid& grid, double excitation_end, double free_vibration,
               int dofs, const UnitSystem& units, std::ostream& out) {
  const std::string time = units.time();
  fmt::print(out,
             "dt = {:g} {}, {} steps ({:.4g} {} of excitation, then {:.4g} {} of free "
             "vibration), {} dofs\n\n",
             grid.dt, time, grid.steps, excitation_end, time, free_vibration, time, dofs);
}

void PrintRunOutcome(const model::AnalysisSection& analysis, const integrators::RunSummary& run,
                     const std::string& output, std::ostream& out) {
  if (std::isnan(run.energy_balance_error)) {
    fmt::print(out, "energy balance error: undefined (the input energy is not finite)\n");
  } else {
    fmt::print(out, "energy balance error: {:.2e} of the input energy\n", run.energy_balance_error);
  }
  if (analysis.integrator == model::AnalysisSection::Integrator::kIda) {
    fmt::print(out,
               "IDA: {} steps, {} phase-change events, {} Jacobians, {} error-test failures; "
               "{:.3f} s\n",
               run.ida_steps, run.events, run.jacobian_evaluations, run.error_test_failures,
               run.wall_seconds);
  } else {
    fmt::print(out,
               "Newton: {} iterations ({:.3f} solves per step, at most {} in a step), {} "
               "factorisations, {} step cuts; {:.3f} s\n",
               run.newton_iterations, run.SolvesPerStep(), run.max_iterations_in_a_step,
               run.factorisations, run.step_cuts, run.wall_seconds);
  }
  if (!output.empty()) fmt::print(out, "results: {}\n", output);
}

void PrintPreamble(const Problem& problem, std::ostream& out) {
  const UnitSystem& u = problem.units();
  const ModelSummary& m = problem.summary;
  const structure::Layout& layout = problem.layout;
  const bool directions = layout.directions > 1 || layout.rotations;
  fmt::print(out, "== {} ==\n", problem.model.path);
  if (!problem.model.description.empty()) fmt::print(out, "{}\n", problem.model.description);
  if (problem.records.size() == 1) PrintRecord(problem.records[0], "record", u, out);
  if (problem.records.size() > 1) {
    PrintRecord(problem.records[0], "record H1", u, out);
    PrintRecord(problem.records[1], "record H2", u, out);
  }
  if (problem.vertical_record) PrintRecord(*problem.vertical_record, "record V", u, out);
  const structure::AxialLoads& axial = problem.structure.axial_loads();
  if (!axial.empty()) {
    const model::AxialLoadSection& asked = *problem.model.axial_load;
    fmt::print(out, "axial loads N(t) of {} pendulum bearings: static share{}{}\n",
               axial.bearings.size(), asked.vertical ? ", vertical component" : "",
               asked.overturning ? ", overturning (Newmark: from the step's start)" : "");
  }
  if (const std::optional<double> angle = problem.IncidenceAngle()) {
    fmt::print(out, "H1 at {:g} degrees from x, H2 at {:g}\n", *angle, *angle + 90.0);
  }
  const double tonnes = m.total_mass * u.SiFactor(dimension::kMass) / 1000.0;
  fmt::print(out, "model: ");
  if (layout.isolators.size() > 1) {
    fmt::print(out, "{} levels, {} isolators, ", layout.levels.size(), layout.isolators.size());
  }
  fmt::print(out, "total weight {:.5g} {} ({:.5g} t)", m.total_weight, u.force(), tonnes);
  if (!m.fixed_base_modes.empty()) {
    fmt::print(out, "; fixed-base periods {} {}{}", JoinModes(m.fixed_base_modes, 3, directions),
               u.time(), m.fixed_base_modes.size() > 3 ? ", ..." : "");
  }
  if (m.isolated) {
    fmt::print(out, "; {}{} {} {} at {:g} {} (secant stiffness {:.4g} {})",
               layout.stories.empty() ? "period" : "isolated period",
               m.rigid_modes.size() > 1 ? "s" : "", JoinModes(m.rigid_modes, 3, directions),
               u.time(), m.trial_displacement, u.length(), m.secant_stiffness,
               DescribeUnits(u, dimension::kStiffness));
  }
  fmt::print(out, "\n");
  PrintGrid(problem.grid, problem.excitation_end, problem.free_vibration, problem.structure.dofs(),
            u, out);
}

void PrintSummary(const Problem& problem, const model::AnalysisSection& analysis,
                  const Summary& summary, std::ostream& out) {
  const UnitSystem& u = problem.units();
  const structure::Layout& layout = problem.layout;
  const ResponsePeaks& peaks = summary.peaks;
  const std::string length = u.length(), force = u.force(), time = u.time();
  const double g = u.Convert(1.0, "g", dimension::kAcceleration);
  // What a line adds after the peak's time.
  const auto note = [&](const NamedPeak& p) -> std::string {
    const int index = p.peak->index;
    switch (p.note) {
      case NamedPeak::Note::kNone:
        return "";
      case NamedPeak::Note::kIsolator:
        return layout.isolators.size() > 1 && index >= 0
                   ? fmt::format(" ({})", layout.isolators[index].name)
                   : "";
      case NamedPeak::Note::kStoryAndRatio:
        if (index < 0) return "";
        return fmt::format(
            " (story {}{})", index + 1,
            peaks.story_drift_ratio > 0.0
                ? fmt::format(", {:.3g} % of its height", 100 * peaks.story_drift_ratio)
                : "");
      case NamedPeak::Note::kLevelAndG:
        return fmt::format(" ({}{:.3g} g)",
                           index >= 0 ? layout.levels[index].name + ", " : std::string(),
                           p.peak->value / g);
      case NamedPeak::Note::kG:
        return fmt::format(" ({:.3g} g)", p.peak->value / g);
      case NamedPeak::Note::kLevel:
        return index >= 0 ? fmt::format(" ({})", layout.levels[index].name) : "";
    }
    return "";
  };
  if (layout.isolators.size() > 1) {
    fmt::print(out, "peak isolator displacement [{}] and force [{}]:\n", length, force);
    for (std::size_t i = 0; i < layout.isolators.size(); ++i) {
      const Peak& d = peaks.isolator_displacements[i];
      fmt::print(out, "  {:<24} {:>12.5g} at t = {:<8.4g} {:>12.5g} at t = {:.4g} {}\n",
                 layout.isolators[i].name, d.value, d.time, peaks.isolator_forces[i].value,
                 peaks.isolator_forces[i].time, time);
    }
  }
  for (const NamedPeak& p : SummaryPeaks(layout, peaks)) {
    fmt::print(out, "{:<34} {:>12.5g} {:<8} at t = {:.4g} {}{}\n", p.label, p.peak->value,
               PeakUnit(u, p.dimension), p.peak->time, time, note(p));
  }
  for (std::size_t i = 0; i < peaks.regimes_at_peak.size(); ++i) {
    if (!peaks.regimes_at_peak[i]) continue;
    const std::string label = layout.isolators.size() > 1
                                  ? "triple pendulum regime " + layout.isolators[i].name
                                  : std::string("triple pendulum regime");
    fmt::print(out, "{:<34} {:>12} {:<8} at its peak displacement, t = {:.4g} {}\n", label,
               hysteresis::PendulumRegimeName(*peaks.regimes_at_peak[i]), "",
               peaks.isolator_displacements[i].time, time);
  }
  if (layout.rotations && layout.isolated()) {
    fmt::print(out,
               "{:<34} {:>12.4g} (the largest isolator displacement over the peak base "
               "centre displacement)\n",
               "torsional amplification", peaks.torsional_amplification);
  }
  const structure::AxialLoads& axial = problem.structure.axial_loads();
  for (std::size_t j = 0; j < peaks.axial_load_minima.size(); ++j) {
    fmt::print(out, "{:<34} {:>12.5g} {:<8} at t = {:.4g} {} (static {:.5g}{})\n",
               "least axial load " + axial.bearings[j].name, peaks.axial_load_minima[j].value,
               problem.units().force(), peaks.axial_load_minima[j].time, time,
               axial.bearings[j].static_load,
               peaks.uplift_durations[j] > 0.0 || peaks.first_uplift_times[j] >= 0.0
                   ? fmt::format("; uplift for {:.4g} {} from t = {:.4g}",
                                 peaks.uplift_durations[j], time, peaks.first_uplift_times[j])
                   : std::string());
  }
  if (layout.isolated()) {
    fmt::print(out, "{:<34} {:>12.5g} {:<8} ", "residual isolator displacement",
               peaks.residual_isolator_displacement, length);
    if (problem.free_vibration > 0.0) {
      fmt::print(out, "after {:.4g} {} of free vibration (still swinging +-{:.3g} {})",
                 problem.free_vibration, time, peaks.residual_oscillation, length);
    }
    fmt::print(out, "\n{:<34} {:>12.5g} {}\n", "  at the end of the excitation",
               peaks.isolator_displacement_at_excitation_end, length);
    const std::optional<SecantIsolation> at = IsolationAtPeak(problem, peaks);
    if (at && at->stiffness > 0.0) {
      fmt::print(out, "{:<34} {:>12.4g} {:<8} (secant stiffness {:.4g} {} at the peak)\n",
                 "period at the peak displacement", at->period, time, at->stiffness,
                 DescribeUnits(u, dimension::kStiffness));
    }
  }
  if (peaks.rows > 0) {
    const integrators::Energies& e = peaks.energies;
    const double input = e.input != 0.0 ? e.input : 1.0;
    fmt::print(out,
               "\nenergy at the end [{}*{}]: input {:.5g} = kinetic {:.3g} + damping {:.5g} "
               "({:.1f} %) + elastic {:.3g} + hysteretic {:.5g} ({:.1f} %)\n",
               force, length, e.input, e.kinetic, e.damping, 100 * e.damping / input, e.elastic,
               e.hysteretic, 100 * e.hysteretic / input);
  }
  PrintRunOutcome(analysis, summary.run, summary.results_path, out);
}

}  // namespace isolab::analysis
