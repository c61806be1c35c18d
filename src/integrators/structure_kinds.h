// What the integrators' bookkeeping needs to know about the two kinds of structure, a
// one-direction one (structure.h) and a plan one (plan_structure.h): how many force columns a
// response row carries, and the in-memory recorder sized for a run on it.
#pragma once

#include <cstddef>

#include "isolab/integrators/response.h"
#include "isolab/structure/plan_structure.h"
#include "isolab/structure/structure.h"

namespace isolab::integrators {

inline std::size_t ForceColumns(const structure::Structure& s) { return s.connections().size(); }
inline std::size_t ForceColumns(const structure::PlanStructure& s) { return s.force_columns(); }

// Keeps every grid.output_every-th row of a run on `structure` in `response`.
template <class Structure>
HistoryRecorder RecorderFor(const Structure& structure, const TimeGrid& grid,
                            ResponseHistory* response) {
  return HistoryRecorder(response, grid, structure.dofs(),
                         static_cast<int>(ForceColumns(structure)),
                         static_cast<int>(structure.law_count()));
}

}  // namespace isolab::integrators
