#include "isolab/io/run_analysis.h"

#include <fmt/format.h>

#include "isolab/core/errors.h"
#include "isolab/hysteresis/rate_form.h"

namespace isolab::io {
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

integrators::RunSummary RunAnalysis(const AnalysisSection& analysis, const AnalysisSetup& setup,
                                    integrators::ResponseHistory* response) {
  if (analysis.integrator == AnalysisSection::Integrator::kIda) {
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
                               response);
  }
  return integrators::RunNewmark(setup.structure, setup.excitation, setup.grid, analysis.newmark,
                                 response);
}

std::string DescribeIntegrator(const AnalysisSection& analysis, double dt) {
  if (analysis.integrator == AnalysisSection::Integrator::kIda) {
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

}  // namespace isolab::io
