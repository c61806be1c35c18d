// `isolab diagnose DATA... --building SPEC`: the discrepancy workflow on a building's shake-table
// motions (building/building_diagnosis.h): the building fitted by output error, the isolator's
// loops reconstructed with the fitted masses and diagnosed, and an effect named only where the
// building's own refit bears it out. Writes the diagnosis's report files and the final building.
#pragma once

#include <ostream>

#include "diagnose_command.h"
#include "search_ranks.h"

namespace isolab::cli {

// Throws InputError for bad data, specification or options that do not apply. Runs its fits on
// `ranks`, where rank 0 alone prints and writes.
void RunBuildingDiagnoseCommand(const DiagnoseOptions& options, const SearchRanks& ranks,
                                std::ostream& out);

}  // namespace isolab::cli
