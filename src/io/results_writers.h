// The two results formats' writers, private to io: results_file.h is the interface.
#pragma once

#include <string>

#include "isolab/io/result_series.h"

namespace isolab::io {

// The two formats (results_file.h); WriteResultsFile chooses.
void WriteResultsHdf5(const std::string& path, const RunDescription& run);
void WriteResultsCsv(const std::string& path, const RunDescription& run);

}  // namespace isolab::io
