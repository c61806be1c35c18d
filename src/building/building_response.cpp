#include "isolab/building/building_response.h"

#include <fmt/format.h>

#include <cmath>

#include "isolab/analysis/problem.h"
#include "isolab/analysis/solve.h"
#include "isolab/core/errors.h"
#include "isolab/model/build_structure.h"
#include "isolab/structure/layout.h"

namespace isolab::building {
namespace {

// Collects the channels' values at every `every`-th step of the grid: at the measured samples.
class ChannelRecorder final : public integrators::ResponseObserver {
 public:
  ChannelRecorder(const structure::Layout& layout, const std::vector<BuildingChannel>& channels,
                  std::size_t samples, int every)
      : histories_(channels.size()), every_(every) {
    for (const BuildingChannel& channel : channels) {
      dofs_.push_back(layout.levels[std::size_t(channel.level - 1)].dofs[structure::kX]);
      displacement_.push_back(channel.kind == BuildingChannel::Kind::kDisplacement);
    }
    for (Signal& history : histories_) history.reserve(samples);
  }
  void Observe(const integrators::ResponseRow& row) override {
    if (row.step % every_ != 0) return;
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
  int every_ = 1;
};

// What drives a motion's run, sampled at `dt`: the table's acceleration as the run's record, or
// (a force-driven test) the force on level 1 with the ground still; from rest, with no free
// vibration after it, integrated in `substeps` steps a sample.
struct Drive {
  const Signal& input;
  bool force = false;
  double dt = 0.0;
  int substeps = 1;
};

analysis::Problem PrepareDriven(model::ModelFile model, const Drive& drive) {
  analysis::RunOverrides overrides;
  if (drive.force) {
    const structure::LaidOutStructure built = model::BuildStructure(model);
    model.excitation = {};
    model.excitation.forces.push_back(
        {built.layout.levels.front().dofs[structure::kX], drive.dt, drive.input});
  } else {
    overrides.records.push_back(TableRecord(model.units, drive.input, drive.dt));
  }
  overrides.dt = drive.dt / drive.substeps;
  overrides.free_vibration = model::FreeVibration{false, 0.0};
  return analysis::Prepare(model, overrides);
}

std::vector<Signal> Run(const model::ModelFile& model, const Drive& drive,
                        const std::vector<BuildingChannel>& channels) {
  const analysis::Problem problem = PrepareDriven(model, drive);
  ChannelRecorder recorder(problem.layout, channels, drive.input.size() + 1, drive.substeps);
  integrators::ResponseObserver* const also[] = {&recorder};
  analysis::SolveOptions options;
  options.analysis = model.analysis;
  options.analysis.dt = problem.grid.dt;
  const analysis::Summary summary = analysis::Solve(options, problem, also);
  if (!summary.ok()) throw std::runtime_error("the run stopped: " + summary.run.message);
  return std::move(recorder.histories());
}

// The history that drives a motion, and whether it is a force (all motions of a fit must agree).
const Signal& Input(const BuildingMotion& motion) {
  return motion.measured.applied_force.empty() ? motion.measured.table_acceleration
                                               : motion.measured.applied_force;
}

}  // namespace

std::string BuildingChannel::Name() const {
  return fmt::format("{}{}", kind == Kind::kDisplacement ? 'd' : 'a', level);
}

BuildingChannel ParseChannel(const std::string& text, const SourceLocation& where) {
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
    throw InputError(where, fmt::format("channel '{}': expected d<level> (displacement relative "
                                        "to the table) or a<level> (absolute acceleration), "
                                        "level 1 the isolation slab",
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
                                  double pause, int substeps) {
  const bool force = !motions.front().measured.applied_force.empty();
  for (const BuildingMotion& motion : motions) {
    if (motion.measured.applied_force.empty() != force) continue;
    throw InputError({motion.name},
                     fmt::format("driven by {}, {} by {}: one fit's motions are all "
                                 "table motions or all force-driven tests",
                                 force ? "the table" : "a force", motions.front().name,
                                 force ? "a force" : "the table"));
  }
  ChannelHistories out;
  if (!sequential) {
    for (const BuildingMotion& motion : motions) {
      std::vector<Signal> run =
          Run(model, {Input(motion), force, SampleStep(motion.measured), substeps}, channels);
      for (Signal& history : run) history.resize(motion.measured.time.size());
      out.push_back(std::move(run));
    }
    return out;
  }
  // One specimen: the motions one after the other with a pause of rest between, in one run.
  const double dt = SampleStep(motions.front().measured);
  if (pause <= 0.0) {
    pause =
        5.0 * PrepareDriven(model, {Input(motions.front()), force, dt, 1}).summary.LongestPeriod();
  }
  const std::size_t rest = std::size_t(std::ceil(pause / dt));
  Signal input;
  std::vector<std::size_t> starts;
  for (const BuildingMotion& motion : motions) {
    const double step = SampleStep(motion.measured);
    if (std::abs(step - dt) > 1e-6 * dt) {
      throw InputError({motion.name},
                       fmt::format("sampled every {:g}, {} every {:g}: one specimen's motions run "
                                   "as one history need one step",
                                   step, motions.front().name, dt));
    }
    if (!starts.empty()) input.resize(input.size() + rest, 0.0);
    starts.push_back(input.size());
    input.insert(input.end(), Input(motion).begin(), Input(motion).end());
  }
  const std::vector<Signal> run = Run(model, {input, force, dt, substeps}, channels);
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

}  // namespace isolab::building
