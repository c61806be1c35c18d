// A model file driven along displacement paths (path_replay.h), as `isolab cyclic --path/--orbit`
// and the Python module's cyclic(path=..., orbit=...) ask: which assemblies of the model are
// driven (a building in plan's isolators, or a one-direction model's isolation, its laws in their
// coupled forms or uncoupled in two directions) and along which paths (files, or orbits shaped by
// the request or the model's cyclic section). The command line and Python share this; they differ
// only in how they name an option in a message.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "isolab/core/units.h"
#include "isolab/cyclic/path_replay.h"
#include "isolab/model/model_file.h"

namespace isolab::cyclic {

struct ReplayRequest {
  std::vector<std::string> paths;  // CSV files of displacement paths; or
  std::string orbit;               // "circle" or "figure8"
  std::vector<double> amplitudes;  // an orbit's radius (model length), one run each
  std::vector<double> periods;     // an orbit's period (model time), one run each
  std::optional<int> cycles, steps_per_cycle;
  std::string isolator;                 // one isolator of a building in plan; empty: each
  bool uncoupled = false;               // a one-direction model's laws along x and y separately
  std::string force_unit, length_unit;  // of path files without a "# units:" line
};

// How a caller names a request's field in messages: "--force-unit" on the command line,
// "force_unit" in Python.
enum class OptionStyle { kCommandLine, kPython };

struct ReplayRun {
  std::string model;  // the model file, and the isolator of a building in plan
  UnitSystem units;   // the model's
  ReplayResult result;
};

// Every run the request asks of `model` (for a plan model, isolator by isolator, each along every
// path). Throws
// InputError naming the option at fault (an isolator the model does not have, --isolator on a
// one-direction model, --uncoupled on a plan one, an orbit without an amplitude, a path file
// without units) or the model (no isolation, a law without a coupled form, axial_load:
// model::RefuseAxialLoads).
std::vector<ReplayRun> ReplayModel(const model::ModelFile& model, const ReplayRequest& request,
                                   OptionStyle style);

}  // namespace isolab::cyclic
