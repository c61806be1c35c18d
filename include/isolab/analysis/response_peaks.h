// The peaks an engineer reads first from a run: isolator displacement and force, base shear,
// roof absolute acceleration, story drift; and where the isolator comes to rest.
//
// The residual isolator displacement is read after the free vibration that follows the
// excitation (analysis_setup.h): the middle of the isolator's range over the last
// `residual_window` of the run. A structure at rest gives its final displacement; a bearing that
// still swings elastically about an offset (a bilinear isolator below yield is undamped) gives
// that offset, and half the range says how much it still swings.
//
// A PeakTracker sees every step of a run (it is a ResponseObserver), whatever the results file
// keeps, and holds no history: only the isolator's displacements within the residual window.
#pragma once

#include <deque>
#include <utility>

#include "isolab/analysis/analysis_setup.h"
#include "isolab/integrators/response.h"

namespace isolab::analysis {

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
  // Isolator only (0 without isolation), signed:
  double residual_isolator_displacement = 0.0;  // the middle of the range over the window
  double residual_oscillation = 0.0;            // half that range
  double isolator_displacement_at_excitation_end = 0.0;
  integrators::Energies energies;  // at the last row seen (zero before any)
  int rows = 0;                    // rows seen
};

class PeakTracker final : public integrators::ResponseObserver {
 public:
  explicit PeakTracker(const AnalysisSetup& setup) : setup_(setup) {}
  void Observe(const integrators::ResponseRow& row) override;
  // The peaks of the rows seen so far.
  ResponsePeaks Peaks() const;

 private:
  const AnalysisSetup& setup_;
  ResponsePeaks peaks_;
  // (time, isolator displacement) of the rows within residual_window of the latest one.
  std::deque<std::pair<double, double>> window_;
};

// The peaks of a history's rows (a PeakTracker fed with them).
ResponsePeaks ComputePeaks(const AnalysisSetup& setup,
                           const integrators::ResponseHistory& response);

}  // namespace isolab::analysis
