#include "isolab/analysis/building_response.h"

#include <fmt/format.h>

#include <cmath>

#include "isolab/analysis/problem.h"
#include "isolab/analysis/solve.h"
#include "isolab/core/errors.h"
#include "isolab/structure/layout.h"

namespace isolab::analysis {
namespace {

// Collects the channels' values at every step of the grid.
class ChannelRecorder final : public integrators::ResponseObserver {
 public:
  ChannelRecorder(const structure::Layout& layout, const std::vector<BuildingChannel>& channels,
                  std::size_t steps)
      : histories_(channels.size()) {
    for (const BuildingChannel& channel : channels) {
      dofs_.push_back(layout.levels[std::size_t(channel.level - 1)].dofs[structure::kX]);
      displacement_.push_back(channel.kind == BuildingChannel::Kind::kDisplacement);
    }
    for (Signal& history : histories_) history.reserve(steps);
  }
  void Observe(const integrators::ResponseRow& row) override {
    for (std::size_t c = 0; c < dofs_.size(); ++c) {
      histories_[c].push_back(displacement_[c] ? row.displacement[dofs_[c]]
                                               : row.absolute_acceleration[dofs_[c]]);
    }
  }
  std::vector<Signal>& histories() { return histories_; }

 private:
  std::vector<Signal> histories_;
  std::vector<int> dofs_;
  std::vector<bool> displacement_;
};

// The measured table acceleration (sampled at `dt`) as the run's record, from rest, with no free
// vibration after it.
RunOverrides TableMotion(const model::ModelFile& model, const Signal& acceleration, double dt) {
  RunOverrides overrides;
  overrides.records.push_back(TableRecord(model.units, acceleration, dt));
  overrides.dt = dt;
  overrides.free_vibration = model::FreeVibration{false, 0.0};
  return overrides;
}

std::vector<Signal> Run(const model::ModelFile& model, const Signal& acceleration, double dt,
                        const std::vector<BuildingChannel>& channels) {
  const Problem problem = Prepare(model, TableMotion(model, acceleration, dt));
  ChannelRecorder recorder(problem.layout, channels, acceleration.size() + 1);
  integrators::ResponseObserver* const also[] = {&recorder};
  SolveOptions options;
  options.analysis = model.analysis;
  options.analysis.dt = dt;
  const Summary summary = Solve(options, problem, also);
  if (!summary.ok()) throw std::runtime_error("the run stopped: " + summary.run.message);
  return std::move(recorder.histories());
}

}  // namespace

std::string BuildingChannel::Name() const {
  return fmt::format("{}{}", kind == Kind::kDisplacement ? 'd' : 'a', level);
}

BuildingChannel ParseChannel(const std::string& text, const std::string& given_by) {
  BuildingChannel channel;
  int level = 0;
  std::size_t used = 0;
  if (text.size() >= 2 && (text[0] == 'd' || text[0] == 'a')) {
    try {
      level = std::stoi(text.substr(1), &used);
    } catch (const std::exception&) {
      used = 0;
    }
  }
  if (used == 0 || used != text.size() - 1 || level < 1) {
    throw InputError({given_by}, fmt::format("channel '{}': expected d<level> (displacement "
                                             "relative to the table) or a<level> (absolute "
                                             "acceleration), level 1 the isolation slab",
                                             text));
  }
  channel.kind =
      text[0] == 'd' ? BuildingChannel::Kind::kDisplacement : BuildingChannel::Kind::kAcceleration;
  channel.level = level;
  return channel;
}

ChannelHistories SimulateChannels(const model::ModelFile& model,
                                  const std::vector<BuildingMotion>& motions,
                                  const std::vector<BuildingChannel>& channels, bool sequential,
                                  double pause) {
  ChannelHistories out;
  if (!sequential) {
    for (const BuildingMotion& motion : motions) {
      std::vector<Signal> run =
          Run(model, motion.measured.table_acceleration, SampleStep(motion.measured), channels);
      for (Signal& history : run) history.resize(motion.measured.time.size());
      out.push_back(std::move(run));
    }
    return out;
  }
  // One specimen: the motions one after the other with a pause of rest between, in one run.
  const double dt = SampleStep(motions.front().measured);
  if (pause <= 0.0) {
    const Signal& first = motions.front().measured.table_acceleration;
    pause = 5.0 * Prepare(model, TableMotion(model, first, dt)).summary.LongestPeriod();
  }
  const std::size_t rest = std::size_t(std::ceil(pause / dt));
  Signal table;
  std::vector<std::size_t> starts;
  for (const BuildingMotion& motion : motions) {
    const double step = SampleStep(motion.measured);
    if (std::abs(step - dt) > 1e-6 * dt) {
      throw InputError({motion.name},
                       fmt::format("sampled every {:g}, {} every {:g}: one specimen's motions run "
                                   "as one history need one step",
                                   step, motions.front().name, dt));
    }
    if (!starts.empty()) table.resize(table.size() + rest, 0.0);
    starts.push_back(table.size());
    const Signal& a = motion.measured.table_acceleration;
    table.insert(table.end(), a.begin(), a.end());
  }
  const std::vector<Signal> run = Run(model, table, dt, channels);
  for (std::size_t m = 0; m < motions.size(); ++m) {
    std::vector<Signal>& signals = out.emplace_back();
    const std::size_t n = motions[m].measured.time.size();
    for (const Signal& history : run) {
      signals.emplace_back(history.begin() + long(starts[m]),
                           history.begin() + long(starts[m] + n));
    }
  }
  return out;
}

}  // namespace isolab::analysis
