// `isolab fit --building SPEC data...`: identifies a building model (isolation and
// superstructure) from shake-table motions by output error (building/building_fit.h) and writes
// the fitted model with its parameters' uncertainty.
#pragma once

#include <ostream>

#include "fit_command.h"

namespace isolab::cli {

// Throws InputError for bad data, specification or options that do not apply.
void RunBuildingFitCommand(const FitOptions& options, std::ostream& out);

}  // namespace isolab::cli
