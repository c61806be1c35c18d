// `isolab cyclic`'s tests of one model (also the Python module's cyclic): the model's cyclic
// protocol with its amplitude, period, cycles and steps replaced as asked, one test per period and
// amplitude, run on fresh specimens or on one specimen in order (a campaign).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "isolab/hysteresis/cyclic_test.h"
#include "isolab/identification/cyclic_data.h"
#include "isolab/model/model_file.h"

namespace isolab::cyclic {

struct CyclicRequest {
  std::vector<double> amplitudes;  // empty: the model's cyclic.amplitude
  std::vector<double> periods;     // empty: the model's cyclic.period (or the default)
  std::optional<int> cycles, steps_per_cycle;
  bool sequential = false;  // one specimen: each test starts from the state the last one left
  std::string where = "command line";            // named by errors in the request
  std::string amplitude_option = "--amplitude";  // named when no amplitude is given
};

// The protocols, periods outer and amplitudes inner. Throws InputError for a model without an
// isolation section or an amplitude, with axial_load (model::RefuseAxialLoads), and for a
// protocol out of range.
std::vector<hysteresis::CyclicProtocol> CyclicProtocols(const model::ModelFile& model,
                                                        const CyclicRequest& request);

// Every protocol run on the model's isolation assembly, in order.
std::vector<hysteresis::CyclicResult> RunCyclicCampaign(const model::ModelFile& model,
                                                        const CyclicRequest& request);

// Cyclic tests made of computed loops, named as TestFromLoop names them (with the period when a
// request has several periods).
std::vector<identification::CyclicTestData> TestsFromLoops(
    const std::vector<hysteresis::CyclicResult>& runs, bool name_period);

}  // namespace isolab::cyclic
