// A building model's response to measured shake-table motions at the measured channels: the
// simulation the building-level fit (building_fit.h) compares at every point of its search, and
// the prediction band (prediction_band.h) runs for every parameter set it draws.
#pragma once

#include <string>
#include <vector>

#include "isolab/building/shake_table_prediction.h"
#include "isolab/model/model_file.h"

namespace isolab::building {

struct BuildingMotion {
  std::string name;
  BuildingMeasurements measured;  // model units; levels from the slab to the roof
};

// A measured channel: level 1 is the isolation slab, the last the roof.
struct BuildingChannel {
  enum class Kind { kDisplacement, kAcceleration } kind = Kind::kDisplacement;
  int level = 1;
  // "d1" (the slab's displacement relative to the table), "a6" (level 6's absolute acceleration).
  std::string Name() const;
};
// Parses "d1", "a6"; throws InputError at `where` (the channel's place in its file) otherwise.
BuildingChannel ParseChannel(const std::string& text, const SourceLocation& where);

// A model's responses to the motions at the measured channels: per motion, per channel, at the
// measured samples (the model integrated with the measured step).
using ChannelHistories = std::vector<std::vector<Signal>>;

// Runs `model` under every motion (one specimen when `sequential`, with `pause` of rest between;
// 0: 5 x the isolated building's longest period), driven by the table's acceleration or, for
// force-driven tests, by the force on level 1, integrated in `substeps` steps per sample (the
// input linear between samples). Throws InputError for a model or motions it cannot run (steps
// that differ between sequential motions, table motions beside force-driven tests),
// std::runtime_error for a run that stops early.
ChannelHistories SimulateChannels(const model::ModelFile& model,
                                  const std::vector<BuildingMotion>& motions,
                                  const std::vector<BuildingChannel>& channels, bool sequential,
                                  double pause, int substeps = 1);

}  // namespace isolab::building
