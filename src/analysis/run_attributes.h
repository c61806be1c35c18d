// What every HDF5 results file carries, one-direction or plan (docs/results.md): the program and
// model at its root, the integrator's run as root attributes, and the groups its series need.
#pragma once

#include <set>
#include <string>
#include <vector>

#include "isolab/analysis/result_series.h"
#include "isolab/integrators/response.h"
#include "isolab/io/hdf5_file.h"
#include "isolab/model/model_file.h"

namespace isolab::analysis {

// isolab_version, model_file and units ("force kN, length mm, time s").
void WriteProgramAttributes(io::Hdf5File& file, const std::string& version,
                            const std::string& model_path, const UnitSystem& units);

// integrator, dt, steps, the Newton and IDA statistics, wall_seconds, termination, message and
// energy_balance_error.
void WriteIntegratorAttributes(io::Hdf5File& file, const model::AnalysisSection& analysis,
                               double dt, const integrators::RunSummary& summary);

// Every group the series' names need ("isolator" for "isolator/force"), created once; returns
// them.
std::set<std::string> CreateSeriesGroups(io::Hdf5File& file, const std::vector<Series>& series);

}  // namespace isolab::analysis
