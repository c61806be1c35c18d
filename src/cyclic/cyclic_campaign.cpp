#include "isolab/cyclic/cyclic_campaign.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "isolab/core/errors.h"
#include "isolab/identification/synthetic_tests.h"
#include "isolab/model/build_structure.h"

namespace isolab::cyclic {

using hysteresis::CyclicProtocol;

std::vector<CyclicProtocol> CyclicProtocols(const model::ModelFile& model,
                                            const CyclicRequest& request) {
  model::RefuseAxialLoads(model, "a cyclic test");
  if (model::PlanIsolators(model) != nullptr) {
    throw InputError({model.path},
                     "a building in plan: its isolators are driven along an orbit or a path "
                     "(cyclic --orbit or --path; orbit= or path= in Python); the sinusoidal test "
                     "along one direction is a one-direction model's");
  }
  if (model.isolation.size() == 0) {
    throw InputError({model.path}, "no isolation section: nothing to test cyclically");
  }
  CyclicProtocol base = model.cyclic.value_or(CyclicProtocol{});
  if (request.cycles) base.cycles = *request.cycles;
  if (request.steps_per_cycle) base.steps_per_cycle = *request.steps_per_cycle;
  std::vector<double> amplitudes = request.amplitudes;
  if (amplitudes.empty()) {
    if (!model.cyclic) {
      throw InputError({model.path}, fmt::format("no amplitude: give {} or a 'cyclic:' section",
                                                 request.amplitude_option));
    }
    amplitudes.push_back(model.cyclic->amplitude);
  }
  const std::vector<double> periods =
      request.periods.empty() ? std::vector<double>{base.period} : request.periods;
  std::vector<CyclicProtocol> protocols;
  for (const double period : periods) {
    for (const double amplitude : amplitudes) {
      CyclicProtocol protocol = base;
      protocol.amplitude = amplitude;
      protocol.period = period;
      try {
        protocol.Validate();
      } catch (const InvalidParameter& error) {
        throw InputError({request.where}, error.violation().Describe());
      }
      protocols.push_back(protocol);
    }
  }
  return protocols;
}

std::vector<hysteresis::CyclicResult> RunCyclicCampaign(const model::ModelFile& model,
                                                        const CyclicRequest& request) {
  std::vector<hysteresis::CyclicResult> runs;
  std::vector<hysteresis::LawState> state(model.isolation.state_size());
  for (const CyclicProtocol& protocol : CyclicProtocols(model, request)) {
    if (!request.sequential) std::fill(state.begin(), state.end(), hysteresis::LawState{});
    runs.push_back(hysteresis::RunCyclicTest(model.isolation, protocol, state));
    const hysteresis::CyclicResult& run = runs.back();
    const auto finite = [](double v) { return std::isfinite(v); };
    if (!std::all_of(run.loop.force.begin(), run.loop.force.end(), finite) ||
        !std::all_of(run.cycles.begin(), run.cycles.end(),
                     [](const auto& c) { return std::isfinite(c.dissipated); })) {
      throw InputError({request.where},
                       fmt::format("amplitude {:g} {}: the loop's forces are not finite (no "
                                   "bearing reaches such displacements)",
                                   protocol.amplitude, model.units.length()));
    }
  }
  return runs;
}

std::vector<identification::CyclicTestData> TestsFromLoops(
    const std::vector<hysteresis::CyclicResult>& runs, bool name_period) {
  std::vector<identification::CyclicTestData> tests;
  for (const hysteresis::CyclicResult& run : runs) {
    tests.push_back(identification::TestFromLoop(run, name_period));
  }
  return tests;
}

}  // namespace isolab::cyclic
