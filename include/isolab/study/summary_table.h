// The summary as a terminal table: per scale, per variant, each record's run, then the mean and
// max over records and the mean's ratio to the reference variant.
#pragma once

#include <ostream>

#include "isolab/study/summary.h"

namespace isolab::study {

void PrintSummaryTable(const Summary& summary, std::ostream& out);

}  // namespace isolab::study
