#include "isolab/cyclic/model_replay.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "isolab/core/errors.h"
#include "isolab/io/displacement_path_file.h"
#include "isolab/model/build_structure.h"

namespace isolab::cyclic {
namespace {

std::string OptionName(std::string field, OptionStyle style) {
  if (style == OptionStyle::kPython) return field;
  std::replace(field.begin(), field.end(), '_', '-');
  return "--" + field;
}

struct Paths {
  std::vector<io::DisplacementPath> paths;
  std::vector<std::vector<std::size_t>> cycle_starts;  // an orbit's; empty for a file's path
};

Paths ReadPaths(const ReplayRequest& request, const UnitSystem& units, OptionStyle style) {
  Paths read;
  io::DisplacementPathSet set =
      io::ReadDisplacementPaths(request.paths, request.force_unit, request.length_unit, units);
  if (!set.without_units.empty() && (request.force_unit.empty() || request.length_unit.empty())) {
    throw InputError(
        {set.without_units.front()},
        fmt::format("no '# units: force ..., length ...' line: give the path's units "
                    "in the file or with {} and {}",
                    OptionName("force_unit", style), OptionName("length_unit", style)));
  }
  read.paths = std::move(set.paths);
  read.cycle_starts.resize(read.paths.size());
  return read;
}

Paths Orbits(const ReplayRequest& request, const model::ModelFile& model, OptionStyle style) {
  const std::string option = OptionName("orbit", style);
  OrbitProtocol protocol;
  if (request.orbit == "circle") {
    protocol.shape = OrbitShape::kCircle;
  } else if (request.orbit == "figure8") {
    protocol.shape = OrbitShape::kFigureEight;
  } else {
    throw InputError({option}, fmt::format("'{}' (expected circle or figure8)", request.orbit));
  }
  if (model.cyclic) {
    protocol.period = model.cyclic->period;
    protocol.cycles = model.cyclic->cycles;
    protocol.steps_per_cycle = model.cyclic->steps_per_cycle;
  }
  if (request.cycles) protocol.cycles = *request.cycles;
  if (request.steps_per_cycle) protocol.steps_per_cycle = *request.steps_per_cycle;
  std::vector<double> amplitudes = request.amplitudes;
  if (amplitudes.empty() && model.cyclic) amplitudes.push_back(model.cyclic->amplitude);
  if (amplitudes.empty()) {
    throw InputError({option}, fmt::format("an orbit needs {}", OptionName("amplitude", style)));
  }
  const std::vector<double> periods =
      request.periods.empty() ? std::vector<double>{protocol.period} : request.periods;
  Paths orbits;
  for (const double period : periods) {
    for (const double amplitude : amplitudes) {
      protocol.amplitude = amplitude;
      protocol.period = period;
      std::vector<std::size_t> starts;
      try {
        orbits.paths.push_back(OrbitPath(protocol, &starts));
      } catch (const InvalidParameter& error) {
        throw InputError({option}, error.violation().Describe());
      }
      orbits.paths.back().name += fmt::format("_A={:g}_T={:g}", amplitude, period);
      orbits.cycle_starts.push_back(std::move(starts));
    }
  }
  return orbits;
}

// A path or an amplitude no bearing reaches (1e300 mm) overflows the laws' forces: refused, never
// printed as inf and nan.
const ReplayResult& Finite(const ReplayResult& replay, const std::string& where,
                           const UnitSystem& units) {
  const bool finite =
      std::all_of(replay.force.begin(), replay.force.end(),
                  [](Vec2 f) { return std::isfinite(f.x) && std::isfinite(f.y); }) &&
      std::all_of(replay.dissipated.begin(), replay.dissipated.end(),
                  [](double e) { return std::isfinite(e); }) &&
      (!replay.comparison ||
       (std::isfinite(replay.comparison->e2) && std::isfinite(replay.comparison->nrmse)));
  if (!finite) {
    throw InputError({where},
                     fmt::format("the forces along '{}' (peak displacement {:g} {}), or their "
                                 "error against the measured ones, are not finite: no bearing "
                                 "reaches such displacements",
                                 replay.name, replay.peak_displacement, units.length()));
  }
  return replay;
}

}  // namespace

std::vector<ReplayRun> ReplayModel(const model::ModelFile& model, const ReplayRequest& request,
                                   OptionStyle style) {
  model::RefuseAxialLoads(model, "a path or an orbit");
  const Paths along = request.paths.empty() ? Orbits(request, model, style)
                                            : ReadPaths(request, model.units, style);
  // What a run that overflows is blamed on: the orbit's amplitude, or the path's file.
  const auto where = [&](const io::DisplacementPath& path) {
    return request.paths.empty() ? OptionName("amplitude", style) : path.name;
  };
  std::vector<ReplayRun> runs;
  if (const auto* isolators = model::PlanIsolators(model)) {
    if (request.uncoupled) {
      throw InputError({OptionName("uncoupled", style)},
                       fmt::format("{} is a building in plan: its isolators' laws are coupled or "
                                   "not as the model says",
                                   model.path));
    }
    for (const auto& isolator : *isolators) {
      if (!request.isolator.empty() && isolator.name != request.isolator) continue;
      for (std::size_t p = 0; p < along.paths.size(); ++p) {
        io::DisplacementPath path = along.paths[p];
        path.plan = true;  // a plan isolator moves in plan, whatever the path's columns
        runs.push_back({model.path + ": isolator " + isolator.name, model.units,
                        Finite(Replay(isolator.assembly, path, along.cycle_starts[p]), where(path),
                               model.units)});
      }
    }
    if (runs.empty()) {
      throw InputError(
          {OptionName("isolator", style)},
          fmt::format("{}: {} has no isolator of that name", request.isolator, model.path));
    }
    return runs;
  }
  if (model.isolation.size() == 0) {
    throw InputError({model.path}, "no isolation section: nothing to drive along a path");
  }
  if (!request.isolator.empty()) {
    throw InputError({OptionName("isolator", style)},
                     fmt::format("{} is not a building in plan: its isolation is one assembly, "
                                 "driven whole",
                                 model.path));
  }
  for (std::size_t p = 0; p < along.paths.size(); ++p) {
    const io::DisplacementPath& path = along.paths[p];
    if (request.uncoupled && !path.plan) {
      throw InputError({OptionName("uncoupled", style)},
                       fmt::format("{} moves along one direction: its laws run as they are; "
                                   "uncoupled pairs are for paths in plan (displacement_x and "
                                   "displacement_y) and orbits",
                                   path.name));
    }
    try {
      runs.push_back(
          {model.path, model.units,
           Finite(path.plan ? Replay(PlanFromIsolation(model.isolation, !request.uncoupled), path,
                                     along.cycle_starts[p])
                            : Replay(model.isolation, path, along.cycle_starts[p]),
                  where(path), model.units)});
    } catch (const std::invalid_argument& error) {
      throw InputError({model.path}, error.what());
    }
  }
  return runs;
}

}  // namespace isolab::cyclic
