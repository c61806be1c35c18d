// `isolab run` on a plan model (a model file with a `plan:` section, plan_model_file.h): the
// building in plan under two record components, by Newmark. Prints the records as applied and
// the model, then the peak resultant displacement of every isolator, the torsional
// amplification, the floors' peak rotations, the energy balance and Newton's statistics; the
// histories go to HDF5 (plan_analysis.h).
#pragma once

#include <ostream>

#include "run_command.h"

namespace isolab::cli {

// The exit code as RunRunCommand's. Throws InputError for options that do not apply to plan
// models (--record, --units, --record-dt, --fixed-base, --integrator ida, --rtol, --atol,
// --plot) and for bad input.
int RunPlanRunCommand(const RunOptions& options, std::ostream& out);

}  // namespace isolab::cli
