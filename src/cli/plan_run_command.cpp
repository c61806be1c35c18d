#include "plan_run_command.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <nlohmann/json.hpp>

#include "isolab/analysis/model_summary.h"
#include "isolab/analysis/plan_analysis.h"
#include "isolab/analysis/run_report.h"
#include "isolab/core/errors.h"
#include "isolab/io/output_check.h"
#include "isolab/model/free_vibration_text.h"
#include "run_report.h"

namespace isolab::cli {
namespace {

void RefuseOneDirectionOptions(const RunOptions& options) {
  const auto refuse = [](bool given, const char* option) {
    if (given) {
      throw InputError({option},
                       "does not apply to a plan model (its records are the model's h1 and h2)");
    }
  };
  refuse(!options.record.empty(), "--record");
  refuse(!options.units.empty(), "--units");
  refuse(options.record_dt.has_value(), "--record-dt");
  refuse(options.fixed_base, "--fixed-base");
  refuse(options.plot.has_value(), "--plot");
}

void PrintPreamble(const model::PlanModelFile& model, const analysis::PlanAnalysisSetup& setup,
                   std::ostream& out) {
  const UnitSystem& u = model.units;
  const double g = u.Convert(1.0, "g", dimension::kAcceleration);
  fmt::print(out, "== {} (plan model) ==\n", model.path);
  if (!model.description.empty()) fmt::print(out, "{}\n", model.description);
  for (const auto& [key, r] : {std::pair{"H1", &setup.h1}, std::pair{"H2", &setup.h2}}) {
    if (r->path.empty()) continue;
    fmt::print(out, "record {}: {} ({}, dt = {:g} s, in {}), scale {:g}: PGA {:.4g} g\n", key,
               r->path, r->format, r->dt, r->units, r->scale, r->pga / g);
  }
  fmt::print(out, "H1 at {:g} degrees from x, H2 at {:g}\n", setup.angle, setup.angle + 90.0);
  fmt::print(out,
             "model: {} floors, {} isolators, total mass {:.5g} ({:.5g} t); isolated period "
             "{:.4g} {} at {:g} {} along x\n",
             setup.structure.floors(), setup.structure.isolators().size(), setup.total_mass,
             setup.total_mass * u.SiFactor(dimension::kMass) / 1000.0, setup.isolated_period,
             u.time(), setup.trial_displacement, u.length());
  PrintGrid(setup.grid, setup.excitation_end, setup.free_vibration, setup.structure.dofs(), u, out);
}

void PrintSummary(const model::PlanModelFile& model, const analysis::PlanAnalysisSetup& setup,
                  const analysis::PlanPeaks& peaks, const integrators::RunSummary& summary,
                  const integrators::ResponseHistory& response, const std::string& output,
                  std::ostream& out) {
  const UnitSystem& u = model.units;
  const auto& isolators = setup.structure.isolators();
  fmt::print(out, "peak resultant isolator displacement [{}]:\n", u.length());
  for (std::size_t i = 0; i < isolators.size(); ++i) {
    const analysis::Peak& p = peaks.isolator_resultant[i];
    fmt::print(out, "  {:<24} {:>12.5g} at t = {:.4g} {}\n", isolators[i].name, p.value, p.time,
               u.time());
  }
  fmt::print(out, "  {:<24} {:>12.5g} at t = {:.4g} {}\n", "(base centre of mass)",
             peaks.centre_resultant.value, peaks.centre_resultant.time, u.time());
  fmt::print(out, "torsional amplification {:.4g} ({} over the base's centre of mass)\n",
             peaks.torsional_amplification, isolators[peaks.largest_resultant.index].name);
  const int floor = peaks.largest_floor_rotation.index;
  fmt::print(out, "peak floor rotation {:.4g} rad ({})\n", peaks.largest_floor_rotation.value,
             floor == 0 ? std::string("base") : model.building.stories[floor - 1].name);
  fmt::print(out, "peak base shear (resultant) {:.5g} {} at t = {:.4g} {}\n",
             peaks.base_shear.value, u.force(), peaks.base_shear.time, u.time());
  if (response.rows_written > 0) {
    const integrators::Energies& e = response.energies[response.rows_written - 1];
    fmt::print(out,
               "\nenergy at the end [{}*{}]: input {:.5g} = kinetic {:.3g} + damping {:.5g} + "
               "elastic {:.3g} + hysteretic {:.5g}\n",
               u.force(), u.length(), e.input, e.kinetic, e.damping, e.elastic, e.hysteretic);
  }
  PrintRunOutcome(model.analysis, summary, output, out);
}

nlohmann::json SummaryJson(const model::PlanModelFile& model,
                           const analysis::PlanAnalysisSetup& setup,
                           const analysis::PlanPeaks& peaks, const integrators::RunSummary& summary,
                           const std::string& output) {
  nlohmann::json json;
  nlohmann::json isolators = nlohmann::json::object();
  for (std::size_t i = 0; i < setup.structure.isolators().size(); ++i) {
    isolators[setup.structure.isolators()[i].name] = {
        {"peak_resultant", peaks.isolator_resultant[i].value},
        {"time", peaks.isolator_resultant[i].time}};
  }
  json["isolators"] = isolators;
  json["peak_centre_resultant"] = peaks.centre_resultant.value;
  json["torsional_amplification"] = peaks.torsional_amplification;
  std::vector<double> rotations;
  for (const analysis::Peak& p : peaks.floor_rotation) rotations.push_back(p.value);
  json["peak_floor_rotation"] = rotations;
  json["peak_base_shear"] = peaks.base_shear.value;
  analysis::AddRunOutcome(model.analysis, setup.grid.dt, summary, output, &json);
  return json;
}

}  // namespace

int RunPlanRunCommand(const RunOptions& options, std::ostream& out) {
  RefuseOneDirectionOptions(options);
  model::PlanModelFile model = model::LoadPlanModelFile(options.model);
  model.analysis = ChooseIntegrator(options, model.analysis);
  const std::string output = ChooseResultsPath(options, model.output_file);
  analysis::CheckPlanResultsPath(output);
  std::vector<std::string> inputs{options.model};
  if (model.ground_motion) {
    inputs.push_back(model.ground_motion->h1.file);
    if (model.ground_motion->h2) inputs.push_back(model.ground_motion->h2->file);
  }
  io::CheckOutputs(inputs, {output});
  analysis::PlanOverrides overrides;
  overrides.scale = options.scale;
  overrides.dt = options.dt;
  overrides.max_steps = options.max_steps;
  overrides.trial_displacement = options.trial_displacement;
  if (!options.free_vibration.empty()) {
    overrides.free_vibration =
        model::ParseFreeVibration(options.free_vibration, model.units, "--free-vibration");
  }
  const analysis::PlanAnalysisSetup setup = analysis::PreparePlanAnalysis(model, overrides);
  if (!options.json && !options.quiet) PrintPreamble(model, setup, out);
  out.flush();
  integrators::ResponseHistory response;
  const integrators::RunSummary summary =
      analysis::RunPlanAnalysis(model.analysis, setup, &response);
  const analysis::PlanPeaks peaks = analysis::ComputePlanPeaks(setup, response);
  analysis::WritePlanResults(output, model, setup, response, summary, peaks, ISOLAB_VERSION);
  if (options.json) {
    out << SummaryJson(model, setup, peaks, summary, output).dump(2) << "\n";
  } else {
    PrintSummary(model, setup, peaks, summary, response, output, out);
  }
  const std::string bearing =
      analysis::IsolatorDisplacementWarning(peaks.largest_resultant.value, model.units);
  if (!bearing.empty()) fmt::print(stderr, "isolab: warning: {}\n", bearing);
  return ExitCode(summary, setup.grid.dt, output);
}

}  // namespace isolab::cli
