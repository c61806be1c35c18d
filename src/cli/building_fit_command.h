// `isolab fit --building SPEC data...`: identifies a building model (isolation and
// superstructure) from shake-table motions by output error (building/building_fit.h) and writes
// the fitted model with its parameters' uncertainty.
#pragma once

#include <ostream>

#include "fit_command.h"
#include "search_ranks.h"

namespace isolab::cli {

// Throws InputError for bad data, specification or options that do not apply. Runs the search
// on `ranks`, where rank 0 alone prints and writes.
void RunBuildingFitCommand(const FitOptions& options, const SearchRanks& ranks, std::ostream& out);

}  // namespace isolab::cli
