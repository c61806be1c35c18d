// Readers of the model file's sections, one file each; LoadModelFile (model_file.cpp) calls them.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "isolab/model/building_fit_spec_file.h"
#include "isolab/model/model_file.h"
#include "isolab/model/study_file.h"
#include "yaml_reader.h"

namespace isolab::model {

// The number or quantity at `map[key]`, required, finite and > 0; a damping ratio in [0, 1).
double ReadPositive(const YamlReader& reader, const YAML::Node& map, const std::string& path,
                    std::string_view key, Dimension dimension, const UnitSystem& units);
double ReadRatio(const YamlReader& reader, const YAML::Node& node, const std::string& path);

// A list of priors at `path` (a building fit specification's `priors`, a fitted model's
// `uncertainty.priors`): each {name, value, sigma, source}, the value > 0 (required, or default
// the model's), sigma in ln p in (0, ln 10], none named twice nor among `fitted`.
std::vector<BuildingFitPriorEntry> ReadPriorEntries(const YamlReader& reader,
                                                    const YAML::Node& node, const std::string& path,
                                                    bool value_required,
                                                    std::span<const std::string> fitted);

// The required `units` section of a model (or fit specification) file.
UnitSystem ReadUnits(const YamlReader& reader, const YAML::Node& root);

// A story's name where the model gives none: story1, story2, ... (`index` from 0).
std::string DefaultStoryName(std::size_t index);

// The stories of a uniform shorthand (`stories: {count: N, ...}`): `count` copies of the one story
// read (reading depends on the index only through the default name), named story1, story2, ...
template <typename Story>
std::vector<Story> EqualStories(const Story& first, int count) {
  std::vector<Story> stories(static_cast<std::size_t>(count), first);
  for (std::size_t i = 1; i < stories.size(); ++i) stories[i].name = DefaultStoryName(i);
  return stories;
}

// A list of law components (an isolation layer, a hysteretic story).
hysteresis::ParallelAssembly ReadAssembly(const YamlReader& reader, const YAML::Node& list,
                                          const std::string& path, const UnitSystem& units);

// How many bearings of a type a one-direction layer has, and their name (a model's isolation).
struct BearingGroup {
  std::optional<int> count;
  std::string name = "bearing";
  std::vector<PropertyFactors> modification;  // its property modification factors
};

// `{components: [...]}` or `{file: other.yaml}` (relative to `directory`, in the same `units`), at
// key path `path` ("isolation", "variants[2].isolation"). The files it reads are appended to
// `included_files` when given. With `group`, the keys `count` (>= 1), `name` and `modification`
// are also read into it. The range the laws were identified on (`identified_range`, or the
// file's) goes to `range` when given.
hysteresis::ParallelAssembly ReadIsolation(
    const YamlReader& reader, const YAML::Node& isolation, const std::string& path,
    const std::filesystem::path& directory, const UnitSystem& units,
    std::vector<std::string>* included_files = nullptr, BearingGroup* group = nullptr,
    std::optional<identification::IdentifiedRange>* range = nullptr);

// A count of bearings at `map[key]`: a whole number >= 1 (0 is a located error).
int ReadBearingCount(const YamlReader& reader, const YAML::Node& node, const std::string& path);

// `modification` at key path `path`: factors of the properties of `laws`, whose YAML list is
// `components` (modification_section.cpp).
std::vector<PropertyFactors> ReadModification(const YamlReader& reader, const YAML::Node& node,
                                              const std::string& path,
                                              const hysteresis::ParallelAssembly& laws,
                                              const YAML::Node& components);

StructureSection ReadStructure(const YamlReader& reader, const YAML::Node& node,
                               const UnitSystem& units);
// The `plan` section: a building in plan (plan_section.cpp).
// Its isolator entries' property modification factors are appended to `modifications`.
StructureSection ReadPlan(const YamlReader& reader, const YAML::Node& node, const UnitSystem& units,
                          std::vector<BearingModification>* modifications);
// `{file, units, scale, dt}` at key path `path`.
GroundMotionSection ReadGroundMotion(const YamlReader& reader, const YAML::Node& node,
                                     const std::string& path, const UnitSystem& units);
// The angle of a pair's H1 from the x axis (degrees) at `node`, within a turn either way.
double ReadRecordAngle(const YamlReader& reader, const YAML::Node& node, const std::string& path);
ExcitationSection ReadExcitation(const YamlReader& reader, const YAML::Node& node,
                                 const UnitSystem& units);
// `auto` or a time >= 0 (analysis.free_vibration, a study's free_vibration).
FreeVibration ReadFreeVibration(const YamlReader& reader, const YAML::Node& node,
                                const std::string& path, const UnitSystem& units);
AnalysisSection ReadAnalysis(const YamlReader& reader, const YAML::Node& node,
                             const UnitSystem& units);

// A list of record entries at key path `key` (a study's records, a design's suite): files, globs
// sorted by name, or pairs {h1, h2, angle, name} for a building moving in two `directions`;
// relative to `directory`, names unique (study_file.h describes the entries).
std::vector<StudyRecord> ReadRecords(const YamlReader& reader, const YAML::Node& list,
                                     const std::string& key, const std::filesystem::path& directory,
                                     const UnitSystem& units, int directions,
                                     const std::string& building);

}  // namespace isolab::model
