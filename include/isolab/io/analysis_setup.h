// From a model file (and command-line overrides) to what an integrator runs: the structure, the
// excitation in model units, the output time grid, and where the isolation layer and stories are.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "isolab/integrators/excitation.h"
#include "isolab/integrators/newmark.h"
#include "isolab/integrators/response.h"
#include "isolab/io/model_file.h"
#include "isolab/structure/structure.h"

namespace isolab::io {

struct RunOverrides {
  std::string record;           // replaces excitation.ground_motion.file (relative to the cwd)
  std::optional<double> scale;  // replaces its scale
  std::optional<double> dt;     // replaces analysis.dt (model time unit)
  bool fixed_base = false;      // analyse the building without its isolation layer
};

// Where the parts of interest sit among the structure's connections.
struct StructureLayout {
  int isolation = -1;                 // connection of the isolation layer (SDOF: its spring)
  std::vector<int> stories;           // connection of each story, bottom to top
  std::vector<double> story_heights;  // (length), 0 where not given
};

struct AnalysisSetup {
  structure::Structure structure;
  StructureLayout layout;
  integrators::Excitation excitation;
  integrators::TimeGrid grid;
  std::string record_path;  // empty without a ground motion
  double scale = 1.0;
};

// Drift of story `story` (bottom = 0) at output row `row`: its top floor less its bottom floor.
double StoryDrift(const AnalysisSetup& setup, const integrators::RowMatrix& displacement, int row,
                  std::size_t story);

// Throws InputError (naming the file, or "command line") for records that cannot be read, a dt
// coarser than the record's, or a structure without what the analysis needs.
AnalysisSetup PrepareAnalysis(const ModelFile& model, const RunOverrides& overrides);

}  // namespace isolab::io
