#include "isolab/analysis/run_analysis.h"

#include <fmt/format.h>

#include <optional>

#include "isolab/analysis/results_file.h"
#include "isolab/analysis/results_writer.h"
#include "isolab/core/errors.h"
#include "isolab/hysteresis/rate_form.h"

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

}  // namespace

integrators::RunSummary RunAnalysis(const model::AnalysisSection& analysis,
                                    const AnalysisSetup& setup,
                                    integrators::ResponseObserver& observer) {
  if (analysis.integrator == model::AnalysisSection::Integrator::kIda) {
    for (const auto& connection : setup.structure.connections()) {
      for (const auto& kernel : connection.assembly.kernels()) {
        if (!hysteresis::HasRateForm(kernel)) {
          throw InputError({"integrator ida"},
                           "cannot run a degrading_bhm2 component (the law has no rate form "
                           "yet); run it with Newmark (analysis.integrator: newmark, or "
                           "--integrator newmark)");
        }
      }
    }
    return integrators::RunIda(setup.structure, setup.excitation, setup.grid, analysis.ida,
                               observer);
  }
  return integrators::RunNewmark(setup.structure, setup.excitation, setup.grid, analysis.newmark,
                                 observer);
}

integrators::RunSummary RunAnalysis(const model::AnalysisSection& analysis,
                                    const AnalysisSetup& setup,
                                    integrators::ResponseHistory* response) {
  integrators::HistoryRecorder recorder(response, setup.grid, setup.structure.dofs(),
                                        static_cast<int>(setup.structure.connections().size()),
                                        static_cast<int>(setup.structure.law_count()));
  return RunAnalysis(analysis, setup, recorder);
}

RecordedRun RunAndRecord(const model::ModelFile& model, const model::AnalysisSection& analysis,
                         const AnalysisSetup& setup, const model::OutputSelection& selection,
                         const std::string& results_path, const std::string& version,
                         std::size_t buffer_rows) {
  RecordedRun result;
  RunDescription run{&model, &setup, &analysis, &result.summary, &result.peaks, version, selection};
  PeakTracker tracker(setup);
  std::optional<ResultsWriter> writer;
  if (!results_path.empty()) writer.emplace(results_path, run, buffer_rows);
  std::vector<integrators::ResponseObserver*> list = {&tracker};
  if (writer) list.push_back(&*writer);
  integrators::ObserverList observers(std::move(list));
  result.summary = RunAnalysis(analysis, setup, observers);
  result.peaks = tracker.Peaks();
  if (writer) writer->Finish(result.summary, result.peaks);
  result.warnings = RunWarnings(run);
  return result;
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
