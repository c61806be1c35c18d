// The peaks an engineer reads first from a run: isolator displacement and force, base shear,
// roof absolute acceleration, story drift.
#pragma once

#include "isolab/integrators/response.h"
#include "isolab/io/analysis_setup.h"

namespace isolab::io {

struct Peak {
  double value = 0.0;  // largest absolute value
  double time = 0.0;
  int index = -1;  // story or DOF where it occurred, if relevant
};

struct ResponsePeaks {
  Peak isolator_displacement;  // absent (index -1) without isolation
  Peak isolator_force;
  Peak base_shear;                  // force into the ground: grounded connections
  Peak first_story_shear;           // shear above the isolation layer (buildings)
  Peak roof_absolute_acceleration;  // top DOF
  Peak story_drift;                 // largest story drift; index = story (0-based)
  double story_drift_ratio = 0.0;   // that drift / its story height (0 without heights)
};

ResponsePeaks ComputePeaks(const AnalysisSetup& setup,
                           const integrators::ResponseHistory& response);

}  // namespace isolab::io
