#include "isolab/building/building_fit_inputs.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <filesystem>

#include "isolab/analysis/problem.h"
#include "isolab/building/shake_table_measurements.h"
#include "isolab/building/shake_table_prediction.h"
#include "isolab/core/errors.h"
#include "isolab/cyclic/test_data_checks.h"
#include "isolab/io/cyclic_test_file.h"

namespace isolab::building {
namespace {

void RefuseOption(const BuildingOptionNames& names, const std::string& option, const char* why) {
  throw InputError({names.where}, fmt::format("{} {}", option, why));
}

// Force-driven tests (cyclic-test files: the force applied to level 1 and its displacement), each
// a motion, sampled at one step.
std::vector<BuildingMotion> ReadForceDriven(const BuildingData& data, const model::ModelFile& model,
                                            bool* one_specimen) {
  io::CyclicTestSet set =
      cyclic::ReadCheckedTests(data.data, data.force_unit, data.length_unit, model.units,
                               data.names.force_unit + " and " + data.names.length_unit);
  *one_specimen = io::OneSpecimen(data.specimen, set.one_specimen);
  const double seconds = model.units.SiFactor(dimension::kTime);
  std::vector<BuildingMotion> motions;
  for (std::size_t t = 0; t < set.tests.size(); ++t) {
    identification::CyclicTestData& test = set.tests[t];
    BuildingMotion& motion = motions.emplace_back();
    motion.name = test.name;
    BuildingMeasurements& measured = motion.measured;
    for (const double time : test.time) {
      measured.time.push_back((time - test.time.front()) / seconds);
    }
    const double dt = SampleStep(measured);
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

// The model's value of a parameter the specification names: the name is the model's to check,
// and a name it does not have is said at the specification's line.
double ModelValueAt(const model::ModelFile& model, const std::string& name,
                    const SourceLocation& where, const std::string& at) {
  try {
    return analysis::ParameterValue(model, name);
  } catch (const InputError& error) {
    std::string reason = error.what();
    const std::string prefix = error.location().Describe() + ": ";
    if (reason.rfind(prefix, 0) == 0) reason.erase(0, prefix.size());
    throw InputError(where, fmt::format("{}.name: {}", at, reason));
  }
}

}  // namespace

BuildingFitInputs LoadBuildingFit(const std::string& spec_path, const BuildingData& data) {
  BuildingFitInputs inputs;
  inputs.file = model::LoadBuildingFitSpec(spec_path);
  const model::BuildingFitSpecFile& file = inputs.file;
  const char* const units =
      "applies to force-driven tests (input: force), not to shake-table "
      "motions (they carry their units in the column names)";
  if (!file.force_driven && !data.force_unit.empty())
    RefuseOption(data.names, data.names.force_unit, units);
  if (!file.force_driven && !data.length_unit.empty())
    RefuseOption(data.names, data.names.length_unit, units);
  if (file.force_driven && !data.offsets.empty()) {
    RefuseOption(data.names, data.names.offsets,
                 "applies to shake-table motions, not to force-driven tests (input: force)");
  }
  // The command line's parser allows only these; the Python module's keywords are checked here.
  if (!data.offsets.empty() && data.offsets != "pre-event" && data.offsets != "none") {
    throw InputError({data.names.where}, fmt::format("{} {}: expected pre-event or none",
                                                     data.names.offsets, data.offsets));
  }
  if (!file.force_driven) io::OneSpecimen(data.specimen, false);  // refuses any other word
  inputs.model = model::LoadModelFile(file.model);
  inputs.files = data.data;
  inputs.files.push_back(spec_path);
  inputs.files.push_back(file.model);
  for (const std::string& included : inputs.model.included_files) {
    inputs.files.push_back(included);
  }
  BuildingFitSpec& spec = inputs.spec;
  for (std::size_t i = 0; i < file.parameters.size(); ++i) {
    const model::BuildingFitParameterEntry& entry = file.parameters[i];
    ModelValueAt(inputs.model, entry.name, entry.where, fmt::format("parameters[{}]", i));
    spec.parameters.push_back({entry.name, entry.low, entry.high, entry.start});
  }
  for (std::size_t i = 0; i < file.priors.size(); ++i) {
    const model::BuildingFitPriorEntry& entry = file.priors[i];
    const std::string at = fmt::format("priors[{}]", i);
    const double value = ModelValueAt(inputs.model, entry.name, entry.where, at);
    if (!entry.value && !(value > 0.0)) {
      throw InputError(entry.where,
                       fmt::format("{}: the model's {} is {:g}; a prior is drawn in ln p, so "
                                   "give a value > 0",
                                   at, entry.name, value));
    }
    spec.priors.push_back({entry.name, entry.value, entry.sigma, entry.source});
  }
  const std::size_t levels = LevelMasses(inputs.model).size();
  for (std::size_t i = 0; i < file.channels.size(); ++i) {
    spec.channels.push_back(ParseChannel(file.channels[i], file.channel_where[i]));
    if (std::size_t(spec.channels.back().level) > levels) {
      throw InputError(file.channel_where[i],
                       fmt::format("channels[{}]: {}: the model ({}) has {} levels", i,
                                   file.channels[i], file.model, levels));
    }
  }
  // What a force-driven test measures: the displacement where the force acts.
  if (file.force_driven && spec.channels.empty()) {
    spec.channels.push_back({BuildingChannel::Kind::kDisplacement, 1});
  }
  spec.band_low = file.band_low;
  spec.band_high = file.band_high;
  spec.pause = file.pause;
  spec.substeps = file.substeps;
  spec.sequential = data.specimen == "sequential";
  return inputs;
}

namespace {

// What the specification asks of each motion that its data cannot give: a pause of more than a
// million samples, more steps a simulation than a run may take, a band above the sampling's
// Nyquist frequency. Each is the specification's, so it names that file.
void CheckAgainstMotions(const BuildingFitInputs& inputs,
                         const std::vector<BuildingMotion>& motions) {
  const BuildingFitSpec& spec = inputs.spec;
  const std::string& where = inputs.file.path;
  // A few isolated periods bring the building to rest; a million samples is minutes of it.
  constexpr double kMaxPauseSamples = 1e6;
  for (const BuildingMotion& motion : motions) {
    const double step = SampleStep(motion.measured);
    const double pause = spec.pause / step;
    if (spec.sequential && pause > kMaxPauseSamples) {
      throw InputError({where}, fmt::format("pause: {:g} is {:.3g} samples of {}'s step; at most "
                                            "{:g} (a few isolated periods bring the building to "
                                            "rest)",
                                            spec.pause, pause, motion.name, kMaxPauseSamples));
    }
    const double steps = double(motion.measured.time.size()) * spec.substeps;
    if (steps > double(analysis::kDefaultMaxSteps)) {
      throw InputError({where},
                       fmt::format("substeps: {} makes {:.3g} steps a simulation of {} "
                                   "({} samples); at most {} (a run's limit)",
                                   spec.substeps, steps, motion.name, motion.measured.time.size(),
                                   analysis::kDefaultMaxSteps));
    }
    const double nyquist = 0.5 / step;
    if (spec.band_low && *spec.band_low >= nyquist) {
      throw InputError({where}, fmt::format("band: [{:g}, {:g}] lies above {}'s Nyquist frequency "
                                            "({:g}, sampled every {:g}): nothing of the data is "
                                            "in it",
                                            *spec.band_low, spec.band_high.value_or(nyquist),
                                            motion.name, nyquist, step));
    }
  }
  // One specimen's motions are one run: their samples and the pauses between them, together.
  if (spec.sequential && motions.size() > 1) {
    double steps = 0.0;
    for (std::size_t m = 0; m < motions.size(); ++m) {
      steps += double(motions[m].measured.time.size());
      if (m > 0) steps += spec.pause / SampleStep(motions[m].measured);
    }
    steps *= spec.substeps;
    if (steps > double(analysis::kDefaultMaxSteps)) {
      throw InputError({where}, fmt::format("substeps: {} makes {:.3g} steps of the one run the "
                                            "motions and pauses of one specimen make; at most {} "
                                            "(a run's limit)",
                                            spec.substeps, steps, analysis::kDefaultMaxSteps));
    }
  }
}

}  // namespace

std::vector<BuildingMotion> ReadBuildingMotions(BuildingFitInputs* inputs,
                                                const BuildingData& data) {
  // A motion given twice counts its data twice, and a held-out motion would be the one fitted;
  // two files of one name would be two motions the reports cannot tell apart.
  for (std::size_t j = 0; j < data.data.size(); ++j) {
    for (std::size_t i = 0; i < j; ++i) {
      const std::filesystem::path a(data.data[i]), b(data.data[j]);
      std::error_code error;
      if (std::filesystem::equivalent(a, b, error)) {
        throw InputError({data.data[j]}, fmt::format("given twice (also as {}): each motion is "
                                                     "fitted once",
                                                     data.data[i]));
      }
      if (a.stem() == b.stem()) {
        throw InputError({data.data[j]}, fmt::format("two motions named '{}' ({} and this one): "
                                                     "the reports name each motion by its file's "
                                                     "name; rename one",
                                                     a.stem().string(), data.data[i]));
      }
    }
  }
  const model::ModelFile& model = inputs->model;
  std::vector<BuildingMotion> motions;
  if (inputs->file.force_driven) {
    motions = ReadForceDriven(data, model, &inputs->spec.sequential);
  } else {
    const std::size_t levels = LevelMasses(model).size();
    for (const std::string& path : data.data) {
      ShakeTableChannels read;
      if (!data.offsets.empty()) read.offsets = data.offsets;
      LevelMeasurements measured = ReadShakeTableMeasurements(path, read, model.units, levels);
      if (!data.quiet) {
        fmt::print(stderr, "{}: {}: {} samples, levels (slab to roof) = channels {}; {}\n",
                   data.command, path, measured.time.size(), fmt::join(measured.channels, ","),
                   measured.reference_note);
      }
      motions.push_back({std::filesystem::path(path).stem().string(), std::move(measured)});
    }
  }
  CheckAgainstMotions(*inputs, motions);
  return motions;
}

}  // namespace isolab::building
