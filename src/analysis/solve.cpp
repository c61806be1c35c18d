#include "isolab/analysis/solve.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "isolab/analysis/result_series.h"
#include "isolab/analysis/results_file.h"
#include "isolab/core/errors.h"
#include "isolab/hysteresis/plan_rate_form.h"
#include "isolab/hysteresis/rate_form.h"
#include "isolab/integrators/ida.h"
#include "isolab/integrators/newmark.h"
#include "results_writer.h"

namespace isolab::analysis {
namespace {

std::string NewtonName(integrators::NewmarkOptions::Newton newton) {
  switch (newton) {
    case integrators::NewmarkOptions::Newton::kFull:
      return "full";
    case integrators::NewmarkOptions::Newton::kModifiedInitial:
      return "modified_initial";
    case integrators::NewmarkOptions::Newton::kModifiedStep:
      return "modified_step";
  }
  return "?";
}

// IDA integrates the laws' rate forms: a law without one (a degrading BHM2, alone or in an
// uncoupled pair) is refused before the run, naming where it is.
void RequireRateForms(const structure::Structure& structure) {
  for (std::size_t slot = 0; slot < structure.slots(); ++slot) {
    const bool rate_forms = structure.VisitSlotAssembly(slot, [](const auto& assembly) {
      return std::all_of(assembly.kernels().begin(), assembly.kernels().end(),
                         [](const auto& kernel) { return hysteresis::HasRateForm(kernel); });
    });
    if (rate_forms) continue;
    throw InputError({"integrator ida"},
                     fmt::format("cannot run {} '{}' (a degrading_bhm2 component: the law has no "
                                 "rate form yet); run it with Newmark (analysis.integrator: "
                                 "newmark, or --integrator newmark)",
                                 structure.slot_width(slot) == 2 ? "isolator" : "member",
                                 structure.slot_name(slot)));
  }
}

integrators::RunSummary Integrate(const model::AnalysisSection& analysis, const Problem& problem,
                                  integrators::ResponseObserver& observer) {
  if (analysis.integrator == model::AnalysisSection::Integrator::kIda) {
    return integrators::RunIda(problem.structure, problem.excitation, problem.grid, analysis.ida,
                               observer);
  }
  return integrators::RunNewmark(problem.structure, problem.excitation, problem.grid,
                                 analysis.newmark, observer);
}

}  // namespace

void SolveOptions::Validate() const {
  if (analysis.integrator == model::AnalysisSection::Integrator::kIda) {
    analysis.ida.Validate();
  } else {
    analysis.newmark.Validate();
  }
  if (output.every < 1) {
    throw InputError({"output.every"}, fmt::format("{} (must be >= 1)", output.every));
  }
  for (const std::string& quantity : output.quantities) {
    const std::string error = model::UnknownQuantity(quantity);
    if (!error.empty()) throw InputError({"output.quantities"}, error);
  }
}

Summary Solve(const SolveOptions& options, const Problem& problem,
              std::span<integrators::ResponseObserver* const> observers) {
  options.Validate();
  CheckQuantitiesExist(options.output, problem.layout, "output.quantities");
  if (options.analysis.integrator == model::AnalysisSection::Integrator::kIda) {
    if (!problem.structure.axial_loads().empty() || !problem.excitation.vertical.values.empty()) {
      throw InputError({"integrator ida"},
                       fmt::format("cannot run the axial loads of friction pendulum bearings "
                                   "(axial_load in {}): they run with Newmark "
                                   "(analysis.integrator: newmark, or --integrator newmark)",
                                   problem.model.path));
    }
    RequireRateForms(problem.structure);
  }
  Summary summary;
  summary.results_path = options.results_path;
  const RunDescription run{&problem,       &options.analysis, &summary.run,
                           &summary.peaks, options.version,   options.output};
  PeakTracker tracker(problem);
  std::optional<ResultsWriter> writer;
  if (!options.results_path.empty()) writer.emplace(options.results_path, run, options.buffer_rows);
  std::vector<integrators::ResponseObserver*> list = {&tracker};
  if (writer) list.push_back(&*writer);
  list.insert(list.end(), observers.begin(), observers.end());
  integrators::ObserverList all(std::move(list));
  summary.run = Integrate(options.analysis, problem, all);
  summary.peaks = tracker.Peaks();
  const double input = summary.peaks.energies.input;
  if (summary.run.ok() && !std::isfinite(input)) {
    summary.run.termination = integrators::RunSummary::Termination::kFailed;
    summary.run.message = fmt::format(
        "the input energy is not finite ({}): the response overflowed (check the laws' "
        "parameters and the record's units)",
        input);
  }
  if (summary.run.ok() && !(summary.run.energy_balance_error <= kMaxEnergyBalanceError)) {
    summary.run.termination = integrators::RunSummary::Termination::kFailed;
    summary.run.message = fmt::format(
        "the energy balance does not close: its error, {:.3g} of the input energy, exceeds {:g} "
        "(the response is not to be trusted: refine dt, or check the laws' parameters)",
        summary.run.energy_balance_error, kMaxEnergyBalanceError);
  }
  if (writer) writer->Finish(summary.run, summary.peaks);
  summary.warnings = RunWarnings(run);
  return summary;
}

model::AnalysisSection ChooseIntegrator(model::AnalysisSection analysis,
                                        const IntegratorChoice& choice,
                                        const std::string& option_prefix) {
  using Integrator = model::AnalysisSection::Integrator;
  if (choice.integrator == "ida") analysis.integrator = Integrator::kIda;
  if (choice.integrator == "newmark") analysis.integrator = Integrator::kNewmark;
  if (analysis.integrator != Integrator::kIda && (choice.rtol || choice.atol)) {
    throw InputError({option_prefix + (choice.rtol ? "rtol" : "atol")},
                     "a tolerance of the IDA integrator, and this run integrates with "
                     "Newmark-beta (choose IDA: integrator ida)");
  }
  if (choice.rtol) analysis.ida.relative_tolerance = *choice.rtol;
  if (choice.atol) analysis.ida.absolute_tolerance = *choice.atol;
  return analysis;
}

std::string DescribeIntegrator(const model::AnalysisSection& analysis, double dt) {
  if (analysis.integrator == model::AnalysisSection::Integrator::kIda) {
    const integrators::IdaOptions& o = analysis.ida;
    return fmt::format("ida rtol={:g} atol={:g} max_step={:g} max_steps={} output_dt={:g}",
                       o.relative_tolerance, o.absolute_tolerance, o.max_step, o.max_steps, dt);
  }
  const integrators::NewmarkOptions& o = analysis.newmark;
  return fmt::format(
      "newmark beta={} gamma={} newton={} force_tolerance={:g} displacement_tolerance={:g} "
      "max_iterations={} max_step_cuts={} dt={:g}",
      o.beta, o.gamma, NewtonName(o.newton), o.force_tolerance, o.displacement_tolerance,
      o.max_iterations, o.max_step_cuts, dt);
}

}  // namespace isolab::analysis
