// The run's headline peaks, one table that every output iterates: the text summary (run_text.h),
// the JSON report (run_report.h), the HDF5 file's /peaks, the CSV file's '# peak' lines and the
// band of a fitted model's draws (run_band.h). A peak is added to all of them by one row in
// summary_peaks.cpp.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "isolab/analysis/response_peaks.h"
#include "isolab/core/units.h"

namespace isolab::analysis {

struct NamedPeak {
  // What the text adds after the peak's value and time.
  enum class Note {
    kNone,
    kIsolator,       // the isolator's name, where there are several
    kStoryAndRatio,  // the story, and the drift over its height where it has one
    kLevelAndG,      // the level's name, and the acceleration in g
    kG,              // the acceleration in g
    kLevel,          // the level's name
  };
  const char* name;   // JSON's and the files' ("isolator_displacement": /peaks/<name> in HDF5)
  const char* label;  // the text's ("peak isolator displacement")
  const Peak* peak;
  Dimension dimension;  // kNone: radians
  Note note;
};

// The peaks that apply to the run's structure (isolator ones with isolators, story ones with
// stories, rotations with rotating levels), in the outputs' order.
std::vector<NamedPeak> SummaryPeaks(const structure::Layout& layout, const ResponsePeaks& peaks);

// The isolation at the run's peak isolator displacement (model_summary.h's IsolationAt: the
// secant stiffness and the isolated period there), for the text and the JSON alike; nullopt
// without isolators or before they moved. Computed when an output asks, not by every Solve (fits
// and studies run thousands).
std::optional<SecantIsolation> IsolationAtPeak(const Problem& problem, const ResponsePeaks& peaks);

// A peak's unit as the outputs write it: the model's ("mm/s^2"), or "rad".
std::string PeakUnit(const UnitSystem& units, Dimension dimension);

}  // namespace isolab::analysis
