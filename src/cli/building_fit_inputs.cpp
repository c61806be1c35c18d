#include "building_fit_inputs.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <filesystem>

#include "building_measurement.h"
#include "isolab/analysis/test_data_checks.h"
#include "isolab/core/errors.h"
#include "isolab/io/cyclic_test_file.h"

namespace isolab::cli {
namespace {

void Refuse(const char* option, const char* why) {
  throw InputError({"command line"}, fmt::format("{} {}", option, why));
}

// Force-driven tests (cyclic-test files: the force applied to level 1 and its displacement), each
// a motion, sampled at one step.
std::vector<analysis::BuildingMotion> ReadForceDriven(const BuildingData& data,
                                                      const model::ModelFile& model,
                                                      bool* one_specimen) {
  io::CyclicTestSet set = io::ReadCyclicTests(data.data,
                                              {data.force_unit.empty() ? "kN" : data.force_unit,
                                               data.length_unit.empty() ? "mm" : data.length_unit},
                                              model.units);
  analysis::RequireUnits(set, !data.force_unit.empty() && !data.length_unit.empty(),
                         "--force-unit and --length-unit");
  analysis::RequireFiniteSquares(set);
  *one_specimen = io::OneSpecimen(data.specimen, set.one_specimen);
  const double seconds = model.units.SiFactor(dimension::kTime);
  std::vector<analysis::BuildingMotion> motions;
  for (std::size_t t = 0; t < set.tests.size(); ++t) {
    identification::CyclicTestData& test = set.tests[t];
    analysis::BuildingMotion& motion = motions.emplace_back();
    motion.name = test.name;
    analysis::BuildingMeasurements& measured = motion.measured;
    for (const double time : test.time) {
      measured.time.push_back((time - test.time.front()) / seconds);
    }
    const double dt = analysis::SampleStep(measured);
    for (std::size_t k = 1; k < measured.time.size(); ++k) {
      const double step = measured.time[k] - measured.time[k - 1];
      if (std::abs(step - dt) > 0.01 * dt) {
        throw InputError({set.source[t]},
                         fmt::format("test {}: sample {} comes {:g} s after the previous one, "
                                     "against {:g} s on average: a force-driven test must be "
                                     "sampled at one step",
                                     test.name, k, step * seconds, dt * seconds));
      }
    }
    if (!data.quiet) {
      fmt::print(stderr, "{}: {}: {} samples, driven by the force on level 1\n", data.command,
                 test.name, measured.time.size());
    }
    measured.applied_force = std::move(test.force);
    measured.displacement = {std::move(test.displacement)};
    measured.acceleration = {{}};
  }
  return motions;
}

}  // namespace

BuildingFitInputs LoadBuildingFit(const std::string& spec_path, const BuildingData& data) {
  BuildingFitInputs inputs;
  inputs.file = model::LoadBuildingFitSpec(spec_path);
  const model::BuildingFitSpecFile& file = inputs.file;
  const char* const units =
      "applies to force-driven tests (input: force), not to shake-table "
      "motions (they carry their units in the column names)";
  if (!file.force_driven && !data.force_unit.empty()) Refuse("--force-unit", units);
  if (!file.force_driven && !data.length_unit.empty()) Refuse("--length-unit", units);
  if (file.force_driven && !data.offsets.empty()) {
    Refuse("--offsets", "applies to shake-table motions, not to force-driven tests (input: force)");
  }
  inputs.model = model::LoadModelFile(file.model);
  inputs.files = data.data;
  inputs.files.push_back(spec_path);
  inputs.files.push_back(file.model);
  for (const std::string& included : inputs.model.included_files) {
    inputs.files.push_back(included);
  }
  analysis::BuildingFitSpec& spec = inputs.spec;
  for (const model::BuildingFitParameterEntry& entry : file.parameters) {
    spec.parameters.push_back({entry.name, entry.low, entry.high, entry.start});
  }
  for (const std::string& channel : file.channels) {
    spec.channels.push_back(analysis::ParseChannel(channel, file.path));
  }
  // What a force-driven test measures: the displacement where the force acts.
  if (file.force_driven && spec.channels.empty()) {
    spec.channels.push_back({analysis::BuildingChannel::Kind::kDisplacement, 1});
  }
  spec.band_low = file.band_low;
  spec.band_high = file.band_high;
  spec.pause = file.pause;
  spec.substeps = file.substeps;
  spec.sequential = data.specimen == "sequential";
  return inputs;
}

std::vector<analysis::BuildingMotion> ReadBuildingMotions(BuildingFitInputs* inputs,
                                                          const BuildingData& data) {
  const model::ModelFile& model = inputs->model;
  if (inputs->file.force_driven) return ReadForceDriven(data, model, &inputs->spec.sequential);
  const std::size_t levels = analysis::LevelMasses(model).size();
  std::vector<analysis::BuildingMotion> motions;
  for (const std::string& path : data.data) {
    ShakeTableOptions read;
    read.data = path;
    read.model = inputs->file.model;
    if (!data.offsets.empty()) read.offsets = data.offsets;
    Measured measured = ReadMeasured(read, model.units, levels);
    if (!data.quiet) {
      fmt::print(stderr, "{}: {}: {} samples, levels (slab to roof) = channels {}; {}\n",
                 data.command, path, measured.time.size(), fmt::join(measured.channels, ","),
                 measured.reference_note);
    }
    motions.push_back({std::filesystem::path(path).stem().string(), std::move(measured)});
  }
  return motions;
}

}  // namespace isolab::cli
